// `soilsph examples`: the shipped scenes, materials, programmes, strain paths and verification
// cases, each with its one-line description (the first line of the file, a comment) and the
// command that runs it, with the paths of this installation (apps/soilsph/data_dir.h).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/data_dir.h"

namespace soilsph::cli {

namespace {
namespace fs = std::filesystem;

/// One kind of shipped file: where it lies, how it is named, what runs it.
struct ExampleKind {
  const char* title;
  const char* folder;     ///< below data_dir()
  const char* extension;  ///< of the files listed
  /// The command for the file at `path` ("soilsph collapse PATH"); `first_material` is the first
  /// shipped material, for the kinds that need one.
  std::string (*command)(const std::string& path, const std::string& first_material);
};

const ExampleKind kKinds[] = {
    {"Scenes (SPH runs; soilsph check SCENE shows the size and cost first)", "data/scenes", ".toml",
     [](const std::string& path, const std::string&) { return "soilsph collapse " + path; }},
    {"Materials (a drained triaxial test; soilsph material FILE prints the model's constants)",
     "data/materials", ".toml",
     [](const std::string& path, const std::string&) {
       return "soilsph point " + path + " --test triaxial-drained";
     }},
    {"Programmes (laboratory tests of several legs)", "data/programmes", ".toml",
     [](const std::string& path, const std::string&) { return "soilsph point " + path; }},
    {"Strain paths (strain increments applied to any material)", "data/strain-paths", ".csv",
     [](const std::string& path, const std::string& material) {
       return "soilsph point " + material + " --test strain-path:" + path;
     }},
    {"Verification cases (every case against CVODE and the closed forms; soilsph verify runs them all)",
     "verification/cases", ".toml",
     [](const std::string& path, const std::string&) { return "soilsph verify --cases " + path; }},
};

/// The files of a shipped folder with the extension, by name.
std::vector<fs::path> files_in(const char* folder, const char* extension) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(data_dir() / folder, error))
    if (entry.is_regular_file() && entry.path().extension() == extension) files.push_back(entry.path());
  std::ranges::sort(files);
  return files;
}

/// The file's description: the first sentence of the comment it begins with, however many lines it
/// takes (a line that breaks mid-sentence is not cut off there). Every shipped file begins with one.
std::string description(const fs::path& file) {
  std::ifstream in(file);
  std::string text, line;
  while (!text.ends_with('.') && !text.ends_with('?') && !text.ends_with('!') && std::getline(in, line) &&
         line.starts_with('#')) {
    const std::size_t from = line.find_first_not_of("# ");
    if (from == std::string::npos) break;  // an empty comment line ends the paragraph
    text.append(text.empty() ? "" : " ").append(line, from);
  }
  return text.empty() ? "(no description)" : text;
}

void list_examples() {
  const std::vector<fs::path> materials = files_in("data/materials", ".toml");
  const std::string first_material =
      materials.empty() ? "MATERIAL.toml" : shell_quoted(materials.front().string());
  std::cout << "Shipped examples, in " << data_dir().string() << "\n";
  for (const ExampleKind& kind : kKinds) {
    std::cout << '\n' << kind.title << ":\n";
    for (const fs::path& file : files_in(kind.folder, kind.extension))
      std::cout << "  " << file.stem().string() << ": " << description(file) << "\n      "
                << kind.command(shell_quoted(file.string()), first_material) << '\n';
  }
}
}  // namespace

void add_examples_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "examples",
      "List the shipped scenes, materials, programmes, strain paths and verification cases, each with "
      "what it is and the command that runs it");
  cmd->callback(list_examples);
}

}  // namespace soilsph::cli

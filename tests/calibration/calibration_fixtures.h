#pragma once
// Synthetic laboratory data for the calibration tests: the point driver runs programmes with known
// ("true") parameters, and the readings it writes are what a calibration must give back.
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/common/temp_dir.h"
#include "verification/calibration/point_columns.h"
#include "verification/programme/programme_file.h"

namespace soilsph::calibration::testing {

namespace fs = std::filesystem;

/// A folder of its own under the system's temporary directory (mkdtemp), removed at the end.
struct TempDir : soilsph::testing::TempDir {
  TempDir() : soilsph::testing::TempDir("soilsph-calibration") {}
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(*this / name) << text;
    return (*this / name).string();
  }
};

/// What a laboratory measures on one test: the programme, the driven column, the columns read.
struct SyntheticTest {
  std::string name;
  std::string programme;  ///< the programme file's text without its material
  std::string against;
  std::vector<std::string> match;
};

/// The driver's run of `test` with `material` (a [material] table's text), every `stride`th
/// increment from the first, as a CSV of `against` and `match`; with `noise` > 0, each matched
/// value gets Gaussian noise of standard deviation `noise` × its column's range.
inline std::string measured_csv(const TempDir& dir, const std::string& material, const SyntheticTest& test,
                                int stride, double noise = 0.0, unsigned seed = 0) {
  const std::string path =
      dir.file(test.name + "-truth.toml", "[material]\n" + material + "\n" + test.programme);
  const verification::ProgrammeFile file = verification::read_programme_file(path);
  const verification::PointCurve curve = std::visit(
      [&](const auto& model) {
        std::string name = "implicit";
        if constexpr (requires { model.integrator(); })
          name = std::string(integrator_name(model.integrator()));
        return verification::run_programme(file.material, file.programme, name);
      },
      file.material);
  std::vector<double> range(test.match.size());
  for (std::size_t c = 0; c < test.match.size(); ++c) {
    const auto field = point_column(test.match[c])->field;
    double low = curve.front().*field, high = low;
    for (const auto& r : curve) low = std::min(low, r.*field), high = std::max(high, r.*field);
    range[c] = high - low;
  }
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::ostringstream out;
  out.precision(17);
  out << "# synthetic readings of " << test.name << "\n" << test.against;
  for (const std::string& name : test.match) out << ',' << name;
  out << '\n';
  for (std::size_t k = static_cast<std::size_t>(stride); k < curve.size();
       k += static_cast<std::size_t>(stride)) {
    out << curve[k].*(point_column(test.against)->field);
    for (std::size_t c = 0; c < test.match.size(); ++c)
      out << ',' << curve[k].*(point_column(test.match[c])->field) + noise * range[c] * normal(random);
    out << '\n';
  }
  return dir.file(test.name + ".csv", out.str());
}

/// A calibration file: `material` (a [material] table's text, the start), `fit` ([fit] keys), and
/// one experiment per test with its programme and measured CSV written into `dir`.
inline std::string calibration_file(const TempDir& dir, const std::string& material, const std::string& fit,
                                    const std::vector<SyntheticTest>& tests,
                                    const std::vector<std::string>& csvs) {
  std::string text = "[material]\n" + material + "\n[fit]\n" + fit + "\n";
  for (std::size_t k = 0; k < tests.size(); ++k) {
    dir.file(tests[k].name + ".toml", tests[k].programme);
    text += "[[experiment]]\nname = \"" + tests[k].name + "\"\nprogramme = \"" + tests[k].name +
            ".toml\"\ndata = \"" + fs::path(csvs[k]).filename().string() + "\"\nagainst = \"" +
            tests[k].against + "\"\nmatch = [";
    for (std::size_t c = 0; c < tests[k].match.size(); ++c)
      text += (c ? ", \"" : "\"") + tests[k].match[c] + "\"";
    text += "]\n";
  }
  return dir.file("calibration.toml", text);
}

/// Modified Cam-Clay's CU tests at OCR 1, 2 and 4 (q and u against eps_a) and an isotropic
/// compression from OCR 2 (eps_v against p), which separates λ from κ.
inline std::vector<SyntheticTest> cam_clay_tests(int increments) {
  const std::string n = std::to_string(increments);
  std::vector<SyntheticTest> tests;
  for (const int ocr : {1, 2, 4})
    tests.push_back({"cu-ocr" + std::to_string(ocr),
                     "[initial]\np = " + std::to_string(200000 / ocr) + "\nocr = " + std::to_string(ocr) +
                         "\n[[leg]]\ndrainage = \"undrained\"\nincrements = " + n +
                         "\nstrain = { xx = 0.1 }\nstress = { yy = \"hold\", zz = \"hold\" }\n",
                     "eps_a",
                     {"q", "u"}});
  tests.push_back({"isotropic",
                   "[initial]\np = 100000\nocr = 2\n[[leg]]\nincrements = " + n +
                       "\nstress = { xx = 400000, yy = 400000, zz = 400000 }\n",
                   "p",
                   {"eps_v"}});
  return tests;
}

/// Drained triaxial compression at three cell pressures (q and eps_v against eps_a): the failure
/// line's slope and intercept (φ, c), the dilatancy (ψ) and the stiffness (E).
inline std::vector<SyntheticTest> drained_tests(int increments) {
  std::vector<SyntheticTest> tests;
  for (const int cell : {50, 100, 200})
    tests.push_back({"cd-" + std::to_string(cell),
                     "[initial]\np = " + std::to_string(cell * 1000) +
                         "\n[[leg]]\nincrements = " + std::to_string(increments) +
                         "\nstrain = { xx = 0.05 }\nstress = { yy = \"hold\", zz = \"hold\" }\n",
                     "eps_a",
                     {"q", "eps_v"}});
  return tests;
}

}  // namespace soilsph::calibration::testing

#include "verification/report/report_writer.h"

#include "verification/closed_form/cam_clay_compression.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/material_description.h"

#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace soilsph::verification {

namespace {
namespace fs = std::filesystem;

std::ofstream open(const fs::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  return out;
}

std::string scientific(double x) {
  std::ostringstream s;
  s << std::scientific << std::setprecision(1) << x;
  return s.str();
}

std::string errors_cells(const std::optional<CurveErrors>& e) {
  if (!e) return "– | – | –";
  return scientific(e->q) + " | " + scientific(e->p) + " | " + scientific(e->eps_v);
}

void write_closed_form_csv(const fs::path& path, const std::vector<ReferencePoint>& points,
                           std::span<const std::string> comments) {
  std::ofstream out = open(path);
  out << "# soilsph verify: closed-form reference; compression-positive, SI (strains -, stresses Pa)\n";
  for (const std::string& line : comments) out << "# " << line << '\n';
  out << "eps_a,eps_v,p,q,p_c\n"
      << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (const ReferencePoint& r : points)
    out << r.eps_a << ',' << r.eps_v << ',' << r.p << ',' << r.q << ',' << r.p_c << '\n';
}

/// Model constants the plots need: the failure (critical-state) line of any plastic model, and
/// MCC's yield ellipse and void ratio.
std::string model_json(const Material& material) {
  std::ostringstream s;
  s << std::setprecision(std::numeric_limits<double>::max_digits10);
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        s << "\"model\": \"" << T::kName << "\"";
        if constexpr (std::is_same_v<T, ModifiedCamClay>)
          s << ", \"M\": " << m.M() << ", \"e0\": " << m.params().initial_void_ratio
            << ", \"lambda\": " << m.params().compression_index
            << ", \"kappa\": " << m.params().swelling_index;
        if constexpr (std::is_same_v<T, ModifiedCamClay>)
          if (m.elasticity().kind() == Elasticity::Kind::PressureDependent)
            s << ", \"eta_k0\": " << cam_clay_k0_stress_ratio(m);  // the K0 line of the oedometer plots
      },
      material);
  if (const auto line = triaxial_failure_line(material))
    s << ", \"failure_slope\": " << line->slope << ", \"failure_intercept\": " << line->intercept;
  return s.str();
}

void write_manifest(const fs::path& path, const std::vector<CaseResult>& results) {
  std::ofstream out = open(path);
  out << std::setprecision(std::numeric_limits<double>::max_digits10) << "[\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const VerificationCase& c = *results[i].spec;
    out << "  {\"name\": \"" << c.name << "\", \"path\": \"" << load_path_name(c.test.path)
        << "\", \"p_initial\": " << c.test.p_initial << ", \"ocr\": " << c.test.ocr
        << ", \"closed_form\": " << (results[i].closed_form.empty() ? "false" : "true") << ", "
        << model_json(c.material) << ", \"reference\": " << (results[i].reference.empty() ? "false" : "true")
        << ", \"integrators\": [";
    bool first = true;
    for (const IntegratorRun& run : results[i].runs) {
      if (run.integrator == kReferenceIntegrator || run.curve.empty()) continue;
      out << (first ? "" : ", ") << '"' << run.integrator << '"';
      first = false;
    }
    out << "]}" << (i + 1 < results.size() ? "," : "") << '\n';
  }
  out << "]\n";
}

void write_markdown(const fs::path& path, const std::vector<CaseResult>& results) {
  std::ofstream out = open(path);
  std::size_t runs = 0, failed = 0, uncompared = 0;
  for (const CaseResult& r : results)
    for (const IntegratorRun& run : r.runs) {
      if (run.passed && !run.compared) {
        ++uncompared;
        continue;
      }
      ++runs, failed += run.passed ? 0 : 1;
    }
  out << "# soilsph verification report\n\n"
      << (failed == 0 ? "**All " + std::to_string(runs) + " runs pass.**"
                      : "**" + std::to_string(failed) + " of " + std::to_string(runs) + " runs FAIL.**")
      << (uncompared ? " " + std::to_string(uncompared) +
                           " CVODE run(s) without a closed form are the reference of their case, not checked."
                     : std::string())
      << "\n\nMaximum relative errors of each integrator's curve against the closed form and against the "
         "CVODE "
         "reference, sampled at the same driven strains. Stress errors (q, p') are divided by the largest "
         "|p'| or "
         "|q| of the reference curve, volumetric-strain errors by its largest |ε_a| or |ε_v|. All quantities "
         "are "
         "compression-positive, SI. A run passes when every error is within its tolerance (from the case "
         "file).\n\n"
      << "| case | model | path | OCR | integrator | closed form: q | p' | ε_v | CVODE: q | p' | ε_v | "
         "tolerance | "
         "result |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CaseResult& r : results) {
    const VerificationCase& c = *r.spec;
    for (const IntegratorRun& run : r.runs) {
      std::string verdict = !run.passed ? "**FAIL**" : run.compared ? "pass" : "no closed form";
      if (!run.failure.empty()) verdict += " (" + run.failure + ")";
      out << "| " << c.name << " | " << model_name(c.material) << " | " << load_path_name(c.test.path)
          << " | " << c.test.ocr << " | " << run.integrator << " | " << errors_cells(run.vs_closed_form)
          << " | "
          << (run.integrator == kReferenceIntegrator ? "reference | – | –" : errors_cells(run.vs_reference))
          << " | " << scientific(run.tolerance) << " | " << verdict << " |\n";
    }
  }
  out << "\nCurves: `csv/CASE.INTEGRATOR.csv` (and `csv/CASE.closed-form.csv`); plots: `plots/CASE.png`.\n";
}
}  // namespace

void write_report(const fs::path& folder, const std::vector<CaseResult>& results,
                  std::span<const std::string> provenance) {
  fs::create_directories(folder / "csv");
  for (const CaseResult& r : results) {
    std::vector<std::string> case_lines(provenance.begin(), provenance.end());
    case_lines.push_back("case: " + r.spec->name + " of " + r.spec->source);
    const auto write_curve = [&](std::string_view integrator, const PointCurve& curve) {
      const bool reference = integrator == kReferenceIntegrator;
      const Material used = reference || integrator == kUmatRun
                                ? r.spec->material
                                : with_integrator(r.spec->material, parse_integrator(integrator));
      std::vector<std::string> comments = case_lines;
      comments.push_back("material: " + r.spec->material_file + ": " + describe_material(used));
      comments.push_back("integrator: " + std::string(integrator) +
                         (reference ? " (the CVODE reference; the material's integrator key is not used)" : ""));
      comments.push_back("test: " + describe_test(r.spec->test));
      std::ofstream out = open(folder / "csv" / (r.spec->name + "." + std::string(integrator) + ".csv"));
      write_point_csv(out, curve, comments);
    };
    for (const IntegratorRun& run : r.runs)
      if (!run.curve.empty()) write_curve(run.integrator, run.curve);
    if (!r.reference.empty() &&
        r.runs.end() == std::find_if(r.runs.begin(), r.runs.end(), [](const IntegratorRun& x) {
          return x.integrator == kReferenceIntegrator;
        }))
      write_curve(kReferenceIntegrator, r.reference);
    if (!r.closed_form.empty())
      write_closed_form_csv(folder / "csv" / (r.spec->name + ".closed-form.csv"), r.closed_form, case_lines);
  }
  write_manifest(folder / "cases.json", results);
  write_markdown(folder / "report.md", results);
}

}  // namespace soilsph::verification

#include "verification/work_precision.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <limits>
#include <optional>
#include <stdexcept>
#include <sstream>

namespace soilsph::verification {

namespace {
double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// max_k |a_k − b_k| / max_k |b_k| for one column of two curves with the same rows.
template <class Field>
double path_error(const PointCurve& curve, const PointCurve& reference, Field field) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < reference.size() && k < curve.size(); ++k) {
    diff = std::max(diff, std::abs(field(curve[k]) - field(reference[k])));
    scale = std::max(scale, std::abs(field(reference[k])));
  }
  if (curve.size() != reference.size()) return std::numeric_limits<double>::infinity();
  return scale > 0.0 ? diff / scale : diff;
}

/// A copy of `material` with another `substep_tolerance`.
Material with_substep_tolerance(const Material& material, double tolerance) {
  return with_edited_params(material, [tolerance](auto& params) {
    if constexpr (requires { params.substep_tolerance; }) params.substep_tolerance = tolerance;
  });
}

/// A copy of an MCC `material` with another `implicit_tolerance`.
Material with_implicit_tolerance(const Material& material, double tolerance) {
  return with_edited_params(material, [tolerance](auto& params) {
    if constexpr (requires { params.implicit_tolerance; }) params.implicit_tolerance = tolerance;
  });
}

/// The rows of `curve` (`fine` increments per leg) at the ends of the increments of `coarse` per leg
/// (coarse divides fine).
PointCurve at_rows_of(const PointCurve& curve, int fine, int coarse) {
  PointCurve rows{curve.front()};
  const std::size_t legs = (curve.size() - 1) / static_cast<std::size_t>(fine);
  const int stride = fine / coarse;
  for (std::size_t l = 0; l < legs; ++l)
    for (int i = 1; i <= coarse; ++i) rows.push_back(curve[l * fine + i * stride]);
  return rows;
}

double largest_q_difference(const PointCurve& a, const PointCurve& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k].q - b[k].q));
  return d;
}

struct Variant {
  std::string integrator;
  Material material;
  std::string label;
  double path_tolerance = 0.0;
};

std::vector<Variant> variants(const Material& material, const WorkPrecisionOptions& options, bool mixed) {
  std::vector<Variant> out;
  for (const std::string& integrator : options.integrators) {
    const bool error_controlled = std::visit(
        [](const auto& model) { return requires { model.params().implicit_tolerance; }; }, material);
    if (integrator == "implicit" && error_controlled) {
      out.push_back({integrator, material, integrator});
      for (double tolerance : options.implicit_tolerances) {
        std::ostringstream label;
        label << "implicit(" << tolerance << ')';
        out.push_back({integrator, with_implicit_tolerance(material, tolerance), label.str()});
      }
      continue;
    }
    if (integrator != "substep") {
      out.push_back({integrator, material, integrator});
      continue;
    }
    for (double tolerance : options.substep_tolerances) {
      std::ostringstream label;
      label << "substep(" << tolerance << ')';
      out.push_back({integrator, with_substep_tolerance(material, tolerance), label.str()});
    }
  }
  if (!mixed) return out;
  // The driver's sub-steps act on the path, so they are paired with the schemes that can follow it
  // accurately (explicit's own first-order error would dominate).
  const std::size_t plain = out.size();
  for (double path_tolerance : options.path_tolerances)
    for (std::size_t k = 0; k < plain; ++k) {
      if (out[k].integrator == "explicit") continue;
      std::ostringstream label;
      label << out[k].label << "+path(" << path_tolerance << ')';
      Variant v = out[k];
      v.label = label.str();
      v.path_tolerance = path_tolerance;
      out.push_back(std::move(v));
    }
  return out;
}
}  // namespace

SelfReference self_reference(const Material& material, PointTest test, int increments) {
  const int finest = 4 * increments;
  std::vector<PointCurve> runs;  // F/4, F/2, F, each at the rows of `increments`
  for (const int n : {finest / 4, finest / 2, finest}) {
    test.increments = n;
    runs.push_back(at_rows_of(run_point_test(material, test, "implicit"), n, increments));
  }
  const double coarse = largest_q_difference(runs[0], runs[1]), fine = largest_q_difference(runs[1], runs[2]);
  SelfReference reference{runs[2], finest, std::numeric_limits<double>::quiet_NaN()};
  double q_scale = 0.0;
  for (const PointRecord& r : runs[2]) q_scale = std::max(q_scale, std::abs(r.q));
  // Differences at round-off (an update exact on the path) have no order: u_F is the reference.
  if (coarse > 1e-12 * q_scale && fine > 1e-12 * q_scale) {
    reference.observed_order = std::log2(coarse / fine);
    const double factor = 1.0 / (std::pow(2.0, reference.observed_order) - 1.0);
    for (std::size_t k = 0; k < reference.curve.size(); ++k) {
      reference.curve[k].q += (runs[2][k].q - runs[1][k].q) * factor;
      reference.curve[k].p += (runs[2][k].p - runs[1][k].p) * factor;
    }
  }
  return reference;
}

std::vector<WorkPrecisionRow> work_precision(const std::string& material_name, const Material& material,
                                             PointTest test, const WorkPrecisionOptions& options,
                                             const std::function<void(const WorkPrecisionRow&)>& on_row,
                                             std::vector<std::string>* notes) {
  std::vector<WorkPrecisionRow> rows;
  const bool self_referenced = !has_rate_form(material);
  std::optional<SelfReference> umat_reference;
  int reference_increments = 0;
  if (self_referenced) {
    // Every count divides the largest one for the default counts; the reference is sampled at its rows.
    reference_increments = *std::max_element(options.increments.begin(), options.increments.end());
    for (const int n : options.increments)
      if (reference_increments % n != 0)
        throw std::invalid_argument("bench point of a " + std::string(model_name(material)) +
                                    " material: every increment count must divide the largest (" +
                                    std::to_string(reference_increments) + "), " + std::to_string(n) + " does not");
    umat_reference = self_reference(material, test, reference_increments);
    if (notes) {
      std::ostringstream note;
      note << material_name << ", " << load_path_name(test.path) << ": reference = Richardson extrapolation of its "
           << "own runs at " << umat_reference->finest / 4 << ", " << umat_reference->finest / 2 << " and "
           << umat_reference->finest << " increments per leg, observed order "
           << (std::isnan(umat_reference->observed_order) ? std::string("none (their differences are at round-off)")
                                                          : std::to_string(umat_reference->observed_order));
      notes->push_back(note.str());
    }
  }
  for (int n : options.increments) {
    test.increments = n;
    const PointCurve reference = self_referenced ? at_rows_of(umat_reference->curve, reference_increments, n)
                                                 : run_point_test(material, test, kReferenceIntegrator);
    const bool mixed = test.path == LoadPath::TriaxialDrained || test.path == LoadPath::TriaxialUndrained;
    const std::vector<Variant> runs =
        self_referenced ? std::vector<Variant>{{"implicit", material, "umat"}} : variants(material, options, mixed);
    for (const auto& [integrator, run_material, label, path_tolerance] : runs) {
      test.path_tolerance = path_tolerance;
      WorkPrecisionRow row{material_name, std::string(load_path_name(test.path)), label, n, 0, 0, 0, 0};
      std::vector<double> times;
      PointCurve curve;
      double total = 0.0;
      try {
        while (times.size() < 3 || (total < options.min_seconds && times.size() < 200)) {
          const double t0 = cpu_now();
          curve = run_point_test(run_material, test, integrator);
          times.push_back(cpu_now() - t0);
          total += times.back();
        }
        row.error_q = path_error(curve, reference, [](const PointRecord& r) { return r.q; });
        row.error_p = path_error(curve, reference, [](const PointRecord& r) { return r.p; });
      } catch (const std::exception&) {  // the driver could not solve a step: no point for this count
        row.error_q = row.error_p = std::numeric_limits<double>::infinity();
        if (times.empty()) times.push_back(std::numeric_limits<double>::quiet_NaN());
      }
      std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
      row.cpu_seconds = times[times.size() / 2];
      row.repeats = static_cast<int>(times.size());
      rows.push_back(row);
      if (on_row) on_row(row);
    }
    test.path_tolerance = 0.0;
  }
  return rows;
}

void write_work_precision_csv(std::ostream& out, const std::vector<WorkPrecisionRow>& rows) {
  out << "# work-precision of the stress integrators against the CVODE reference; p and q "
         "compression-positive; "
         "error_q = max_k |q_k - q_ref,k| / max_k |q_ref,k| over the path (same for p); cpu_seconds = median "
         "CPU "
         "time of one path (s)\n";
  out << "material,path,integrator,increments,error_q,error_p,cpu_seconds,repeats\n";
  out << std::setprecision(6);
  for (const auto& r : rows)
    out << r.material << ',' << r.path << ',' << r.integrator << ',' << r.increments << ',' << r.error_q
        << ',' << r.error_p << ',' << r.cpu_seconds << ',' << r.repeats << '\n';
}

}  // namespace soilsph::verification

#pragma once
/// @file
/// The verification report's files in one output folder:
///   report.md                       the error table (pass/fail against each case's tolerances);
///   csv/CASE.INTEGRATOR.csv         every curve (write_point_csv), compression-positive, SI;
///   csv/CASE.closed-form.csv        the closed form at the reference's strains;
///   cases.json                      what scripts/plot_verification.py needs to draw each case.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "verification/report/case_result.h"

namespace soilsph::verification {

/// `provenance` (the version and the command line) heads every CSV as '#' lines, followed by the
/// case's own: its file, material (every parameter, defaults resolved), integrator and test.
void write_report(const std::filesystem::path& folder, const std::vector<CaseResult>& results,
                  std::span<const std::string> provenance = {});

}  // namespace soilsph::verification

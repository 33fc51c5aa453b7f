#!/usr/bin/env bash
# Quick-start command 1: install what is missing, build, and run the main job on the shipped
# default input, writing results and pictures into the folder given (default: results/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out="${1:-results}"
bash scripts/setup.sh
mkdir -p "$out"
for material in data/materials/dp-table1.toml data/materials/mcc-table1.toml; do
  build/apps/soilsph/soilsph material "$material"
done
# Main job (until the SPH solver lands): the material-point verification report, every case of
# verification/cases/ against the CVODE reference and the closed forms, with CSVs and plots.
build/apps/soilsph/soilsph verify --out "$out/verification"
echo "results written to $out/ (verification report: $out/verification/report.md)"

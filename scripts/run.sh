#!/usr/bin/env bash
# Quick-start command 1: install what is missing, build, and run the main job: the collapse of the
# paper's soil column with both shipped scenes (D-P and MCC), its pictures (Fig. 4 and 5) and the
# D-P/MCC profile overlay, then the material-point verification report. Results go into the
# folder given (default: results/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out="${1:-results}"
bash scripts/setup.sh
mkdir -p "$out"
# Threads: SOILSPH_THREADS (default auto: every core, one while the machine is too busy for more to
# help; sph/thread_tuner.h).
threads="${SOILSPH_THREADS:-auto}"
for model in dp mcc; do
  build/apps/soilsph/soilsph collapse "data/scenes/collapse-$model.toml" --out "$out/collapse-$model" --threads "$threads"
done
/usr/bin/python3 scripts/plot_collapse.py "$out/collapse-dp" --compare "$out/collapse-mcc"
/usr/bin/python3 scripts/plot_collapse.py "$out/collapse-mcc"
# Every verification case against the CVODE reference and the closed forms, with CSVs and plots.
build/apps/soilsph/soilsph verify --out "$out/verification"
echo "results written to $out/: collapse-dp/, collapse-mcc/ (frames.xdmf, summary.json, PNGs), verification/report.md"

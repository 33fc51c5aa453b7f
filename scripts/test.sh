#!/usr/bin/env bash
# Quick-start command 2: install what is missing, build, and run every test (ctest).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"

#!/usr/bin/env bash
# Installs the Debian 12 packages soilsph needs (only those missing) and builds it in Release
# into build/. Sourced by scripts/run.sh and scripts/test.sh; safe to run again.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(
  build-essential cmake pkg-config gfortran      # toolchain (gfortran: the UMAT plug-ins)
  libeigen3-dev libsundials-dev libgsl-dev       # tensors, CVODE reference, roots and quadrature
  libhdf5-dev libtomlplusplus-dev libcli11-dev   # SPH frames, input files, command line
  catch2 libbenchmark-dev                        # tests and micro-benchmarks
  python3-matplotlib python3-h5py python3-numpy  # pictures (run with Debian's /usr/bin/python3)
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSOILSPH_REQUIRE_FORTRAN=ON >/dev/null
cmake --build build -j"$(nproc)"

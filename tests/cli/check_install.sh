#!/bin/sh
# `cmake --install` into a temporary prefix, then soilsph run from there as a user would: from another
# folder, with the build tree out of reach (no marker beside the installed executable), it finds its
# shipped files under PREFIX/share/soilsph: `verify` with its plots, a short collapse of an installed
# scene and its pictures, `examples` naming installed paths; SOILSPH_DATA_DIR overrides, and a wrong
# one is refused naming the variable (exit 2).
# Usage: check_install.sh CMAKE BUILD_DIR
set -eu
cmake=$1 build=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
"$cmake" --install "$build" --prefix "$prefix" > "$prefix/install.log"
share="$prefix/share/soilsph"
test -x "$prefix/bin/soilsph"
test ! -e "$prefix/bin/soilsph-source-dir.txt"
mkdir "$prefix/work"
cd "$prefix/work"
unset SOILSPH_DATA_DIR
"$prefix/bin/soilsph" --help > help.txt
grep -q "^Usage: soilsph " help.txt
"$prefix/bin/soilsph" verify --out verification > verify.log
test -s verification/report.md
ls verification/plots/*.png > /dev/null
"$prefix/bin/soilsph" collapse "$share/data/scenes/collapse-dp.toml" --threads 1 \
  --set scene.particle_spacing=0.004 --set scene.end_time=0.05 --set output.frame_interval=0.025 > collapse.log
grep -q "output in results/collapse-dp/" collapse.log
/usr/bin/python3 "$share/scripts/plot_collapse.py" results/collapse-dp > plot.log
test -s results/collapse-dp/deposit.png
"$prefix/bin/soilsph" examples > examples.txt
grep -q "soilsph collapse $share/data/scenes/collapse-dp.toml" examples.txt
SOILSPH_DATA_DIR="$share" "$prefix/bin/soilsph" examples > examples.txt
grep -q "in $share\$" examples.txt
set +e
SOILSPH_DATA_DIR="$prefix/nowhere" "$prefix/bin/soilsph" examples 2> wrong.log
status=$?
set -e
test $status -eq 2
grep -q "^error: SOILSPH_DATA_DIR=$prefix/nowhere: no data/ folder" wrong.log
echo "installed soilsph ran verify, collapse, plot and examples from $prefix"

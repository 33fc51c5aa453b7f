#!/usr/bin/python3
"""Write the worked example's synthetic "measured" curves, data/calibration/measured/*.csv.

    make_measured.py [--soilsph PATH]

Each programme of the example is run by `soilsph point` with the TRUE parameters below (in place
of clay-start.toml's first guesses), one increment in STRIDE is kept as a reading, and each matched
column gets Gaussian noise of standard deviation NOISE x its range (seed SEED), as a laboratory's
scatter. The files are written as a laboratory reports them: stresses in kPa, strains in percent
(clay.toml says so with stress_unit and strain_unit). Calibrating clay.toml should give back the
true values within its reported intervals.
"""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
TRUE = {"compression_index": 0.2, "swelling_index": 0.04, "friction_angle": 28.0}
NOISE = 0.01
SEED = 20261205
STRIDE = 2
EXPERIMENTS = [  # programme, driven column, matched columns
    ("cu-ocr1", "eps_a", ["q", "u"]),
    ("cu-ocr2", "eps_a", ["q", "u"]),
    ("cu-ocr4", "eps_a", ["q", "u"]),
    ("isotropic-ocr2", "p", ["eps_v"]),
]
STRESSES = {"sig_a", "sig_r", "p", "q", "p_c", "u", "tau_xy"}


def run_point(soilsph, programme, out):
    settings = [arg for key, value in TRUE.items() for arg in ("--set", f"material.{key}={value}")]
    subprocess.run([soilsph, "point", str(programme), *settings, "--out", str(out)], check=True)
    lines = [line for line in out.read_text().splitlines() if not line.startswith("#")]
    names = lines[0].split(",")
    values = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    return {name: values[:, k] for k, name in enumerate(names)}


def in_lab_units(column, values):
    return values * 1e-3 if column in STRESSES else values * 100.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--soilsph", default=str(HERE.parent.parent / "build" / "apps" / "soilsph" / "soilsph"))
    args = parser.parse_args()
    rng = np.random.default_rng(SEED)
    (HERE / "measured").mkdir(exist_ok=True)
    truth = ", ".join(f"{key} = {value}" for key, value in TRUE.items())
    with tempfile.TemporaryDirectory() as tmp:
        for name, against, match in EXPERIMENTS:
            curve = run_point(args.soilsph, HERE / f"{name}.toml", Path(tmp) / f"{name}.csv")
            rows = slice(STRIDE, None, STRIDE)
            columns = {against: in_lab_units(against, curve[against][rows])}
            for column in match:
                exact = curve[column][rows]
                spread = NOISE * (curve[column].max() - curve[column].min())
                columns[column] = in_lab_units(column, exact + spread * rng.standard_normal(exact.size))
            header = (f"# Synthetic readings of {name}.toml (data/calibration/make_measured.py): soilsph point with "
                      f"{truth} in place of clay-start.toml's values; one reading every {STRIDE} increments; Gaussian noise of "
                      f"{NOISE:g} x each column's range (seed {SEED}). Compression-positive; stresses kPa; strains percent\n")
            text = header + ",".join(columns) + "\n"
            for k in range(columns[against].size):
                text += ",".join(f"{columns[c][k]:.6g}" for c in columns) + "\n"
            (HERE / "measured" / f"{name}.csv").write_text(text)
            print(f"wrote measured/{name}.csv ({columns[against].size} readings)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Check the calibration of Modified Cam-Clay on the measured CU test C001 (data/calibration/lab-c001).

    check_lab_fit.py PROGRAMME.toml OUT_DIR

The soil softens after its peak, which Modified Cam-Clay cannot follow, so the fit is not expected
to pass through the readings; what must hold, independently of soilsph's numbers:

1. the fit lowers the misfit of every matched column below the starting parameters';
2. the fitted curve ends at the model's critical state, which for an undrained test from a normally
   consolidated K0 state has a closed form in the fitted parameters (constant volume: elastic and
   plastic volume changes cancel, kappa ln(p'/p'0) + (lambda - kappa) ln(p_c/p_c0) = 0, and at
   critical state q = M p', p_c = 2 p'):

       p'_f = p'_0 (p_c0 / (2 p'_0))^((lambda - kappa)/lambda),  p_c0 = p'_0 + q_0^2/(M^2 p'_0),
       q_f = M p'_f,  u_f = p'_0 + (q_f - q_0)/3 - p'_f  (cell pressure held),

   with M = 6 sin(phi)/(3 - sin(phi)) (eq 26). The last fitted q and u must match them to 0.1 % of
   the measured range: fit.json's values are the ones that drew the fitted curves.

Exit status 1 with one line per failure otherwise.
"""
import csv
import json
import math
import sys
import tomllib
from pathlib import Path


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def main(programme_path, out):
    out = Path(out)
    fit = json.loads((out / "fit.json").read_text())
    value = {p["key"]: p["value"] for p in fit["parameters"]}
    initial = tomllib.loads(Path(programme_path).read_text())["initial"]
    rows = list(csv.DictReader(line for line in (out / "curves-cu-c001.csv").read_text().splitlines()
                               if not line.startswith("#")))
    failures = []
    for column in ("q", "u"):
        measured = [float(r[f"{column}_measured"]) for r in rows]
        fitted = [float(r[f"{column}_fitted"]) - m for r, m in zip(rows, measured)]
        start = [float(r[f"{column}_start"]) - m for r, m in zip(rows, measured)]
        if not rms(fitted) < rms(start):
            failures.append(f"{column}: the fit's rms {rms(fitted):g} is not below the start's {rms(start):g}")

    sin_phi = math.sin(math.radians(value["friction_angle"]))
    M = 6.0 * sin_phi / (3.0 - sin_phi)
    lam, kappa = value["compression_index"], value["swelling_index"]
    sigma_v = initial["vertical_stress"]
    sigma_h = initial["lateral_stress_ratio"] * sigma_v
    p0, q0 = (sigma_v + 2.0 * sigma_h) / 3.0, sigma_v - sigma_h
    pc0 = p0 + q0 * q0 / (M * M * p0)
    p_f = p0 * (pc0 / (2.0 * p0)) ** ((lam - kappa) / lam)
    q_f = M * p_f
    u_f = p0 + (q_f - q0) / 3.0 - p_f
    for column, expected in (("q", q_f), ("u", u_f)):
        measured = [float(r[f"{column}_measured"]) for r in rows]
        last = float(rows[-1][f"{column}_fitted"])
        scale = max(measured) - min(measured)
        if abs(last - expected) > 0.001 * scale:
            failures.append(f"{column}: the fitted curve ends at {last:g} Pa, the closed-form critical state "
                            f"is {expected:g} Pa")
    for failure in failures:
        print(f"error: {out}: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))

#!/usr/bin/python3
"""Checks the histories of a `soilsph collapse` run of data/scenes/gate-lift.toml against statics and
the scene, then that scripts/plot_collapse.py draws them.

    check_histories.py PLOT_SCRIPT RUN_DIR

boundary_forces.csv: one row per wall present at t = 0 per sample; at t = 0 (the column still at rest
behind the gate) the floor carries the soil's weight M g and the gate and the fixed wall the thrust
K0 rho g (H + dx)^2 / 2 outwards (within 5 %: the SPH boundary); gauges.csv: a row per gauge per
sample, the same times as the forces, zero displacement at t = 0; energy.csv: the same times, the soil
at rest at t = 0, its potential energy falling, kinetic + potential = mechanical. Then
boundary_forces.png, gauges.png and energy.png must be non-blank PNGs."""
import json
import pathlib
import subprocess
import sys
import tomllib

import matplotlib.image as mpimg
import numpy as np

script, run = sys.argv[1], pathlib.Path(sys.argv[2])
scene = tomllib.loads((run / "scene.toml").read_text())
summary = json.loads((run / "summary.json").read_text())
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def rows(name):
    # numpy would take the first '#' line for the names (docs/reference/output-formats.md)
    with open(run / name) as f:
        data = np.genfromtxt((line for line in f if not line.startswith("#")), delimiter=",", names=True,
                             dtype=None, encoding="utf-8")
    return np.atleast_1d(data)


forces = rows("boundary_forces.csv")
names = sorted(set(forces["boundary"]))
check(names == ["fixed_wall", "floor", "removable_wall"], f"boundaries {names}")
times = np.unique(forces["time_s"])
check(times[0] == 0.0 and len(times) >= 5, f"sample times {times[:5]} ...")
# The k-th sample is the first step that starts at or after k intervals.
due = np.arange(len(times)) * scene["output"]["history_interval"]
check(np.all(times >= due * (1 - 1e-9)) and np.all(times < due + 1.01 * summary["largest_time_step"]),
      "samples are not the first steps at or after each multiple of history_interval")

s, m = scene["scene"], scene["material"]
dx, g, rho, k0 = s["particle_spacing"], s["gravity"], m["density"], scene["initial"]["lateral_stress_ratio"]
weight = summary["particles"] * rho * dx * dx * g
thrust = 0.5 * k0 * rho * g * (s["column_height"] + dx) ** 2
at_start = {r["boundary"]: r for r in forces[forces["time_s"] == 0.0]}
for name, component, expected in (("floor", "fy_N_per_m", -weight), ("fixed_wall", "fx_N_per_m", thrust),
                                  ("removable_wall", "fx_N_per_m", -thrust)):
    value = at_start[name][component]
    check(abs(value - expected) <= 0.05 * abs(expected), f"{name} {component} at t = 0: {value} (expected {expected})")

gauges = rows("gauges.csv")
check(sorted(set(gauges["gauge"])) == ["centre", "gate-foot"], f"gauges {sorted(set(gauges['gauge']))}")
check(np.array_equal(np.unique(gauges["time_s"]), times), "gauge and force sample times differ")
first = gauges[gauges["time_s"] == 0.0]
check(np.all(first["ux_m"] == 0.0) and np.all(np.abs(first["uy_m"]) < 1e-12), "displacement at t = 0 is not zero")

energy = rows("energy.csv")
check(np.array_equal(energy["time_s"], times), "energy and force sample times differ")
weight_height = weight * s["column_height"]  # M g H: the scale of the soil's energies (J/m)
check(energy["potential_J_per_m"][0] == 0.0 and energy["kinetic_J_per_m"][0] < 1e-6 * weight_height,
      f"energy at t = 0: {energy[0]} (the soil at rest, its potential measured from t = 0)")
check(energy["potential_J_per_m"][-1] < -1e-3 * weight_height, "the soil's potential energy did not fall")
check(np.allclose(energy["mechanical_J_per_m"], energy["kinetic_J_per_m"] + energy["potential_J_per_m"],
                  rtol=0, atol=1e-12 * weight_height), "mechanical energy is not kinetic + potential")

for name in ("boundary_forces.png", "gauges.png", "energy.png"):
    (run / name).unlink(missing_ok=True)
subprocess.run([sys.executable, script, str(run)], check=True)
for name in ("boundary_forces.png", "gauges.png", "energy.png"):
    path = run / name
    if not path.exists():
        failures.append(f"{name} was not written")
        continue
    image = mpimg.imread(path)
    check(image[..., :3].std() > 0.01, f"{name} is blank")

if failures:
    sys.exit("check_histories: " + "; ".join(failures))
print(f"check_histories: {len(times)} samples of {len(names)} boundaries and 2 gauges, statics at t = 0 hold")

#!/usr/bin/python3
"""Runs scripts/plot_collapse.py on two synthetic runs and checks the pictures it must write exist, are
PNG images of a sensible size and are not blank. Usage: check_plots.py PLOT_SCRIPT RUN_DIR COMPARE_DIR"""
import pathlib
import subprocess
import sys

import matplotlib.image as mpimg

script, run, other = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
expected = [f"velocity_t{t}.png" for t in ("0.05", "0.10", "0.15", "0.20")]
expected += ["velocity.png", "deposit.png", "profiles.png", "compare_velocity.png"]
for name in expected:
    (run / name).unlink(missing_ok=True)  # so that a stale picture cannot pass

subprocess.run([sys.executable, script, str(run), "--compare", other], check=True)
failures = []
for name in expected:
    path = run / name
    if not path.exists():
        failures.append(f"{name} was not written")
        continue
    if path.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
        failures.append(f"{name} is not a PNG")
        continue
    image = mpimg.imread(path)
    if image.shape[0] < 200 or image.shape[1] < 300:
        failures.append(f"{name} is only {image.shape[1]} x {image.shape[0]} pixels")
    if image[..., :3].std() < 0.01:
        failures.append(f"{name} is blank")
for failure in failures:
    print("FAIL:", failure)
print("plots ok" if not failures else "plots FAILED")
sys.exit(1 if failures else 0)

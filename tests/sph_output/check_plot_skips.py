#!/usr/bin/python3
"""Runs scripts/plot_collapse.py on a run whose frames lack velocity, speed and layer ([output] fields)
and checks that it succeeds, names each missing field and skips (does not write) the pictures that need
it. Usage: check_plot_skips.py PLOT_SCRIPT RUN_DIR"""
import pathlib
import subprocess
import sys

script, run = sys.argv[1], pathlib.Path(sys.argv[2])
skipped = [f"velocity_t{t}.png" for t in ("0.05", "0.10", "0.15", "0.20")] + ["velocity.png", "deposit.png"]
for name in skipped:
    (run / name).unlink(missing_ok=True)  # so that a stale picture cannot hide a written one

result = subprocess.run([sys.executable, script, str(run)], capture_output=True, text=True)
print(result.stdout + result.stderr)
failures = []
if result.returncode != 0:
    failures.append(f"plot_collapse.py exited with {result.returncode}")
for message in ("has no velocity or speed field", "skipping velocity_t*.png and velocity.png",
                "has no layer field", "skipping deposit.png"):
    if message not in result.stderr:
        failures.append(f"stderr does not say {message!r}")
failures += [f"{name} was written" for name in skipped if (run / name).exists()]
for failure in failures:
    print("FAIL:", failure)
print("skips ok" if not failures else "skips FAILED")
sys.exit(1 if failures else 0)

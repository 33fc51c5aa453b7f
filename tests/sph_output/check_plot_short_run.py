#!/usr/bin/python3
"""The velocity snapshots of scripts/plot_collapse.py on runs that end before the paper's last snapshot
time (0.20 s): each frame drawn once, the last frame the run's last, the files named by the frames'
own times; and on a run that reaches it, the paper's four times. Checked on frame times directly and on
a synthetic run cut at 0.10 s (its frames every 0.01 s) in a temporary folder.
Usage: check_plot_short_run.py PLOT_SCRIPT RUN_DIR"""
import importlib.util
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

script, run = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
spec = importlib.util.spec_from_file_location("plot_collapse", script)
plot_collapse = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot_collapse)
failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)


# Frame times every 0.01 s up to `end`: which frames are drawn, and under which names.
for end, expected in ((0.30, [("0.05", 5), ("0.10", 10), ("0.15", 15), ("0.20", 20)]),
                      (0.20, [("0.05", 5), ("0.10", 10), ("0.15", 15), ("0.20", 20)]),
                      # 0.1 s: the frames nearest 0.025, 0.05, 0.075 and 0.1 s (ties either way).
                      (0.10, None),
                      (0.02, None),
                      (0.0, [("0.00", 0)])):
    times = np.round(np.arange(0.0, end + 0.005, 0.01), 10)
    chosen = plot_collapse.snapshot_frames(times)
    indices = [index for _, index in chosen]
    names = [name for name, _ in chosen]
    if expected is not None:
        expect(chosen == expected, f"run to {end} s: {chosen}, expected {expected}")
        continue
    last = len(times) - 1
    expect(len(set(indices)) == len(indices), f"run to {end} s: a frame drawn twice: {chosen}")
    expect(indices == sorted(indices) and indices[-1] == last, f"run to {end} s: not ending at the last frame: {chosen}")
    expect(len(indices) == min(4, len(times)), f"run to {end} s: {len(indices)} frames, expected {min(4, len(times))}")
    expect(names == [f"{times[i]:.2f}" for i in indices], f"run to {end} s: names {names} are not the frames' times")

# A synthetic run cut at 0.10 s: four distinct pictures, none named after a time it never reached.
with tempfile.TemporaryDirectory() as temp:
    short = pathlib.Path(temp) / "short"
    short.mkdir()
    with h5py.File(run / "frames.h5", "r") as source, h5py.File(short / "frames.h5", "w") as target:
        for name in source:
            if name.startswith("frame_") and float(source[name].attrs["time"]) <= 0.1 + 1e-9:
                source.copy(source[name], target, name)
    summary = json.loads((run / "summary.json").read_text())
    summary["end_time"] = 0.1
    (short / "summary.json").write_text(json.dumps(summary))
    subprocess.run([sys.executable, str(script), str(short)], check=True, capture_output=True)
    written = sorted(path.name for path in short.glob("velocity_t*.png"))
    expected_names = [f"velocity_t{t}.png" for t in ("0.10",)]
    expect(len(written) == 4, f"cut run: {written}, expected four pictures")
    expect(all(float(name[len("velocity_t"):-4]) <= 0.1 for name in written),
           f"cut run: a picture named after a time past the run's end: {written}")
    expect(set(expected_names) <= set(written), f"cut run: no picture of its last frame (0.10 s): {written}")
    contents = {(short / name).read_bytes() for name in written}
    expect(len(contents) == len(written), "cut run: two snapshot pictures are the same")
    expect((short / "velocity.png").exists(), "cut run: no velocity.png")
    shutil.rmtree(short)

for failure in failures:
    print("FAIL:", failure)
print("short-run snapshots ok" if not failures else "short-run snapshots FAILED")
sys.exit(1 if failures else 0)

#!/usr/bin/python3
"""Checks that two `soilsph collapse` output folders hold the same result, bit for bit: every number
of summary.json that describes the result (not the wall time, threads, version or command line), the
number of frames, and every dataset of the final frame (exact equality, NaN equal to NaN).

    /usr/bin/python3 scripts/compare_runs.py DIR_A DIR_B

Prints the differences and exits 1 if there is any (e.g. to check that a change of code leaves the
shipped runs bit-identical; docs/validation/scenes.md). A summary field or a
dataset that only the second run has is listed as added, not a difference: a newer soilsph writes
more than an older one (e.g. the `material` field and the summary's `materials`)."""
import json
import pathlib
import sys

import h5py
import numpy as np

NOT_RESULTS = {"wall_seconds", "particle_steps_per_second", "threads", "version", "command_line", "inputs"}


def final_frame(run: pathlib.Path) -> pathlib.Path:
    frames = sorted(p for p in (run / "frames").glob("frame_*.h5"))
    if not frames:
        sys.exit(f"error: {run}: no frames/frame_*.h5")
    return frames[-1]


def main() -> int:
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    sa, sb = (json.loads((d / "summary.json").read_text()) for d in (a, b))
    differences, added = [], []
    for key in sorted(set(sa) | set(sb)):
        if key in NOT_RESULTS:
            continue
        if key not in sa:
            added.append(f"summary.json {key}")
            continue
        if sa.get(key, "<absent>") != sb.get(key, "<absent>"):
            differences.append(f"summary.json {key}: {sa.get(key, '<absent>')} != {sb.get(key, '<absent>')}")
    fa, fb = final_frame(a), final_frame(b)
    if fa.name != fb.name:
        differences.append(f"final frame: {fa.name} != {fb.name}")
    with h5py.File(fa, "r") as ha, h5py.File(fb, "r") as hb:
        for name in sorted(set(ha) | set(hb)):
            if name not in ha:
                added.append(f"{fb.name} {name}")
                continue
            if name not in hb:
                differences.append(f"{fa.name}: dataset {name} only in one run")
                continue
            x, y = np.asarray(ha[name]), np.asarray(hb[name])
            if x.shape != y.shape:
                differences.append(f"{fa.name} {name}: shape {x.shape} != {y.shape}")
            elif not np.array_equal(x, y, equal_nan=x.dtype.kind == "f"):
                differences.append(f"{fa.name} {name}: {np.count_nonzero(x != y)} of {x.size} values differ, "
                                   f"largest by {np.nanmax(np.abs(x.astype(float) - y.astype(float))):.3g}")
    for d in differences:
        print(d)
    if added:
        print(f"added in {b} (not compared): {', '.join(added)}")
    print(f"{a} vs {b}: {'identical' if not differences else f'{len(differences)} differences'} "
          f"(summary.json results, {fa.name} datasets)")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())

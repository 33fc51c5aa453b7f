#!/usr/bin/python3
"""The axes of scripts/plot_collapse.py keep their tick labels apart: on a scene as wide as a slope
with its run-out floor (here 100 cm by 10 cm) no two labels of an axis overlap, and the narrow column
keeps a label on every 2 cm grid line. Usage: check_tick_labels.py PLOT_SCRIPT"""
import importlib.util
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

spec = importlib.util.spec_from_file_location("plot_collapse", sys.argv[1])
plot_collapse = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot_collapse)


def labels(limits):
    """The drawn tick labels (text, extent) of each axis of a deposit-sized figure with `limits` (cm)."""
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=150)
    plot_collapse.prepare_axes(ax, limits, [])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    result = {}
    for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
        result[name] = [(t.get_text(), t.get_window_extent(renderer)) for t in axis.get_ticklabels()
                        if t.get_visible() and t.get_text()]
    plt.close(fig)
    return result


failures = []
for limits in ((-40.0, 60.0, -0.5, 10.0), (-30.0, 30.0, -0.5, 2.0), (0.0, 200.0, -0.5, 20.0)):
    for name, drawn in labels(limits).items():
        for (a, box_a), (b, box_b) in zip(drawn, drawn[1:]):
            if box_a.overlaps(box_b):
                failures.append(f"limits {limits}: {name} labels {a!r} and {b!r} overlap")
        if len(drawn) < 2:
            failures.append(f"limits {limits}: only {len(drawn)} {name} label(s)")
column = labels((-14.0, 6.0, -0.5, 8.0))["x"]
if len(column) != 11:  # -14, -12, ..., 6
    failures.append(f"the column's x axis has {len(column)} labels, not one per 2 cm line (11)")
print("\n".join(failures) or "tick labels apart")
sys.exit(1 if failures else 0)

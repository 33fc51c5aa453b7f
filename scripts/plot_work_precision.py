#!/usr/bin/python3
"""Work-precision plot of `soilsph bench point`: error against CVODE versus CPU time per path, log-log,
one line per integrator, one panel per model x path. Also prints, per panel and integrator, the least
CPU time that reaches an error of 1e-3 and 1e-4 (markdown). Run with Debian's /usr/bin/python3
(matplotlib, numpy).

usage: scripts/plot_work_precision.py DIR   (reads DIR/work_precision.csv, writes DIR/work_precision.png)
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(directory):
    rows = []
    with open(f"{directory}/work_precision.csv") as f:
        lines = [line for line in f if not line.startswith("#")]
    for r in csv.DictReader(lines):
        r["increments"] = int(r["increments"])
        r["error"] = max(float(r["error_q"]), float(r["error_p"]))
        r["cpu_seconds"] = float(r["cpu_seconds"])
        rows.append(r)
    panels = defaultdict(lambda: defaultdict(list))
    for r in rows:
        panels[(r["material"], r["path"])][r["integrator"]].append(r)
    materials = sorted({k[0] for k in panels}, reverse=True)
    paths = ["triaxial-drained", "triaxial-undrained", "oedometer"]
    # Driver sub-step variants ("+path(TOL)", the K ~ p cases): the scheme keeps its colour, the path
    # tolerance sets the line style, and the legends move outside the panels.
    many = any("+path(" in r["integrator"] for r in rows)
    styles = {}
    base_colours = {}

    def style(integrator):
        base, _, path = integrator.partition("+path(")
        colour = base_colours.setdefault(base, f"C{len(base_colours) % 10}")
        dash = styles.setdefault(path, ["-", "--", ":", "-."][len(styles) % 4])
        return colour, dash

    fig, axes = plt.subplots(len(materials), len(paths), figsize=(24 if many else 15, 4.2 * len(materials)),
                             squeeze=False)
    floor = 1e-16
    for i, material in enumerate(materials):
        for j, path in enumerate(paths):
            ax = axes[i][j]
            for integrator, points in sorted(panels[(material, path)].items()):
                points = sorted(points, key=lambda r: r["increments"])
                xs = [p["cpu_seconds"] for p in points if math.isfinite(p["error"])]
                ys = [max(p["error"], floor) for p in points if math.isfinite(p["error"])]
                colour, dash = style(integrator)
                ax.loglog(xs, ys, marker="o", markersize=3, label=integrator, color=colour, linestyle=dash)
            ax.set_title(f"{material}, {path} (to eps_a = 0.1)", fontsize=9)
            ax.set_xlabel("CPU time per path (s)")
            ax.set_ylabel("max relative error in q, p' vs CVODE")
            ax.grid(True, which="both", alpha=0.3)
            if many:
                ax.legend(fontsize=5, loc="upper left", bbox_to_anchor=(1.0, 1.0))
            else:
                ax.legend(fontsize=7)
    fig.suptitle("Work-precision of the stress integrators (1 to 10^4 increments per path; "
                 "p', q compression-positive)", fontsize=11)
    fig.tight_layout()
    fig.savefig(f"{directory}/work_precision.png", dpi=110)

    print("| model | path | integrator | least time for error ≤ 1e-3 (increments) | least time for error ≤ 1e-4 (increments) |")
    print("|---|---|---|---|---|")
    for material in materials:
        for path in paths:
            for integrator, points in sorted(panels[(material, path)].items()):
                cells = []
                for target in (1e-3, 1e-4):
                    ok = [p for p in points if p["error"] <= target]
                    best = min(ok, key=lambda p: p["cpu_seconds"]) if ok else None
                    cells.append(f"{best['cpu_seconds']:.2e} s ({best['increments']})" if best else "not reached")
                print(f"| {material} | {path} | {integrator} | {cells[0]} | {cells[1]} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "results/bench-point")

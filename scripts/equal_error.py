#!/usr/bin/python3
"""Cost of `substep` over the error-controlled family of `implicit` at equal error, from one or more
`soilsph bench point` runs (docs/method/integrators.md).

For each family (every row whose integrator label starts with "implicit", every one that starts with
"substep": tolerances, increments and driver sub-steps pooled) the work-precision front is the set of
rows that no cheaper row beats in error. The CPU time a family needs for an error e is read off its
front two ways:
  - grid: the least time of a row with error <= e (what the benchmark's grid happens to hold);
  - interpolated: log-log interpolation between the two front rows whose errors bracket e (the
    cost a tolerance between those two grid values would have, if cost and error move together);
    at or above the least accurate front row, that row's time.
Each cell is the ratio substep / implicit (> 1: implicit is cheaper), the median over the runs given.
With --plot PNG, the two fronts of the first run, one panel per case and path.

usage: /usr/bin/python3 scripts/equal_error.py [--plot PNG] DIR [DIR ...]   (each DIR holds work_precision.csv)
"""
import csv
import math
import statistics
import sys
from collections import defaultdict

TARGETS = (1e-3, 3e-4, 1e-4, 3e-5)
FAMILIES = ("implicit", "substep")


def read(directory):
    with open(f"{directory}/work_precision.csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    points = defaultdict(list)  # (material, path, family) -> [(error, seconds)]
    for r in rows:
        family = next((f for f in FAMILIES if r["integrator"].startswith(f)), None)
        error = max(float(r["error_q"]), float(r["error_p"]))
        if family and math.isfinite(error):
            points[(r["material"], r["path"], family)].append((error, float(r["cpu_seconds"])))
    return points


def front(points):
    """Rows by increasing error whose time is below every more accurate row's."""
    out, best = [], math.inf
    for error, seconds in sorted(points):
        if seconds < best:
            out.append((error, seconds))
            best = seconds
    return out


def grid_time(points, target):
    ok = [s for e, s in points if e <= target]
    return min(ok) if ok else None


def interpolated_time(points, target):
    f = front(points)
    if not f or target < f[0][0]:
        return None
    if target >= f[-1][0]:
        return f[-1][1]
    for (e1, s1), (e2, s2) in zip(f, f[1:]):
        if e1 <= target <= e2:
            w = (math.log(target) - math.log(e1)) / (math.log(e2) - math.log(e1))
            return math.exp((1 - w) * math.log(s1) + w * math.log(s2))
    return None


def plot(run, path_png):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    materials = sorted({k[0] for k in run})
    paths = sorted({k[1] for k in run})
    fig, axes = plt.subplots(len(materials), len(paths), figsize=(5 * len(paths), 3.8 * len(materials)),
                             squeeze=False)
    for i, material in enumerate(materials):
        for j, path in enumerate(paths):
            ax = axes[i][j]
            for family, colour in zip(FAMILIES, ("C0", "C1")):
                f = front(run.get((material, path, family), []))
                if f:
                    ax.loglog([s for _, s in f], [e for e, _ in f], marker="o", markersize=3, color=colour,
                              label=f"{family} (every tolerance, increments, path sub-steps)")
            ax.set_title(f"{material}, {path}", fontsize=9)
            ax.set_xlabel("CPU time per path (s)")
            ax.set_ylabel("max relative error in q, p' vs CVODE")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
    fig.suptitle("Work-precision fronts: the cheapest run of each family at each error "
                 "(p', q compression-positive)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path_png, dpi=110)


def main(directories, path_png=None):
    runs = [read(d) for d in directories]
    if path_png:
        plot(runs[0], path_png)
    keys = sorted({k[:2] for run in runs for k in run})
    head = " | ".join(f"{t:.0e}" for t in TARGETS)
    print(f"| case | path | metric | {head} |")
    print("|---|---|---|" + "---|" * len(TARGETS))
    for material, path in keys:
        for metric, reader in (("interpolated", interpolated_time), ("grid", grid_time)):
            cells = []
            for target in TARGETS:
                ratios = []
                for run in runs:
                    ti = reader(run.get((material, path, "implicit"), []), target)
                    ts = reader(run.get((material, path, "substep"), []), target)
                    if ti and ts:
                        ratios.append(ts / ti)
                cells.append(f"{statistics.median(ratios):.2f}" if ratios else "-")
            print(f"| {material} | {path} | {metric} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    args = sys.argv[1:]
    png = None
    if args[:1] == ["--plot"] and len(args) >= 2:
        png, args = args[1], args[2:]
    if not args:
        sys.exit(__doc__)
    main(args, png)

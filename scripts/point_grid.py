#!/usr/bin/python3
"""The material-point corner grid: a material's triaxial paths over a product of parameters, every
integrator against the CVODE reference.

    scripts/point_grid.py [--out DIR] [--material FILE] [--integrators cvode,implicit,substep,explicit]
                          [--increments 100] [--jobs 2] [--quick] [--no-tension-cutoff] [--check]
                          [--binary PATH]

Axes (the Mohr-Coulomb grid of docs/validation/known-limits.md): drained and undrained triaxial to
eps_a = 0.3 and -0.2, psi = 0/10/20 deg, c = 0/5 kPa, E = 1/10/100 MPa, p0 = 1 kPa/100 kPa/1 MPa,
and no tension cut-off or T = 0 (`--quick`: one value of psi, c, E and p0, for a smoke test;
`--no-tension-cutoff` for a model without that key, e.g. data/materials/dp-table1.toml). With
`--check` the exit status is 1 when any run failed.
Each case runs `soilsph point MATERIAL --test ... --set material.KEY=VALUE`; a run fails when the
command does. The difference from CVODE is max |x - x_cvode| / max(|q_cvode|, |p_cvode|) over every
row, x = q and p' (compression-positive). Writes DIR/grid.csv (one row per case and integrator) and
DIR/grid.md (per integrator: runs, failures, cases within 1e-6 and beyond 1e-3 of CVODE), and prints
the summary.
"""
import argparse
import csv
import itertools
import pathlib
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

ROOT = pathlib.Path(__file__).resolve().parent.parent
AXES = {
    "test": ["triaxial-drained", "triaxial-undrained"],
    "strain_max": [0.3, -0.2],
    "dilatancy_angle": [0, 10, 20],
    "cohesion": [0, 5000],
    "young_modulus": [1e6, 10e6, 100e6],
    "p_initial": [1e3, 1e5, 1e6],
    "tension_cutoff": [None, 0],
}
QUICK = {"dilatancy_angle": [20], "cohesion": [5000], "young_modulus": [1e6], "p_initial": [1e3]}


def read_curve(path):
    """q and p' columns of a point CSV (header lines start with '#')."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [float(r["q"]) for r in rows], [float(r["p"]) for r in rows]


def run_case(args, case, integrator, out):
    name = "_".join(f"{v}" for v in case.values()) + f"_{integrator}"
    csv_path = out / "runs" / f"{name}.csv"
    command = [args.binary, "point", args.material, "--test", case["test"], f"--strain-max={case['strain_max']}",
               "--increments", str(args.increments), "--integrator", integrator, "--p-initial", str(case["p_initial"]),
               "--out", str(csv_path)]
    for key in ("dilatancy_angle", "cohesion", "young_modulus", "tension_cutoff"):
        if case[key] is not None:
            command += ["--set", f"material.{key}={case[key]}"]
    done = subprocess.run(command, capture_output=True, text=True)
    message = (done.stderr.strip().splitlines() or [""])[-1]
    return {**case, "integrator": integrator, "ok": done.returncode == 0, "message": message, "csv": csv_path}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="results/point-grid")
    parser.add_argument("--material", default=str(ROOT / "data" / "materials" / "mc-table1.toml"))
    parser.add_argument("--integrators", default="cvode,implicit,substep,explicit")
    parser.add_argument("--increments", type=int, default=100)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--no-tension-cutoff", action="store_true")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--binary", default=str(ROOT / "build" / "apps" / "soilsph" / "soilsph"))
    args = parser.parse_args()
    integrators = args.integrators.split(",")
    if "cvode" not in integrators:
        integrators.insert(0, "cvode")
    out = pathlib.Path(args.out)
    (out / "runs").mkdir(parents=True, exist_ok=True)
    axes = {**AXES, **(QUICK if args.quick else {})}
    if args.no_tension_cutoff:
        axes["tension_cutoff"] = [None]
    cases = [dict(zip(axes, values)) for values in itertools.product(*axes.values())]
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        runs = list(pool.map(lambda job: run_case(args, *job, out),
                             [(case, integrator) for case in cases for integrator in integrators]))
    reference = {tuple(r[k] for k in axes): r for r in runs if r["integrator"] == "cvode"}
    for r in runs:
        ref = reference[tuple(r[k] for k in axes)]
        r["difference"] = ""
        if r["ok"] and ref["ok"] and r["integrator"] != "cvode":
            (q, p), (q_ref, p_ref) = read_curve(r["csv"]), read_curve(ref["csv"])
            scale = max(max(map(abs, q_ref)), max(map(abs, p_ref)))
            r["difference"] = max(max(abs(a - b) for a, b in zip(q, q_ref)), max(abs(a - b) for a, b in zip(p, p_ref)))
            r["difference"] /= scale
    fields = list(axes) + ["integrator", "ok", "difference", "message"]
    with open(out / "grid.csv", "w", newline="") as f:
        f.write("# soilsph point grid: one row per case and integrator; difference = max |q, p' - CVODE's| / "
                "max |q, p'| of CVODE (compression-positive)\n")
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(runs)
    lines = [f"# Point grid: {len(cases)} cases of {pathlib.Path(args.material).name}, {args.increments} increments",
             "", "| integrator | runs | failed | within 1e-6 of CVODE | beyond 1e-3 |", "|---|---|---|---|---|"]
    for integrator in integrators:
        mine = [r for r in runs if r["integrator"] == integrator]
        failed = sum(not r["ok"] for r in mine)
        compared = [r["difference"] for r in mine if r["difference"] != ""]
        within = "–" if integrator == "cvode" else sum(d <= 1e-6 for d in compared)
        beyond = "–" if integrator == "cvode" else sum(d > 1e-3 for d in compared)
        lines.append(f"| {integrator} | {len(mine)} | {failed} | {within} | {beyond} |")
    for r in runs:
        if not r["ok"]:
            lines.append(f"\nfailed: {r['integrator']} {[r[k] for k in axes]}: {r['message']}")
    (out / "grid.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 1 if args.check and not all(r["ok"] for r in runs) else 0


if __name__ == "__main__":
    sys.exit(main())

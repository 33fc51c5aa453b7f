#!/usr/bin/python3
"""soilsph's axisymmetric column beside SPHinXsys's own run of its 3D repose-angle case.

Usage: compare_sphinxsys_3d.py RUN_DIR [--figure FILE]

RUN_DIR is a `soilsph collapse data/scenes/axisymmetric-column.toml` run (any symmetry) with its
energy.csv; the reference is data/reference/sphinxsys-3d-repose/ (SPHinXsys's energy history and
deposit, whole cylinder). Energies are compared divided by each run's initial potential energy above
the floor's surface, E_p0 = sum m g (y - y_floor), so a quarter compares with a whole cylinder;
soilsph's E_p0 comes from its first frame. Prints the deposit and energy table (markdown) and draws
the two energy histories.
"""
import argparse
import csv
import json
import pathlib

import h5py
import numpy as np

REFERENCE = pathlib.Path(__file__).resolve().parent.parent / "data" / "reference" / "sphinxsys-3d-repose"


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def soilsph_energy(run):
    summary = json.loads((run / "summary.json").read_text())
    scene = summary["inputs"]["scene"]
    dp, rho = scene["particle_spacing"], summary["inputs"]["material"]["density"]
    g = -scene["gravity"][1] if isinstance(scene["gravity"], list) else scene["gravity"]
    with h5py.File(run / "frames.h5") as f:
        y = f["frame_000000/position"][:, 1]
    # The floor's surface lies half a spacing below the first row (docs/reference/scenes.md).
    ep0 = float(np.sum(rho * dp**3 * g * (y - (y.min() - 0.5 * dp))))
    history = rows(run / "energy.csv")
    t = np.array([float(r["time_s"]) for r in history])
    kinetic = np.array([float(r["kinetic_J"]) for r in history]) / ep0
    mechanical = np.array([float(r["mechanical_J"]) for r in history]) / ep0
    return summary, t, kinetic, mechanical


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", type=pathlib.Path)
    parser.add_argument("--figure", type=pathlib.Path)
    args = parser.parse_args()

    summary, t, kinetic, mechanical = soilsph_energy(args.run)
    reference = rows(REFERENCE / "energy_history_1s.csv")
    rt = np.array([float(r["time_s"]) for r in reference])
    rk = np.array([float(r["kinetic_over_Ep0"]) for r in reference])
    rm = np.array([float(r["mechanical_change_over_Ep0"]) for r in reference])
    deposit = json.loads((REFERENCE / "deposit.json").read_text())["deposit_at_end_time"]

    at = 0.5  # SPHinXsys's end time
    print("| | SPHinXsys (whole, r0/dp = 10) | soilsph |")
    print("|---|---|---|")
    print(f"| runout radius (m) | {deposit['runout_radius_m']:.4f} | {summary['runout_radius_m']:.4f} |")
    print(f"| spread over azimuths (m) | {deposit['runout_radius_spread_m']:.4f} | "
          f"{summary['runout_radius_spread_m']:.4f} |")
    print(f"| height on the axis (m) | {deposit['height_on_axis_m']:.4f} | {summary['height_m']:.4f} |")
    print(f"| peak E_k / E_p0 | {rk.max():.3f} at {rt[rk.argmax()]:.3f} s | "
          f"{kinetic.max():.3f} at {t[kinetic.argmax()]:.3f} s |")
    print(f"| dissipated by t = {at} s, / E_p0 | {-np.interp(at, rt, rm):.3f} | {-np.interp(at, t, mechanical):.3f} |")
    print(f"| dissipated at the end, / E_p0 | {-rm[-1]:.3f} (t = {rt[-1]:.2f} s) | "
          f"{-mechanical[-1]:.3f} (t = {t[-1]:.2f} s) |")

    if args.figure:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.4, 3.8))
        ax.plot(rt, rk, color="tab:gray", label="SPHinXsys: kinetic")
        ax.plot(rt, -rm, color="tab:gray", linestyle="--", label="SPHinXsys: dissipated")
        ax.plot(t, kinetic, color="tab:blue", label="soilsph: kinetic")
        ax.plot(t, -mechanical, color="tab:blue", linestyle="--", label="soilsph: dissipated")
        ax.set_xlabel("t (s)")
        ax.set_ylabel("energy / initial potential energy")
        ax.set_xlim(0, max(rt[-1], t[-1]))
        ax.legend(frameon=False, fontsize=8)
        fig.tight_layout()
        fig.savefig(args.figure, dpi=120)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Figures of a `soilsph calibrate` result folder.

    plot_calibration.py DIR

Reads DIR/fit.json, DIR/curves-NAME.csv and DIR/history.csv and writes
  DIR/fit-NAME.png   per experiment: each matched column against the driven one, measured (dots),
                     fitted (line) and with the starting parameters (dashed);
  DIR/history.png    the misfit (sum of squared normalised residuals) after each iteration, per start.
Compression-positive; stresses plotted in kPa, strains dimensionless. Run with Debian's
/usr/bin/python3 (matplotlib, numpy). A missing file gives one `error:` line and exit status 1.
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STRESSES = {"sig_a", "sig_r", "p", "q", "p_c", "u", "tau_xy"}
LABELS = {"eps_a": "axial strain", "eps_r": "radial strain", "eps_v": "volumetric strain",
          "eps_q": "deviatoric strain", "sig_a": "axial stress", "sig_r": "radial stress",
          "p": "mean effective stress p'", "q": "deviator stress q", "p_c": "preconsolidation p_c",
          "u": "excess pore pressure u", "tau_xy": "shear stress", "gamma_xy": "shear strain"}


def read_csv(path):
    """{column: array} of a CSV with '#' comment lines and a header row."""
    if not path.is_file():
        raise FileNotFoundError(f"{path}: no such file")
    lines = [line for line in path.read_text().splitlines() if line and not line.startswith("#")]
    names = lines[0].split(",")
    values = np.array([[float(x) for x in line.split(",")] for line in lines[1:]], ndmin=2)
    return {name: values[:, k] for k, name in enumerate(names)}


def shown(column, values):
    """Values in plotting units and the axis label."""
    unit = " (kPa)" if column in STRESSES else ""
    return (values * 1e-3 if column in STRESSES else values), LABELS.get(column, column) + unit


def plot_experiment(folder, experiment):
    data = read_csv(folder / experiment["curves"])
    against = experiment["against"]
    columns = experiment["match"]
    fig, axes = plt.subplots(1, len(columns), figsize=(5.0 * len(columns), 4.0), squeeze=False)
    x, x_label = shown(against, data[against])
    for ax, column in zip(axes[0], columns):
        for suffix, style in (("measured", dict(ls="none", marker="o", ms=3, color="k", label="measured")),
                              ("fitted", dict(color="tab:blue", label="fitted")),
                              ("start", dict(color="tab:gray", ls="--", label="start"))):
            y, y_label = shown(column, data[f"{column}_{suffix}"])
            ax.plot(x, y, **style)
        ax.set_xlabel(x_label)
        ax.set_ylabel(y_label)
        ax.grid(alpha=0.3)
        ax.legend()
    fig.suptitle(f"{experiment['name']}: measured and fitted (compression-positive)")
    fig.tight_layout()
    out = folder / f"fit-{experiment['name']}.png"
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def plot_history(folder):
    history = read_csv(folder / "history.csv")
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    for start in np.unique(history["start"]):
        rows = history["start"] == start
        ax.semilogy(history["iteration"][rows], np.maximum(history["cost"][rows], 1e-300), marker=".",
                    label=f"start {int(start)}")
    ax.set_xlabel("iteration")
    ax.set_ylabel("misfit: sum of squared normalised residuals")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    out = folder / "history.png"
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    folder = Path(argv[1])
    try:
        fit = json.loads((folder / "fit.json").read_text())
        written = [plot_experiment(folder, e) for e in fit["experiments"]] + [plot_history(folder)]
    except (OSError, ValueError, KeyError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    print("figures: " + ", ".join(str(p) for p in written))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""Plot material-point CSVs of `soilsph point`, one or more overlaid in one figure.

    plot_point.py CSV [CSV ...] [--out FILE.png] [--labels A,B,...]

Panels: q - eps_a, eps_v - eps_a, the p'-q stress path with each file's yield surfaces and critical-state
line (MCC: the initial and final ellipses from the first and last row's p_c) or failure line (D-P,
Mohr-Coulomb: triaxial compression), e - ln p' (e = e0 - (1 + e0) eps_v, e0 from the `# material:` line; eps_v when
no file has e0), and tau_xy - gamma_xy when some file has non-zero shear. The lines come from the
CSV's `# failure line` comment (any plastic model), or for older files from its `# material:` line. Compression-positive; stresses plotted in kPa, strains dimensionless.
Labels default to the file names (stem); the PNG to the first CSV's path with .png.
Run with Debian's /usr/bin/python3 (matplotlib, numpy). A missing file or a CSV without the header
row gives one `error:` line on stderr and exit status 1.
"""
import argparse
import io
import math
import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

KPA = 1e-3
COLUMNS = ["eps_a", "eps_r", "eps_v", "eps_q", "sig_a", "sig_r", "p", "q", "p_c", "u"]
SHEAR_COLUMNS = ["tau_xy", "gamma_xy"]  # absent from older files: read as zeros
COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink",
          "tab:olive", "tab:cyan"]


class PointCsvError(Exception):
    """A CSV that cannot be plotted; the message names the file."""


def parse_material(line):
    """`# material: FILE: key = value; ...` -> {key: value}, strings unquoted, numbers as float."""
    material = {}
    for item in line.split("; "):
        match = re.search(r"([A-Za-z_]\w*) = (.+)$", item.strip())
        if not match:
            continue
        key, value = match.groups()
        if value.startswith('"') and value.endswith('"'):
            material[key] = value[1:-1]
        else:
            try:
                material[key] = float(value)
            except ValueError:
                material[key] = value
    return material


def read_point_csv(path):
    """(material dict, {column: array}) of one `soilsph point` CSV."""
    if not path.is_file():
        raise PointCsvError(f"{path}: no such file")
    lines = path.read_text().splitlines()
    material = {}
    for line in lines:
        if line.startswith("# material:"):
            material = {**parse_material(line[len("# material:"):]), **material}
        if line.startswith("# failure line"):
            numbers = re.findall(r"(slope|intercept) = ([-+0-9.eE]+)", line)
            material["failure_line"] = tuple(float(dict(numbers)[key]) for key in ("slope", "intercept"))
    body = [line for line in lines if not line.startswith("#") and line.strip()]
    header = body[0].strip().split(",") if body else []
    if header[:len(COLUMNS)] != COLUMNS:
        raise PointCsvError(f"{path}: no header row '{','.join(COLUMNS)}[,tau_xy,gamma_xy]' "
                            f"after the '#' lines (not a soilsph point CSV?)")
    if len(body) < 2:
        raise PointCsvError(f"{path}: header but no data rows")
    try:
        rows = np.loadtxt(io.StringIO("\n".join(body[1:])), delimiter=",", ndmin=2)
    except ValueError as err:
        raise PointCsvError(f"{path}: unreadable data row ({err})") from None
    data = {name: rows[:, i] for i, name in enumerate(header)}
    for name in SHEAR_COLUMNS:
        data.setdefault(name, np.zeros(len(rows)))
    return material, data


def critical_state_ratio(friction_angle_deg):
    """M = 6 sin(phi) / (3 - sin(phi)) (triaxial compression; modified_cam_clay.cpp, eq 26)."""
    sin_phi = math.sin(math.radians(friction_angle_deg))
    return 6.0 * sin_phi / (3.0 - sin_phi)


def drucker_prager_cone(friction_angle_deg, cohesion):
    """(slope, intercept) of the cone f = sqrt(J2) + alpha_phi I1 - k_c = 0 (drucker_prager.h, eq 19) on
    triaxial compression, q = 3 sqrt3 alpha_phi p' + sqrt3 k_c: for files without a `# failure line`."""
    tan_phi = math.tan(math.radians(friction_angle_deg))
    root = math.sqrt(9.0 + 12.0 * tan_phi ** 2)
    alpha, k_c = tan_phi / root, 3.0 * cohesion / root
    return 3.0 * math.sqrt(3.0) * alpha, math.sqrt(3.0) * k_c


def failure_line(material):
    """(slope, intercept) of the file's failure line q = slope p' + intercept, or None."""
    if "failure_line" in material:
        return material["failure_line"]
    model = material.get("model")
    if model == "modified-cam-clay" and "friction_angle" in material:
        return critical_state_ratio(material["friction_angle"]), 0.0
    if model == "drucker-prager" and "friction_angle" in material:
        return drucker_prager_cone(material["friction_angle"], material.get("cohesion", 0.0))
    return None


def draw_surfaces(ax, material, data, color, p_top, drawn):
    """Yield surfaces and the critical-state line / D-P cone of one file in the p'-q plane.

    `drawn` collects the lines already drawn, so files of one material share one CSL or cone."""
    model = material.get("model")
    line = failure_line(material)
    if line is None:
        return
    p = np.linspace(0.0, p_top, 400)
    if (model, line) not in drawn:
        drawn.add((model, line))
        if model == "modified-cam-clay":
            ax.plot(p * KPA, line[0] * p * KPA, color="gray", lw=1, label=f"CSL q = M p', M = {line[0]:.3f}")
        else:
            ax.plot(p * KPA, (line[0] * p + line[1]) * KPA, color=color, ls="-.", lw=1,
                    label=f"{model} failure (compression), φ = {material.get('friction_angle', float('nan')):g}°")
    if model == "modified-cam-clay":
        M = line[0]
        for pc, ls, which in ((data["p_c"][0], ":", "initial"), (data["p_c"][-1], "--", "final")):
            pp = np.linspace(0.0, pc, 400)
            qq = M * np.sqrt(np.maximum(pp * (pc - pp), 0.0))
            ax.plot(pp * KPA, qq * KPA, color=color, ls=ls, lw=0.9, alpha=0.8,
                    label=f"{which} yield surface (p_c = {pc * KPA:.4g} kPa)")
            ax.plot(pp * KPA, -qq * KPA, color=color, ls=ls, lw=0.9, alpha=0.8)


def void_ratio(material, data):
    """e = e0 - (1 + e0) eps_v, or None for a material without initial_void_ratio."""
    e0 = material.get("initial_void_ratio")
    if not isinstance(e0, float):
        return None
    return e0 - (1.0 + e0) * data["eps_v"]


def make_axes(with_shear):
    """The figure and its named panels: 2 x 2, or 2 x 3 with the tau - gamma panel."""
    columns = 3 if with_shear else 2
    fig, grid = plt.subplots(2, columns, figsize=(5.0 * columns, 8.4))
    grid = grid.ravel()
    names = ["q", "eps_v", "path", "e"] + (["shear"] if with_shear else [])
    for ax in grid[len(names):]:
        ax.set_visible(False)
    return fig, dict(zip(names, grid))


def plot_curves(axes, runs):
    """Each file's curves on every panel; returns the labels of files left out of e - ln p'."""
    any_e0 = any(void_ratio(material, data) is not None for _, material, data in runs)
    left_out = []
    for i, (label, material, data) in enumerate(runs):
        style = dict(color=COLORS[i % len(COLORS)], lw=1.3, label=label)
        axes["q"].plot(data["eps_a"], data["q"] * KPA, **style)
        axes["eps_v"].plot(data["eps_a"], data["eps_v"], **style)
        axes["path"].plot(data["p"] * KPA, data["q"] * KPA, **style)
        positive = data["p"] > 0.0  # log axis
        e = void_ratio(material, data)
        if e is not None:
            axes["e"].plot(data["p"][positive] * KPA, e[positive], **style)
        elif not any_e0:
            axes["e"].plot(data["p"][positive] * KPA, data["eps_v"][positive], **style)
        else:
            left_out.append(label)
        if "shear" in axes:
            axes["shear"].plot(data["gamma_xy"], data["tau_xy"] * KPA, **style)
    return any_e0, left_out


def log_axis(ax):
    """A log p' axis labelled in plain numbers (as in plot_verification.py), denser over a narrow range."""
    ax.set_xscale("log")
    low, high = ax.get_xlim()
    narrow = high / low < 4.0
    subs = (1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 7.0) if narrow else (1.0, 2.0, 3.0, 5.0, 7.0)
    ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=subs))
    ax.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())


def label_axes(axes, any_e0, left_out):
    axes["q"].set(xlabel="axial strain ε_a (–)", ylabel="deviator stress q (kPa)", title="q – ε_a")
    axes["eps_v"].set(xlabel="axial strain ε_a (–)", ylabel="volumetric strain ε_v (–)",
                      title="ε_v – ε_a")
    axes["path"].set(xlabel="mean effective stress p' (kPa)", ylabel="deviator stress q (kPa)",
                     title="stress path p' – q")
    log_axis(axes["e"])
    if any_e0:
        axes["e"].set(xlabel="p' (kPa, log scale)", ylabel="void ratio e = e0 − (1+e0) ε_v (–)",
                      title="e – ln p'")
    else:
        axes["e"].set(xlabel="p' (kPa, log scale)", ylabel="volumetric strain ε_v (–)",
                      title="ε_v – ln p' (no e0 in the material)")
    if left_out:
        axes["e"].text(0.02, 0.02, "not shown (no e0): " + ", ".join(left_out), fontsize=7,
                       transform=axes["e"].transAxes)
    if "shear" in axes:
        axes["shear"].set(xlabel="shear strain γ_xy (–)", ylabel="shear stress τ_xy (kPa)",
                          title="τ_xy – γ_xy")
        axes["shear"].xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
    for ax in axes.values():
        ax.grid(alpha=0.3)


def plot(runs, out):
    """One figure of all runs [(label, material, data)] written to `out`."""
    with_shear = any(np.any(data["tau_xy"] != 0.0) or np.any(data["gamma_xy"] != 0.0)
                     for _, _, data in runs)
    fig, axes = make_axes(with_shear)
    any_e0, left_out = plot_curves(axes, runs)
    p_top = max(max(data["p"].max(), data["p_c"].max()) for _, _, data in runs) * 1.05
    drawn = set()
    for i, (_, material, data) in enumerate(runs):
        draw_surfaces(axes["path"], material, data, COLORS[i % len(COLORS)], p_top, drawn)
    axes["path"].set_xlim(0.0, p_top * KPA)
    axes["path"].set_ylim(bottom=min(0.0, axes["path"].get_ylim()[0]))
    label_axes(axes, any_e0, left_out)
    axes["q"].legend(fontsize=8)
    axes["path"].legend(fontsize=6.5, loc="upper left")
    fig.suptitle("soilsph point: compression-positive; stresses in kPa, strains dimensionless", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def parse_args(argv):
    parser = argparse.ArgumentParser(description="Plot soilsph point CSVs (overlaid) into one PNG.")
    parser.add_argument("csv", nargs="+", type=Path, help="CSV files written by `soilsph point`")
    parser.add_argument("--out", type=Path, help="PNG to write (default: the first CSV with .png)")
    parser.add_argument("--labels", help="comma-separated legend labels, one per CSV (default: file stems)")
    return parser.parse_args(argv)


def main(argv):
    args = parse_args(argv)
    labels = args.labels.split(",") if args.labels else [path.stem for path in args.csv]
    try:
        if len(labels) != len(args.csv):
            raise PointCsvError(f"--labels gives {len(labels)} labels for {len(args.csv)} CSV files")
        runs = [(label, *read_point_csv(path)) for label, path in zip(labels, args.csv)]
        out = args.out or args.csv[0].with_suffix(".png")
        plot(runs, out)
    except (PointCsvError, OSError) as err:
        print(f"error: {err}", file=sys.stderr)
        return 1
    print(f"  plot  {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

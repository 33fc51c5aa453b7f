#!/usr/bin/python3
"""Plots of `soilsph verify`: one PNG per case under DIR/plots/, from DIR/cases.json and DIR/csv/.

Panels: q - eps_a, eps_v - eps_a, the p'-q stress path with the yield surface and the critical-state
(MCC) or failure (D-P) line, and e - ln p' for isotropic and oedometer paths. Every integrator's curve
is drawn over the CVODE reference (black) and the closed form (red, dashed) where the case has one.
Compression-positive, SI (plotted in kPa). Run with Debian's /usr/bin/python3 (matplotlib, numpy).
Usage: plot_verification.py DIR
"""
import io
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

KPA = 1e-3
STYLES = {"cvode": dict(color="black", lw=2.2, label="CVODE reference"),
          "closed-form": dict(color="tab:red", lw=1.4, ls="--", label="closed form")}
COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown"]


def read_csv(path):
    """A soilsph CSV: '#' comment lines, then a header row and the numbers."""
    if not path.exists():
        return None
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    return np.genfromtxt(io.StringIO("\n".join(lines)), delimiter=",", names=True)


def curves(case, folder):
    """(label, data, style) for each available curve; the reference and closed form drawn last, on top."""
    out = []
    for i, name in enumerate(case["integrators"]):
        data = read_csv(folder / "csv" / f"{case['name']}.{name}.csv")
        if data is not None:
            out.append((name, data, dict(color=COLORS[i % len(COLORS)], lw=1.0, marker="o", ms=2.5,
                                         markevery=max(len(data) // 25, 1), label=f"{name}")))
    for key in ("cvode", "closed-form"):
        data = read_csv(folder / "csv" / f"{case['name']}.{key}.csv")
        if data is not None:
            out.append((key, data, STYLES[key]))
    return out


def draw_surfaces(ax, case, reference):
    """Yield surface(s) and the critical-state / failure line in the p'-q plane (triaxial compression)."""
    p_top = ax.get_xlim()[1] / KPA
    pcs = {}
    if case["model"] == "modified-cam-clay":
        pcs["initial yield surface"] = case["ocr"] * case["p_initial"]
        if reference is not None:
            pcs["final yield surface"] = reference["p_c"][-1]
        p_top = max([p_top] + list(pcs.values()))
    p = np.linspace(0.0, p_top, 400)
    if "failure_slope" in case:  # every plastic model: q = slope p' + intercept (failure_line.h)
        label = "CSL q = M p'" if case["model"] == "modified-cam-clay" else f"{case['model']} failure (compression)"
        ax.plot(p * KPA, (case["failure_slope"] * p + case["failure_intercept"]) * KPA, color="gray", lw=1,
                label=label)
    if case["model"] == "modified-cam-clay":
        M = case["M"]
        if case["path"] == "oedometer" and "eta_k0" in case:
            ax.plot(p * KPA, case["eta_k0"] * p * KPA, color="tab:green", lw=1, ls="--",
                    label=f"K0 line, η = {case['eta_k0']:.3f}")
        for (label, pc), ls in zip(pcs.items(), (":", "-.")):
            pp = np.linspace(0.0, pc, 400)
            qq = M * np.sqrt(np.maximum(pp * (pc - pp), 0.0))
            ax.plot(pp * KPA, qq * KPA, color="gray", ls=ls, lw=1, label=label)
            ax.plot(pp * KPA, -qq * KPA, color="gray", ls=ls, lw=1)


def plot_case(case, folder):
    data = curves(case, folder)
    if not data:
        return None
    reference = next((d for name, d, _ in data if name == "cvode"), None)
    compression = case["path"] in ("isotropic", "oedometer") and case["model"] == "modified-cam-clay"
    panels = 4 if compression else 3
    fig, axes = plt.subplots(1, panels, figsize=(4.6 * panels, 4.0))
    for name, d, style in data:
        axes[0].plot(d["eps_a"], d["q"] * KPA, **style)
        axes[1].plot(d["eps_a"], d["eps_v"], **style)
        axes[2].plot(d["p"] * KPA, d["q"] * KPA, **style)
        if compression:
            e = case["e0"] - (1.0 + case["e0"]) * d["eps_v"]
            axes[3].plot(d["p"] * KPA, e, **style)
    axes[0].set(xlabel="axial strain ε_a", ylabel="q (kPa)", title="q – ε_a")
    axes[1].set(xlabel="axial strain ε_a", ylabel="volumetric strain ε_v", title="ε_v – ε_a")
    axes[2].set(xlabel="p' (kPa)", ylabel="q (kPa)", title="stress path")
    draw_surfaces(axes[2], case, reference)
    axes[2].set_xlim(left=0.0)
    axes[2].set_ylim(bottom=min(0.0, axes[2].get_ylim()[0]))
    low, high = axes[0].get_ylim()
    if high - low < 1.0:  # q ≡ 0 (isotropic): do not magnify round-off
        axes[0].set_ylim(-1.0, 1.0)
    if compression:
        axes[3].set_xscale("log")
        axes[3].xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        axes[3].xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 1.5, 2.0, 3.0, 5.0, 7.0)))
        axes[3].xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
        axes[3].set(xlabel="p' (kPa, log scale)", ylabel="void ratio e = e0 − (1+e0) ε_v", title="e – ln p'")
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[2].legend(fontsize=7, loc="upper left")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{case['name']}: {case['model']}, {case['path']}, p'_0 = {case['p_initial'] * KPA:g} kPa, "
                 f"OCR = {case['ocr']:g} (compression-positive)", fontsize=10)
    fig.tight_layout()
    out = folder / "plots" / f"{case['name']}.png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    (folder / "plots").mkdir(parents=True, exist_ok=True)
    for case in json.loads((folder / "cases.json").read_text()):
        out = plot_case(case, folder)
        if out is not None:
            print(f"  plot  {out}")


if __name__ == "__main__":
    main()

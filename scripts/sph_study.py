#!/usr/bin/python3
"""Studies of the SPH collapse: resolution, time step (CFL) and stress integrator, run as sets of
`soilsph collapse` runs whose summary.json files are gathered into one CSV and one figure.
Run with Debian's /usr/bin/python3 (matplotlib, numpy).

    scripts/sph_study.py resolution [--out DIR] [--spacings 4,2,1,0.5] [--block paper|fixed]
                                    [--smoothing-length MM] [--models D-P,MCC,MCC-viscous] [--jobs 2] [--reuse]
    scripts/sph_study.py cfl        [--out DIR] [--cfls 0.2,0.3,...] [--spacing 2] [--integrators shipped,implicit]
    scripts/sph_study.py integrator [--out DIR] [--spacing 1]
    scripts/sph_study.py cut        [--out DIR] [--heights 3,4,...] [--spacings 2,1]
    scripts/sph_study.py slope      [--out DIR] [--spacings 4,2] [--rounds 3] [--end-time 0.5] [--factors F,...]

Every run goes to the scene's end time or to rest (the scene's stop_at_rest). Runs go `--jobs` at a
time with one thread each (results do not depend on the thread count; wall times are one core's).

resolution: spacing 4, 2, 1 and 0.5 mm for both shipped scenes (--models: some of them, or the variant
  MCC-viscous: the MCC scene with viscoplastic_relaxation_time = 1.16e-4 s, to rest within 3 s).
  Writes DIR/resolution.csv (one row per run: the summary's fields) and DIR/resolution.md: runout,
  height and repose angle, their differences from the finest run, Richardson's observed order and
  extrapolated value where three spacings converge monotonically, and wall time; DIR/resolution.png: error against wall time,
  log-log, per model and measure (the SPH counterpart of the work-precision figure).
  --block fixed refines one W x H block: the column keys put particle centres on the edges of W x H
  (the paper's layout), a block of (W + dp) x (H + dp) that shrinks as dp does, so each run takes
  column_width W - dp, column_height H - dp and toe_thickness H/10, and the table reports the
  measures from the walls' faces to the cells' edges (runout, H/10 runout and height + dp; the
  CSV adds them as runout_face_m, runout_thick_face_m, height_face_m).
  --smoothing-length MM keeps h at MM millimetres in every run (smoothing_ratio = h/dp, which the
  scene allows from 1 to 2) instead of the scene's h/dp: it refines the particles within one kernel.
  A softening soil's shear bands are about h wide, so this separates the deposit's dependence on
  the particles from its dependence on the kernel (docs/validation/resolution.md).
cfl: the shipped scenes at one spacing for each CFL number, with the shipped and the implicit
  integrator; a run counts as unstable if it fails, if the wall guard acts, or if it is not at rest by
  its end time (2 s). Writes DIR/cfl.csv and DIR/cfl.md.
integrator: explicit, substep and implicit for both scenes at one spacing: DIR/integrator.csv, .md.
cut: the vertical cut (data/scenes/vertical-cut.toml) at each height and spacing, to 1 s without
  stopping at rest (a marginal cut creeps below the rest speed); the face displacement W - min x at
  the end against H in units of (c/gamma) tan(45 + phi/2), between the limit-analysis bounds 2 and
  3.83. Writes DIR/cut.csv, DIR/cut.md and DIR/cut.png (face displacement against time per height).
slope: the factor of safety of data/scenes/slope.toml by strength reduction: for a factor F the
  Mohr-Coulomb strength is reduced to c/F and tan(phi)/F (the D-P cone follows from its plane-strain
  match), and the run goes to --end-time without stopping at rest. It fails if the largest
  displacement of a soil particle at the end exceeds --fail-spacings (3) spacings. The bracket starts
  at [1, 2 FoS_Bishop] (each end checked) and shrinks threefold per round (two runs at its thirds, in
  parallel); --factors runs the given factors only (a finer spacing near a known bracket). Writes DIR/slope.csv (every run), DIR/slope.md (the critical F and its bracket per
  spacing) and, with --figure, docs-style DIR/slope.png: the displacement field of the failing run
  nearest above the critical F with the Bishop circle (scripts/slope_bishop.py) drawn over it.
"""
import argparse
import csv
import json
import math
import os
import pathlib
import subprocess
import sys
import tomllib
from concurrent.futures import ThreadPoolExecutor

ROOT = pathlib.Path(__file__).resolve().parent.parent
# The binary: $SOILSPH_BINARY (the tests give their build's), else build/apps/soilsph/soilsph.
SOILSPH = pathlib.Path(os.environ.get("SOILSPH_BINARY", ROOT / "build" / "apps" / "soilsph" / "soilsph"))
SCENES = {"D-P": "collapse-dp", "MCC": "collapse-mcc"}
# Variants the resolution study runs on request (--models): label -> (run prefix, scene, --set values).
# MCC-viscous: the paper's MCC scene with the Duvaut-Lions relaxation whose deposit converges,
# G tau = 45 Pa s on Table 1's E; it rests after about 1.3 s (docs/validation/resolution.md).
VARIANTS = {"MCC-viscous": ("collapse-mcc-viscous", "collapse-mcc",
                            ["material.viscoplastic_relaxation_time=1.16e-4", "scene.end_time=3"])}
RESOLUTION_MODELS = {**{label: (scene, scene, []) for label, scene in SCENES.items()}, **VARIANTS}
MEASURES = (("runout_m", "runout", 100.0, "cm"), ("runout_thick_m", "runout where H0/10 thick", 100.0, "cm"),
            ("height_m", "height", 100.0, "cm"), ("repose_angle_deg", "repose angle", 1.0, "deg"))
# --block fixed: the same measures from the walls' faces to the cells' edges (each length + dp).
FACE_MEASURES = (("runout_face_m", "runout from the wall's face", 100.0, "cm"),
                 ("runout_thick_face_m", "runout where H0/10 thick, from the face", 100.0, "cm"),
                 ("height_face_m", "height above the floor's face", 100.0, "cm"),
                 ("repose_angle_deg", "repose angle", 1.0, "deg"))


def run(name, scene, overrides, out, reuse=False):
    """One `soilsph collapse` run into out/runs/name; returns its summary with the run's name and status.
    With `reuse`, a run whose folder already holds a summary.json is not run again (resume a study)."""
    folder = out / "runs" / name
    if reuse and (folder / "summary.json").exists():
        return {"run": name, "status": "ok", **json.loads((folder / "summary.json").read_text())}
    command = [str(SOILSPH), "collapse", str(ROOT / "data" / "scenes" / f"{scene}.toml"), "--out", str(folder),
               "--threads", "1", "--set", 'output.fields=["velocity","layer"]', "--set", "output.frame_interval=0.05"]
    for o in overrides:
        command += ["--set", o]
    done = subprocess.run(command, capture_output=True, text=True)
    summary = {"run": name, "status": "ok" if done.returncode == 0 else "failed"}
    if done.returncode == 0:
        summary.update(json.loads((folder / "summary.json").read_text()))
    else:
        summary["error"] = (done.stderr.strip().splitlines() or ["?"])[-1]
    print(f"{name}: {summary['status']}", {k: summary.get(k) for k in ("runout_m", "end_time", "wall_seconds")},
          flush=True)
    return summary


def run_all(specs, out, jobs, reuse=False):
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(lambda s: {**s[3], **run(*s[:3], out, reuse)}, specs))


def write_csv(rows, path):
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        f.write("# soilsph collapse study: one row per run (summary.json fields; SI units, angles in degrees)\n")
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(rows)


DEPOSIT_HEADER = "runout (cm) | runout where H0/10 thick (cm) | height (cm) | repose (°) | t end (s) | steps | wall (s)"


def deposit_cells(r):
    """The deposit and cost of one run, as the cells under DEPOSIT_HEADER (7 of them)."""
    if r["status"] != "ok":
        return f"failed: {r['error']} |" + " |" * 6
    return (f"{100 * r['runout_m']:.2f} | {100 * r['runout_thick_m']:.2f} | {100 * r['height_m']:.2f} "
            f"| {r['repose_angle_deg']:.1f} | {r['end_time']:.3f} | {r['steps']} | {r['wall_seconds']:.1f}")


def write_markdown(path, title, header, lines):
    text = "\n".join([f"# {title}", "", f"| {header} |", "|" + "---|" * (header.count("|") + 1)] + lines) + "\n"
    path.write_text(text)
    print(text)


def richardson(h, v):
    """Observed order and extrapolated value from three spacings h[0] > h[1] > h[2] with ratio 2, or None
    when the differences do not shrink monotonically at an order of at least ½ (below that the
    extrapolation d2/(2^p − 1) is dominated by noise)."""
    d1, d2 = v[1] - v[0], v[2] - v[1]
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None
    order = math.log(abs(d1 / d2)) / math.log(h[0] / h[1])
    return (order, v[2] + d2 / (2 ** order - 1)) if order >= 0.5 else None


def block_overrides(scene, spacing_m, block, smoothing_m=None):
    """The --set values of one run: the spacing, the smoothing ratio that keeps h at `smoothing_m`
    (if given) and, for the fixed block, the column keys that keep the soil between the walls at the
    scene's W x H and the toe thickness at its H/10."""
    overrides = [f"scene.particle_spacing={spacing_m}"]
    if smoothing_m is not None:
        overrides.append(f"scene.smoothing_ratio={smoothing_m / spacing_m!r}")
    if block == "fixed":
        keys = tomllib.loads((ROOT / "data" / "scenes" / f"{scene}.toml").read_text())["scene"]
        W, H = keys["column_width"], keys["column_height"]
        overrides += [f"scene.column_width={W - spacing_m!r}", f"scene.column_height={H - spacing_m!r}",
                      f"deposit.toe_thickness={0.1 * H!r}"]
    return overrides


def resolution(args):
    out = pathlib.Path(args.out)
    spacings = [float(s) for s in args.spacings.split(",")]
    unknown = [label for label in args.models.split(",") if label not in RESOLUTION_MODELS]
    if unknown:
        sys.exit(f"error: --models {args.models}: unknown {', '.join(unknown)} "
                 f"(allowed: {', '.join(RESOLUTION_MODELS)})")
    scenes = {label: RESOLUTION_MODELS[label] for label in args.models.split(",")}
    smoothing_mm = args.smoothing_length  # h fixed at every spacing, or None
    if smoothing_mm is not None:
        for s in spacings:
            if not 1.0 <= smoothing_mm / s <= 2.0:
                sys.exit(f"error: --smoothing-length {smoothing_mm:g} mm at spacing {s:g} mm is "
                         f"h/dp = {smoothing_mm / s:.3g} (allowed: 1 to 2, the scenes' smoothing_ratio range)")
    specs = [(f"{prefix}-{s:g}mm", scene,
              variant + block_overrides(scene, s / 1000, args.block,
                                        None if smoothing_mm is None else smoothing_mm / 1000) + args.set,
              {"model_label": label, "spacing_mm": s, "block": args.block,
               "smoothing_length_mm": "" if smoothing_mm is None else smoothing_mm})
             for s in sorted(spacings) for label, (prefix, scene, variant) in scenes.items()]  # finest first
    rows = run_all(specs, out, args.jobs, args.reuse)
    for r in rows:
        if r["status"] == "ok":
            r.update({f"{key[:-2]}_face_m": r[key] + r["particle_spacing"]
                      for key in ("runout_m", "runout_thick_m", "height_m")})
    write_csv(rows, out / "resolution.csv")
    measures = FACE_MEASURES if args.block == "fixed" else MEASURES
    header = " | ".join(f"{name} ({unit})" for _, name, _, unit in measures)
    title = ("one W x H block at every spacing, measured from the walls' faces" if args.block == "fixed"
             else "shipped scenes")
    if smoothing_mm is not None:
        title += f", h = {smoothing_mm:g} mm at every spacing"
    lines = [f"# Resolution study (soilsph collapse, {title}, to rest or the end time)", "",
             "Differences from the finest run in brackets (per cent; degrees for the angle).", "",
             f"| model | spacing (mm) | {header} | t end (s) | steps | wall (s) |",
             "|---|---|" + "---|" * len(measures) + "---|---|---|"]
    for label in scenes:
        model_rows = sorted((r for r in rows if r["model_label"] == label and r["status"] == "ok"),
                            key=lambda r: -r["spacing_mm"])
        if not model_rows:
            continue
        finest = model_rows[-1]
        for r in model_rows:
            cells = []
            for key, _, scale, unit in measures:
                d = r[key] - finest[key] if unit == "deg" else 100 * (r[key] - finest[key]) / finest[key]
                cells.append(f"{scale * r[key]:.2f} ({d:+.1f}{'°' if unit == 'deg' else ' %'})")
            lines.append(f"| {label} | {r['spacing_mm']:g} | " + " | ".join(cells) +
                         f" | {r['end_time']:.3f} | {r['steps']} | {r['wall_seconds']:.1f} |")
        if len(model_rows) >= 3:
            h = [r["spacing_mm"] for r in model_rows[-3:]]
            for key, name, scale, unit in measures:
                fit = richardson(h, [r[key] for r in model_rows[-3:]])
                lines.append("" if fit is None else
                             f"| {label} | Richardson ({name}, last three) | order {fit[0]:.2f}, extrapolated "
                             f"{scale * fit[1]:.2f} {unit} |" + " |" * (len(measures) + 2))
    lines = [line for line in lines if line]
    (out / "resolution.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot_resolution(rows, out / "resolution.png", measures)


def plot_resolution(rows, path, measures=MEASURES):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(measures), figsize=(4.3 * len(measures), 4))
    for ax, (key, name, scale, unit) in zip(axes, measures):
        for label, marker in zip(SCENES, "os"):
            model_rows = sorted((r for r in rows if r["model_label"] == label and r["status"] == "ok"),
                                key=lambda r: -r["spacing_mm"])
            if len(model_rows) < 2:
                continue
            finest = model_rows[-1]
            pts = [(r["wall_seconds"], abs(scale * (r[key] - finest[key])) or float("nan"), r["spacing_mm"])
                   for r in model_rows[:-1]]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=f"{label} (vs {finest['spacing_mm']:g} mm)")
            for t, e, s in pts:
                if e == e:
                    ax.annotate(f"{s:g} mm", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xlabel("wall time of the run, one core (s)")
        ax.set_ylabel(f"|{name} − finest| ({unit})")
        ax.set_title(name)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def cfl(args):
    out = pathlib.Path(args.out)
    values = [float(c) for c in args.cfls.split(",")]
    specs = []
    for label, scene in SCENES.items():
        for integrator in args.integrators.split(","):
            for c in values:
                overrides = [f"scene.particle_spacing={args.spacing / 1000}", f"numerics.cfl={c}",
                             "scene.end_time=2.0"] + args.set
                if integrator != "shipped":
                    overrides.append(f'material.integrator="{integrator}"')
                specs.append((f"{scene}-{integrator}-cfl{c:g}", scene, overrides,
                              {"model_label": label, "integrator_choice": integrator, "cfl": c}))
    rows = run_all(specs, out, args.jobs, args.reuse)
    write_csv(rows, out / "cfl.csv")
    lines = []
    for r in rows:
        stable = r["status"] == "ok" and r.get("guard_corrections", 1) == 0 and r.get("stopped_at_rest")
        lines.append(f"| {r['model_label']} | {r['integrator_choice']} | {r['cfl']:g} | {'yes' if stable else 'NO'} "
                     f"| {deposit_cells(r)} |")
    write_markdown(out / "cfl.md", f"CFL sweep at {args.spacing:g} mm (to rest, at most 2 s)",
                   "model | integrator | cfl | stable | " + DEPOSIT_HEADER, lines)


def integrator(args):
    out = pathlib.Path(args.out)
    specs = [(f"{scene}-{name}", scene, [f"scene.particle_spacing={args.spacing / 1000}",
                                         f'material.integrator="{name}"'] + args.set,
              {"model_label": label})
             for label, scene in SCENES.items() for name in ("explicit", "substep", "implicit")]
    rows = run_all(specs, out, args.jobs, args.reuse)
    write_csv(rows, out / "integrator.csv")
    lines = [f"| {r['model_label']} | {r['run'].split('-')[-1]} | {deposit_cells(r)} |" for r in rows]
    write_markdown(out / "integrator.md", f"Stress integrator at {args.spacing:g} mm (to rest or 1 s)",
                   "model | integrator | " + DEPOSIT_HEADER, lines)


def cut(args):
    out = pathlib.Path(args.out)
    c, rho, g, phi, width = 200.0, 2000.0, 9.81, 35.0, 0.08  # data/scenes/vertical-cut.toml
    unit = c / (rho * g) * math.tan(math.radians(45.0 + phi / 2.0))
    heights = [float(h) / 100 for h in args.heights.split(",")]
    spacings = [float(s) / 1000 for s in args.spacings.split(",")]
    specs = [(f"cut-H{100 * h:g}cm-{1000 * s:g}mm", "vertical-cut",
              [f"scene.column_height={h}", f"scene.particle_spacing={s}", "scene.stop_at_rest=false",
               "output.frame_interval=0.02"] + args.set, {"H_m": h, "spacing_m": s})
             for s in spacings for h in heights]
    rows = run_all(specs, out, args.jobs, args.reuse)
    for r in rows:
        r["H_over_unit"] = r["H_m"] / unit
        r["face_displacement_m"] = r["runout_m"] - width if r["status"] == "ok" else float("nan")
    write_csv(rows, out / "cut.csv")
    lines = [f"| {1000 * r['spacing_m']:g} | {100 * r['H_m']:g} | {r['H_over_unit']:.2f} | "
             f"{1000 * r['face_displacement_m']:.2f} | {r['face_displacement_m'] / r['spacing_m']:.2f} | "
             f"{100 * r.get('height_m', float('nan')):.2f} | {r.get('wall_seconds', float('nan')):.1f} |" for r in rows]
    write_markdown(out / "cut.md", f"Vertical cut, c = {c:g} Pa, phi = {phi:g} deg: bounds 2 and 3.83 x "
                   f"{100 * unit:.3f} cm = {200 * unit:.2f} and {383 * unit:.2f} cm (face displacement at 1 s)",
                   "spacing (mm) | H (cm) | H / ((c/γ) tan(45°+φ/2)) | face displacement (mm) | in spacings | "
                   "height (cm) | wall (s)", lines)
    plot_cut(rows, out, unit)


def plot_cut(rows, out, unit):
    import h5py
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    spacings = sorted({r["spacing_m"] for r in rows}, reverse=True)
    fig, axes = plt.subplots(1, len(spacings), figsize=(5.5 * len(spacings), 4.2), squeeze=False)
    for ax, s in zip(axes[0], spacings):
        for r in (r for r in rows if r["spacing_m"] == s and r["status"] == "ok"):
            with h5py.File(out / "runs" / r["run"] / "frames.h5") as f:
                frames = sorted(k for k in f.keys() if k.startswith("frame_"))
                t = [f[k].attrs["time"] for k in frames]
                face = [-f[k]["position"][:, 0].min() for k in frames]  # soil particles only
            ax.plot(t, [1000 * v for v in face],
                    label=f"H = {100 * r['H_m']:g} cm ({r['H_over_unit']:.2f})")
        ax.set(xlabel="t (s)", ylabel="face displacement (mm)", yscale="symlog",
               title=f"spacing {1000 * s:g} mm; H in units of (c/γ) tan(45°+φ/2) = {100 * unit:.2f} cm")
        ax.axhline(1000 * s, color="gray", lw=0.8, ls=":")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Vertical cut in D-P soil (c = 200 Pa, φ = 35°): limit-analysis bounds 2 and 3.83; "
                 "dotted: one spacing", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "cut.png", dpi=110)


def slope_strength():
    """The shipped slope's Mohr-Coulomb c (Pa) and phi (degrees), read from data/scenes/slope.toml."""
    import tomllib
    material = tomllib.loads((ROOT / "data" / "scenes" / "slope.toml").read_text())["material"]
    return material["cohesion"], material["friction_angle"]


def bishop(extra=()):
    """FoS_Bishop and the critical circle of the shipped slope (scripts/slope_bishop.py)."""
    done = subprocess.run([sys.executable, str(ROOT / "scripts" / "slope_bishop.py"),
                           str(ROOT / "data" / "scenes" / "slope.toml"), *extra], capture_output=True, text=True,
                          check=True)
    lines = done.stdout.splitlines()
    fos = float(lines[1].split("=")[1])
    numbers = [float(t.strip("(),m;")) for t in lines[2].replace(",", " ").split() if t.strip("(),m;")
               .replace(".", "", 1).replace("-", "", 1).isdigit()]
    return fos, {"xc": numbers[0], "yc": numbers[1], "r": numbers[2], "x1": numbers[3], "x2": numbers[4]}


def largest_displacement(folder):
    """The largest displacement of a soil particle between the first and the last frame (m)."""
    import h5py
    import numpy as np
    with h5py.File(folder / "frames.h5") as f:
        frames = sorted(k for k in f.keys() if k.startswith("frame_"))
        first, last = f[frames[0]]["position"][:], f[frames[-1]]["position"][:]
    return float(np.max(np.hypot(*(last - first).T[:2])))


def slope_run(args, spacing, factor, out):
    c0, phi0 = slope_strength()
    c = c0 / factor
    phi = math.degrees(math.atan(math.tan(math.radians(phi0)) / factor))
    name = f"slope-{1000 * spacing:g}mm-F{factor:.4f}"
    r = run(name, "slope", [f"scene.particle_spacing={spacing}", f"scene.end_time={args.end_time}",
                            f"material.cohesion={c}", f"material.friction_angle={phi}",
                            "output.fields=[\"velocity\"]", f"output.frame_interval={args.end_time / 10}"] + args.set,
            out, args.reuse)
    r.update({"spacing_m": spacing, "F": factor, "cohesion_Pa": c, "friction_angle_deg": phi})
    if r["status"] == "ok":
        r["largest_displacement_m"] = largest_displacement(out / "runs" / name)
        r["fails"] = r["largest_displacement_m"] > args.fail_spacings * spacing
    else:
        r["fails"] = True  # a run that blows up has not stood
    print(f"  F = {factor:.4f}: largest displacement {1000 * r.get('largest_displacement_m', float('nan')):.2f} mm, "
          f"{'fails' if r['fails'] else 'stands'}", flush=True)
    return r


def slope(args):
    import time
    out = pathlib.Path(args.out)
    start = time.time()
    fos, circle = bishop()
    print(f"FoS_Bishop = {fos:.4f}, critical circle {circle}")
    rows, results = [], []
    if args.factors:  # given factors only, no bisection: the bracket is what they show
        factors = [float(f) for f in args.factors.split(",")]
        for spacing in [float(s) / 1000 for s in args.spacings.split(",")]:
            with ThreadPoolExecutor(max_workers=args.jobs) as pool:
                runs = list(pool.map(lambda f: slope_run(args, spacing, f, out), factors))
            rows += runs
            stands = [r["F"] for r in runs if not r["fails"]]
            fails = [r["F"] for r in runs if r["fails"]]
            lo, hi = max(stands, default=float("nan")), min(fails, default=float("nan"))
            results.append((spacing, 0.5 * (lo + hi), lo, hi, "given factors"))
    for spacing in [] if args.factors else [float(s) / 1000 for s in args.spacings.split(",")]:
        lo, hi = 1.0, 2.0 * fos
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            ends = list(pool.map(lambda f: slope_run(args, spacing, f, out), (lo, hi)))
            rows += ends
            if ends[0]["fails"] or not ends[1]["fails"]:
                results.append((spacing, float("nan"), lo, hi, "the bracket's ends do not stand and fail"))
                continue
            for _ in range(args.rounds):
                thirds = (lo + (hi - lo) / 3.0, lo + 2.0 * (hi - lo) / 3.0)
                runs = list(pool.map(lambda f: slope_run(args, spacing, f, out), thirds))
                rows += runs
                if runs[0]["fails"]:
                    hi = thirds[0]
                elif runs[1]["fails"]:
                    lo, hi = thirds
                else:
                    lo = thirds[1]
        results.append((spacing, 0.5 * (lo + hi), lo, hi, ""))
    wall = time.time() - start
    write_csv(rows, out / "slope.csv")
    lines = [f"| {1000 * s:g} | {f:.3f} | [{lo:.3f}, {hi:.3f}] | {f / fos:.3f} | {note} |" for s, f, lo, hi, note in results]
    write_markdown(out / "slope.md", f"Slope, strength reduction: FoS_Bishop = {fos:.3f}; failure: largest "
                   f"displacement > {args.fail_spacings:g} spacings at t = {args.end_time:g} s; study wall time "
                   f"{wall:.0f} s", "spacing (mm) | critical F | bracket | F / FoS_Bishop | note", lines)
    if args.figure:
        plot_slope(rows, results, circle, fos, out)


def plot_slope(rows, results, circle, fos, out):
    import h5py
    import matplotlib
    import numpy as np
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    finest = min(s for s, *_ in results)
    critical = next(r for r in results if r[0] == finest)
    failing = sorted((r for r in rows if r["spacing_m"] == finest and r["fails"] and r["status"] == "ok"
                      and r["F"] >= critical[3] - 1e-9), key=lambda r: r["F"])
    if not failing:
        return
    r = failing[0]
    with h5py.File(out / "runs" / r["run"] / "frames.h5") as f:
        frames = sorted(k for k in f.keys() if k.startswith("frame_"))
        first, last = f[frames[0]]["position"][:], f[frames[-1]]["position"][:]
    d = np.hypot(*(last - first).T[:2])
    fig, ax = plt.subplots(figsize=(9, 3.2))
    sc = ax.scatter(first[:, 0], first[:, 1], c=1000 * d, s=4, cmap="viridis")
    fig.colorbar(sc, ax=ax, label=f"displacement at t = {r['end_time']:g} s (mm)")
    t = np.linspace(0, 2 * np.pi, 721)
    xs, ys = circle["xc"] + circle["r"] * np.cos(t), circle["yc"] + circle["r"] * np.sin(t)
    keep = (ys <= circle["yc"]) & (xs >= circle["x1"] - 1e-9) & (xs <= circle["x2"] + 1e-9)  # the slip arc
    ax.plot(np.where(keep, xs, np.nan), np.where(keep, ys, np.nan), "r-", lw=1.5,
            label=f"Bishop's critical circle (FoS = {fos:.2f})")
    ax.set(aspect="equal", xlabel="x (m)", ylabel="y (m)", xlim=(-0.02, 0.29), ylim=(-0.005, 0.07),
           title=f"slope.toml at {1000 * finest:g} mm, F = {r['F']:.3f} (critical F in [{critical[2]:.3f}, "
                 f"{critical[3]:.3f}]): displacement, drawn at the initial positions")
    ax.title.set_fontsize(9)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "slope.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="study", required=True)
    for name, default_out in (("resolution", "results/study-resolution"), ("cfl", "results/study-cfl"),
                              ("integrator", "results/study-integrator"), ("cut", "results/study-cut"),
                              ("slope", "results/study-slope")):
        p = sub.add_parser(name)
        p.add_argument("--out", default=default_out)
        p.add_argument("--jobs", type=int, default=2, help="runs at a time, one thread each")
        p.add_argument("--set", action="append", default=[], help="extra --set for every run")
        p.add_argument("--reuse", action="store_true", help="keep runs whose folder has a summary.json")
        if name == "resolution":
            p.add_argument("--spacings", default="4,2,1,0.5", help="particle spacings in mm")
            p.add_argument("--models", default=",".join(SCENES),
                           help=f"comma-separated labels: {', '.join(RESOLUTION_MODELS)} "
                                "(default: the shipped scenes)")
            p.add_argument("--smoothing-length", type=float, default=None,
                           help="mm: keep h fixed (smoothing_ratio = h/dp, 1 to 2) instead of h/dp")
            p.add_argument("--block", choices=("paper", "fixed"), default="paper",
                           help="paper: the scenes' column keys; fixed: one W x H block at every spacing")
        elif name == "cut":
            p.add_argument("--spacings", default="2,1", help="particle spacings in mm")
            p.add_argument("--heights", default="3,4,5,5.4,5.6,5.8,6,8", help="cut heights in cm")
        elif name == "slope":
            p.add_argument("--spacings", default="4,2", help="particle spacings in mm")
            p.add_argument("--rounds", type=int, default=3, help="bracket shrinks 3x per round")
            p.add_argument("--end-time", type=float, default=0.5, help="s, each run's end")
            p.add_argument("--fail-spacings", type=float, default=3.0,
                           help="fails if the largest displacement exceeds this many spacings")
            p.add_argument("--figure", action="store_true", help="draw DIR/slope.png")
            p.add_argument("--factors", default="", help="run these F only (e.g. 1.46,1.53,1.61), no bisection")
        else:
            p.add_argument("--spacing", type=float, default=2.0 if name == "cfl" else 1.0, help="mm")
        if name == "cfl":
            p.add_argument("--cfls", default="0.2,0.3,0.4,0.5,0.6,0.8")
            p.add_argument("--integrators", default="shipped,implicit",
                           help="'shipped' (the scene's) and/or integrator names")
    args = parser.parse_args()
    if not SOILSPH.exists():
        sys.exit(f"sph_study: {SOILSPH} not found: build first (bash scripts/setup.sh)")
    pathlib.Path(args.out).mkdir(parents=True, exist_ok=True)
    {"resolution": resolution, "cfl": cfl, "integrator": integrator, "cut": cut,
     "slope": slope}[args.study](args)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Pictures of an SPH collapse run of any scene (Debian's /usr/bin/python3: matplotlib, h5py, numpy).

    plot_collapse.py DIR [--compare DIR2 ...] [--colour layer|material] [--labels LABEL ...]

reads DIR/frames.h5 and DIR/summary.json (docs/reference/output-formats.md) and writes
  DIR/velocity_t0.05.png ... _t0.20.png  velocity magnitude at the frame nearest each time (paper Fig. 4);
                                          a run that ends sooner gets four frames spread over it instead
                                          (the last its last, each frame once), named by their times
  DIR/velocity.png                        the snapshots together (2 x 2)
  DIR/deposit.png                         final deposit in horizontal layers of two alternating colours
                                          (paper Fig. 5); with --colour material, one colour per
                                          material (the field `material`, names from summary.json)
  DIR/profiles.png                        with --compare: final surface profiles of DIR and DIR2 ...
                                          (labels: summary.json's model; a triangle marks the toe
                                          that summary.json's runout_m measures)
  DIR/compare_velocity.png                with --compare: the snapshots of every run, one row each,
                                          on one colour scale
  DIR/boundary_forces.png                 the force on each boundary over time (boundary_forces.csv)
  DIR/gauges.png                          p, q, speed and displacement of each gauge over time
                                          (gauges.csv)
  DIR/energy.png                          the soil's kinetic, potential and mechanical energy (energy.csv)
Axes are in cm with equal aspect and a 2 cm x 2 cm background grid as in the paper. The walls are
drawn from summary.json's "boundaries" where they stand at each picture's time (a removed wall
disappears, a moving one moves); the extent is that of the particles of the frames drawn.
The velocity pictures need the field `velocity` or `speed` and deposit.png needs `layer` ([output]
fields of the scene): if a run lacks one, the script says which field is missing and skips that picture.

A 3D run (summary.json's inputs.scene.dimension = 3) gets instead, with up against gravity
(inputs.scene.gravity; a number means up = +y) and the column's axis through inputs.deposit.axis
(default the origin) along up:
  DIR/section.png                         a vertical section through the axis (the particles within one
                                          spacing of the plane through the axis), four frames from the
                                          first to the last, coloured by speed where the frames have it
  DIR/height_map.png                      plan view of the final deposit: the height of its top particle
                                          over each cell of one spacing, the initial column's rim and the
                                          measured runout_radius_m as circles
  DIR/radial_profile.png                  the top particle's height against the distance from the axis,
                                          initial column and final deposit (and each --compare run's),
                                          with Lube et al. (2004)'s r_inf and H_inf for the column's
                                          aspect ratio (inputs.scene column_radius, column_height)
and boundary_forces.png, gauges.png and energy.png as above, with z components and whole forces.
"""
import argparse
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SNAPSHOT_TIMES = (0.05, 0.10, 0.15, 0.20)
LAYER_COLOURS = ("#d9b77e", "#7a5230")  # alternating layers: light and dark sand
GRID_CM = 2.0
CM = 100.0  # metres -> centimetres
MODEL_NAMES = {"drucker-prager": "Drucker–Prager", "modified-cam-clay": "Modified Cam-Clay",
               "mohr-coulomb": "Mohr–Coulomb", "linear-elastic": "linear elastic"}


class Run:
    """One run directory: its frames (times, groups) and summary."""

    def __init__(self, directory):
        self.dir = pathlib.Path(directory)
        if not (self.dir / "frames.h5").is_file():
            sys.exit(f"plot_collapse: {self.dir / 'frames.h5'} not found (the output folder of soilsph collapse)")
        self.h5 = h5py.File(self.dir / "frames.h5", "r")
        self.names = sorted(name for name in self.h5 if name.startswith("frame_"))
        if not self.names:
            sys.exit(f"plot_collapse: {self.dir / 'frames.h5'} holds no frame")
        self.times = np.array([float(self.h5[name].attrs["time"]) for name in self.names])
        summary_file = self.dir / "summary.json"
        self.summary = json.loads(summary_file.read_text()) if summary_file.exists() else {}
        model = self.summary.get("model")
        self.label = MODEL_NAMES.get(model, model) if model else self.dir.name
        # A run that did not finish is said so on every picture, and its figures are not quoted
        # (summary.json "complete" and "stop_reason"; docs/reference/output-formats.md).
        self.complete = self.summary.get("complete") is True
        if not self.complete:
            why = (f"stopped: {self.summary['stop_reason']}" if self.summary.get("stop_reason")
                   else "no summary.json: killed, or still running")
            if self.summary.get("stop_reason") == "running":
                why = "not finished: killed, or still running"
            print(f"plot_collapse: warning: {self.dir} is an incomplete run ({why[:200]})", file=sys.stderr)
            self.label += " [INCOMPLETE RUN]"
        spacing = self.summary.get("particle_spacing") or 0.0
        self.spacing = spacing if spacing > 0 else self.estimate_spacing()
        self.dimension = self.summary.get("inputs", {}).get("scene", {}).get("dimension", 2)

    def frame(self, index):
        """Positions (m) and, where the frame holds them, speed (m/s) and layer ids of frame `index`."""
        group = self.h5[self.names[index]]
        position = group["position"][()]
        frame = {"time": self.times[index], "x": position[:, 0], "y": position[:, 1]}
        if "velocity" in group:
            velocity = group["velocity"][()]
            frame["speed"] = np.hypot(velocity[:, 0], velocity[:, 1])
        elif "speed" in group:
            frame["speed"] = group["speed"][()]
        for name in ("layer", "material"):
            if name in group:
                frame[name] = group[name][()]
        return frame

    def lacks(self, datasets, indices, picture):
        """True (after saying so on stderr) if none of `datasets` is in one of the frames `indices`."""
        for index in indices:
            group = self.h5[self.names[index]]
            if not any(name in group for name in datasets):
                print(f"plot_collapse: {self.dir / 'frames.h5'}:/{self.names[index]} has no "
                      f"{' or '.join(datasets)} field ([output] fields): skipping {picture}", file=sys.stderr)
                return True
        return False

    def estimate_spacing(self):
        """Initial spacing from the first frame: the median gap between sorted distinct x."""
        x = np.unique(np.round(self.h5[self.names[0]]["position"][:, 0], 12))
        return float(np.median(np.diff(x))) if x.size > 1 else 1e-3


def extent(frames, spacing):
    """Axis limits in cm, on the 2 cm grid, that hold every particle of `frames`."""
    x = np.concatenate([f["x"] for f in frames]) * CM
    y = np.concatenate([f["y"] for f in frames]) * CM
    pad = spacing * CM
    # A thin strip under the floor rather than a whole grid cell, so the floor line shows.
    return (GRID_CM * np.floor((x.min() - pad) / GRID_CM), GRID_CM * np.ceil((x.max() + pad) / GRID_CM),
            y.min() - max(2 * pad, 0.5), GRID_CM * np.ceil((y.max() + pad) / GRID_CM))


LABEL_INCHES = 0.45  # room a tick label such as "-24" takes along an axis, with a gap


def label_step(span_cm, axis_inches):
    """The spacing of the labelled ticks: the grid's, or the smallest multiple of it (2, 5, 10, ...
    cells) whose labels fit side by side along an axis `axis_inches` long, so that the labels of a
    wide scene do not overlap."""
    room = max(2, int(axis_inches / LABEL_INCHES))
    for cells in (1, 2, 5, 10, 20, 50, 100, 200, 500):
        if span_cm / (GRID_CM * cells) <= room:
            return GRID_CM * cells
    return GRID_CM * 1000


def prepare_axes(ax, limits, walls):
    """Equal aspect, cm axes, the paper's 2 cm background grid, the walls (polylines in cm) drawn."""
    ax.set_xlim(limits[0], limits[1])
    ax.set_ylim(limits[2], limits[3])
    ax.set_aspect("equal")
    ax.apply_aspect()
    box = ax.get_position()  # in figure fractions, once the aspect has shrunk it
    width, height = ax.figure.get_size_inches()
    for axis, low, high, inches in ((ax.xaxis, *limits[:2], box.width * width),
                                    (ax.yaxis, *limits[2:], box.height * height)):
        step = label_step(high - low, inches)
        axis.set_ticks(np.arange(step * np.ceil(low / step), high + 1e-9, step))
        axis.set_ticks(np.arange(GRID_CM * np.ceil(low / GRID_CM), high + 1e-9, GRID_CM), minor=True)
    ax.grid(True, which="both", color="0.85", linewidth=0.6, zorder=0)
    ax.set_axisbelow(True)
    ax.set_xlabel("x (cm)")
    ax.set_ylabel("y (cm)")
    for x, y in walls:
        ax.plot(x, y, color="black", linewidth=2.0, zorder=3, solid_capstyle="butt")


def marker_area(ax, spacing):
    """Scatter marker area (points^2) of a square one particle spacing wide at the axes' scale."""
    ax.apply_aspect()
    x0, _ = ax.transData.transform((0.0, 0.0))
    x1, _ = ax.transData.transform((spacing * CM, 0.0))
    side_points = abs(x1 - x0) * 72.0 / ax.figure.dpi
    return max(side_points, 0.5) ** 2


def walls(run, time=0.0):
    """The walls standing at `time` as (x, y) polylines in cm, from summary.json's "boundaries"; for a
    summary without them (older runs), the column's floor and fixed wall half a spacing beyond the
    initial particle centres."""
    boundaries = run.summary.get("boundaries")
    if boundaries is None:
        first = run.frame(0)
        floor, wall = (first["y"].min() - 0.5 * run.spacing) * CM, (first["x"].max() + 0.5 * run.spacing) * CM
        return [(np.array([-1e3, wall]), np.array([floor, floor])), (np.array([wall, wall]), np.array([floor, 1e3]))]
    lines = []
    for b in boundaries:
        if b.get("removed_at") is not None and time >= b["removed_at"]:
            continue
        points = np.array(b["points"], dtype=float)
        if "velocity" in b:  # moved by its velocity during [start, end]
            moved = min(max(time, b["start"]), b["end"]) - b["start"]
            points = points + moved * np.array(b["velocity"], dtype=float)
        lines.append((points[:, 0] * CM, points[:, 1] * CM))
    return lines


def draw_speed(ax, run, frame, limits, vmax):
    prepare_axes(ax, limits, walls(run, frame["time"]))
    order = np.argsort(frame["speed"])  # fast particles on top
    return ax.scatter(frame["x"][order] * CM, frame["y"][order] * CM, c=frame["speed"][order], cmap="turbo",
                      vmin=0.0, vmax=vmax, marker="s", s=marker_area(ax, run.spacing), linewidths=0,
                      zorder=2)


def snapshot_frames(times):
    """The frames of the velocity snapshots as (name, index), in time order, each frame once: the frames
    nearest the paper's times (Fig. 4, named 0.05 ... 0.20) when the run reaches the last of them, else
    those nearest four times spread evenly up to the run's end, named by their own times."""
    times = np.asarray(times)
    end = float(times[-1])
    interval = end / max(len(times) - 1, 1)
    reaches = end >= SNAPSHOT_TIMES[-1] - 0.5 * interval
    count = len(SNAPSHOT_TIMES)
    wanted = SNAPSHOT_TIMES if reaches else [end * (k + 1) / count for k in range(count)]
    indices, labels = [], []
    for t in wanted:
        index = int(np.argmin(np.abs(times - t)))
        if index not in indices:
            indices.append(index)
            labels.append(t if reaches else float(times[index]))
    digits = 2  # as many as the names need to differ
    while len({f"{t:.{digits}f}" for t in labels}) < len(labels) and digits < 9:
        digits += 1
    return [(f"{t:.{digits}f}", index) for t, index in zip(labels, indices)]


def plot_velocity(run):
    snapshots = snapshot_frames(run.times)
    indices = [index for _, index in snapshots]
    if run.lacks(("velocity", "speed"), indices, "velocity_t*.png and velocity.png"):
        return
    frames = [run.frame(i) for i in indices]
    limits = extent(frames + [run.frame(0), run.frame(len(run.names) - 1)], run.spacing)
    vmax = max(max(float(f["speed"].max()) for f in frames), 1e-12)  # one colour scale for all
    for (name, _), frame in zip(snapshots, frames):
        fig, ax = plt.subplots(figsize=(8, 4.5), dpi=150)
        points = draw_speed(ax, run, frame, limits, vmax)
        ax.set_title(f"{run.label}: velocity magnitude, t = {frame['time']:.3f} s")
        fig.colorbar(points, ax=ax, shrink=0.8, label="velocity magnitude (m/s)")
        fig.savefig(run.dir / f"velocity_t{name}.png", bbox_inches="tight")
        plt.close(fig)
    fig, axes = plt.subplots(2, 2, figsize=(13, 7.5), dpi=150, constrained_layout=True)
    for ax, frame in zip(axes.flat, frames):
        points = draw_speed(ax, run, frame, limits, vmax)
        ax.set_title(f"t = {frame['time']:.3f} s")
    for ax in axes.flat[len(frames):]:  # a run of fewer frames than snapshots
        ax.set_visible(False)
    fig.colorbar(points, ax=axes, shrink=0.8, label="velocity magnitude (m/s)")
    fig.suptitle(f"{run.label}: velocity magnitude")
    fig.savefig(run.dir / "velocity.png")
    plt.close(fig)


MATERIAL_COLOURS = ["#b5651d", "#e8c872", "#6a8caf", "#7fa36b"]  # clay-brown, sand, then others


def plot_deposit(run, colour="layer"):
    if run.lacks((colour,), [len(run.names) - 1], "deposit.png"):
        return
    final = run.frame(len(run.names) - 1)
    limits = extent([run.frame(0), final], run.spacing)
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=150)
    prepare_axes(ax, limits, walls(run, final["time"]))
    area = marker_area(ax, run.spacing)
    if colour == "material":
        materials = run.summary.get("materials") or []
        for k in np.unique(final["material"]):
            mine = final["material"] == k
            m = materials[k] if k < len(materials) else {}
            label = f"{m.get('name') or 'material ' + str(k)} ({m.get('model', '?')})"
            ax.scatter(final["x"][mine] * CM, final["y"][mine] * CM, c=MATERIAL_COLOURS[k % len(MATERIAL_COLOURS)],
                       marker="s", s=area, linewidths=0, zorder=2, label=label)
        ax.legend(loc="upper left", markerscale=3)
    else:
        colours = np.array(LAYER_COLOURS)[final["layer"] % 2]
        ax.scatter(final["x"] * CM, final["y"] * CM, c=colours, marker="s", s=area, linewidths=0, zorder=2)
    title = f"{run.label}: deposit at t = {final['time']:.3f} s"
    s = run.summary
    if run.complete and all(isinstance(s.get(key), (int, float)) for key in ("runout_m", "height_m", "repose_angle_deg")):
        title += (f"\nrunout {s['runout_m'] * CM:.2f} cm, height {s['height_m'] * CM:.2f} cm, "
                  f"repose angle {s['repose_angle_deg']:.1f}°")
    ax.set_title(title)
    fig.savefig(run.dir / "deposit.png", bbox_inches="tight")
    plt.close(fig)


def surface_profile(frame, spacing):
    """Top particle of each vertical strip of one spacing (as in sph/analysis/deposit.cpp), in cm."""
    strips = np.round(frame["x"] / spacing).astype(np.int64)
    order = np.lexsort((frame["y"], strips))
    last = np.r_[strips[order][1:] != strips[order][:-1], True]  # highest particle of each strip
    top = order[last]
    # Start on the floor under the leftmost strip, so a vertical face (the initial column) shows.
    return np.r_[frame["x"][top[0]], frame["x"][top]] * CM, np.r_[frame["y"].min(), frame["y"][top]] * CM


def deposit_frame(run):
    """Origin and unit direction of the deposit measures ([deposit] of the scene as run; the
    column's by default: from the initial right edge along -x)."""
    deposit = run.summary.get("inputs", {}).get("deposit", {})
    origin = deposit.get("origin", [run.frame(0)["x"].max(), 0.0])
    return origin, deposit.get("direction", [-1.0, 0.0])


def plot_compare_velocity(runs):
    """The snapshots of every run side by side, one row per run, one colour scale for all."""
    rows = []
    for run in runs:
        indices = [index for _, index in snapshot_frames(run.times)]
        if run.lacks(("velocity", "speed"), indices, "compare_velocity.png"):
            return
        rows.append([run.frame(i) for i in indices])
    limits = extent([f for row in rows for f in row] + [run.frame(0) for run in runs], runs[0].spacing)
    vmax = max(max(float(f["speed"].max()) for f in row) for row in rows)
    fig, axes = plt.subplots(len(runs), len(SNAPSHOT_TIMES), figsize=(4.2 * len(SNAPSHOT_TIMES), 2.6 * len(runs)),
                             dpi=150, constrained_layout=True, squeeze=False)
    for r, (run, row) in enumerate(zip(runs, rows)):
        for c, frame in enumerate(row):
            points = draw_speed(axes[r, c], run, frame, limits, max(vmax, 1e-12))
            axes[r, c].set_title(f"{run.label}, t = {frame['time']:.3f} s", fontsize=9)
        for ax in axes[r, len(row):]:  # a run of fewer frames than snapshots
            ax.set_visible(False)
    fig.colorbar(points, ax=axes, shrink=0.8, label="velocity magnitude (m/s)")
    fig.savefig(runs[0].dir / "compare_velocity.png")
    plt.close(fig)


def read_history(path):
    """A history CSV (docs/reference/output-formats.md) as {name: {column: array}}, rows grouped by
    their second column (the boundary or gauge)."""
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if line.strip() and not line.startswith("#")]
    header, rows = lines[0].split(","), [line.split(",") for line in lines[1:]]
    rows = [r for r in rows if len(r) == len(header)]  # a torn last row of a killed run
    series = {}
    for r in rows:
        entry = series.setdefault(r[1], {key: [] for key in header if key != header[1]})
        for key, value in zip(header, r):
            if key != header[1]:
                entry[key].append(float(value))
    return {name: {key: np.array(v) for key, v in columns.items()} for name, columns in series.items()}


def read_columns(path):
    """A history CSV without a name column (energy.csv) as {column: array}; a torn last row is skipped."""
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if line.strip() and not line.startswith("#")]
    header, rows = lines[0].split(","), [line.split(",") for line in lines[1:]]
    rows = [r for r in rows if len(r) == len(header)]
    return {key: np.array([float(r[k]) for r in rows]) for k, key in enumerate(header)}


def plot_histories(run):
    """boundary_forces.png, gauges.png and energy.png from the run's history CSVs, in 2D and 3D (whose
    columns add z and whose forces and energies are whole, not per metre)."""
    axes_names = ("x", "y") if run.dimension == 2 else ("x", "y", "z")
    per = "_per_m" if run.dimension == 2 else ""
    unit = "N/m" if run.dimension == 2 else "N"
    forces_file, gauges_file, energy_file = (run.dir / name for name in
                                             ("boundary_forces.csv", "gauges.csv", "energy.csv"))
    if forces_file.is_file():
        series = read_history(forces_file)
        fig, axes = plt.subplots(len(axes_names), 1, figsize=(8, 2 + 2 * len(axes_names)), dpi=150, sharex=True,
                                 constrained_layout=True)
        for name, s in series.items():
            for ax, a in zip(axes, axes_names):
                ax.plot(s["time_s"], s[f"f{a}_N{per}"], label=name)
        for ax, a in zip(axes, axes_names):
            ax.set_ylabel(f"$F_{a}$ ({unit})")
        axes[-1].set_xlabel("t (s)")
        axes[0].legend(fontsize=8)
        axes[0].set_title(f"{run.label}: force of the soil on each boundary"
                          + (" (per metre of thickness)" if run.dimension == 2 else ""))
        fig.savefig(run.dir / "boundary_forces.png")
        plt.close(fig)
    if gauges_file.is_file():
        series = read_history(gauges_file)
        fig, axes = plt.subplots(2, 2, figsize=(11, 6.5), dpi=150, sharex=True, constrained_layout=True)
        for name, s in series.items():
            speed = np.sqrt(sum(s[f"v{a}_m_per_s"] ** 2 for a in axes_names))
            displacement = np.sqrt(sum(s[f"u{a}_m"] ** 2 for a in axes_names))
            axes[0, 0].plot(s["time_s"], s["p_Pa"] / 1e3, label=name)
            axes[0, 1].plot(s["time_s"], s["q_Pa"] / 1e3, label=name)
            axes[1, 0].plot(s["time_s"], speed, label=name)
            axes[1, 1].plot(s["time_s"], displacement * CM, label=name)
        for ax, label in zip(axes.flat, ("p (kPa, compression +)", "q (kPa)", "speed (m/s)", "displacement (cm)")):
            ax.set_ylabel(label)
        for ax in axes[1]:
            ax.set_xlabel("t (s)")
        axes[0, 0].legend(fontsize=8)
        fig.suptitle(f"{run.label}: gauges")
        fig.savefig(run.dir / "gauges.png")
        plt.close(fig)
    if energy_file.is_file():
        e = read_columns(energy_file)
        unit = "J/m" if run.dimension == 2 else "J"
        fig, ax = plt.subplots(figsize=(8, 4), dpi=150, constrained_layout=True)
        for key, label in (("kinetic", "kinetic"), ("potential", "potential (from t = 0)"),
                           ("mechanical", "kinetic + potential")):
            ax.plot(e["time_s"], e[f"{key}_J{per}"], label=label)
        ax.set_xlabel("t (s)")
        ax.set_ylabel(f"energy ({unit})")
        ax.legend(fontsize=8)
        ax.set_title(f"{run.label}: energy of the soil")
        fig.savefig(run.dir / "energy.png")
        plt.close(fig)


def plot_profiles(runs):
    first = runs[0]
    finals = [run.frame(len(run.names) - 1) for run in runs]
    limits = extent(finals + [first.frame(0)], first.spacing)
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=150)
    prepare_axes(ax, limits, walls(first, finals[0]["time"]))
    initial = first.frame(0)
    x, y = surface_profile(initial, first.spacing)
    ax.plot(x, y, color="0.5", linestyle="--", label="initial column")
    for run, final in zip(runs, finals):
        x, y = surface_profile(final, run.spacing)
        label = f"{run.label}, dx = {run.spacing * 1e3:g} mm (t = {final['time']:.2f} s)"
        line, = ax.plot(x, y, linewidth=1.8, label=label)
        runout = run.summary.get("runout_m")
        if run.complete and isinstance(runout, (int, float)):  # the toe the runout measures
            origin, direction = deposit_frame(run)
            toe = (origin[0] + runout * direction[0]) * CM
            ax.plot([toe], [limits[2]], marker="^", markersize=9, color=line.get_color(), clip_on=False,
                    zorder=4)
    ax.set_title("final surface profiles (▲: toe of the measured runout)")
    ax.legend(loc="upper left")
    fig.savefig(first.dir / "profiles.png", bbox_inches="tight")
    plt.close(fig)


class Axis:
    """The column's axis of a 3D run: a point on the floor, up against gravity, and two horizontal unit
    vectors e1, e2 (the first two world axes not along up) in which azimuth and plan view are drawn."""

    def __init__(self, run):
        inputs = run.summary.get("inputs", {})
        gravity = inputs.get("scene", {}).get("gravity", 9.81)
        g = np.array(gravity, dtype=float) if isinstance(gravity, list) else np.array([0.0, -1.0, 0.0])
        self.up = -g / np.linalg.norm(g)
        self.point = np.array(inputs.get("deposit", {}).get("axis", [0.0, 0.0, 0.0]), dtype=float)
        horizontal = []
        for world in np.eye(3):
            e = world - world.dot(self.up) * self.up
            for f in horizontal:
                e = e - e.dot(f) * f
            if np.linalg.norm(e) > 1e-6 and len(horizontal) < 2:
                horizontal.append(e / np.linalg.norm(e))
        self.e1, self.e2 = horizontal

    def coordinates(self, position):
        """(e1, e2, height) of each particle relative to the axis point."""
        d = position - self.point
        return d @ self.e1, d @ self.e2, d @ self.up


def frame_3d(run, axis, index):
    """Axis coordinates (m) and, where the frame holds them, the speeds (m/s) of frame `index`."""
    group = run.h5[run.names[index]]
    a, b, h = axis.coordinates(group["position"][()])
    frame = {"time": run.times[index], "a": a, "b": b, "h": h, "r": np.hypot(a, b)}
    if "velocity" in group:
        frame["speed"] = np.linalg.norm(group["velocity"][()], axis=1)
    elif "speed" in group:
        frame["speed"] = group["speed"][()]
    return frame


def lube_2004(a):
    """Lube, Huppert, Sparks & Hallworth (2004), J. Fluid Mech. 508: (r_inf - r0)/r0 and H_inf/r0 for
    the aspect ratio a = H0/r0 (sph/analysis/axisymmetric_deposit.h, which says why min())."""
    runout = 1.24 * a if a <= 1.7 else 1.6 * np.sqrt(a)
    return runout, min(a, 0.88 * a ** (1.0 / 6.0))


def radial_profile(frame, spacing):
    """The top particle's height (cm) in each ring of one spacing about the axis, against its radius."""
    ring = np.floor(frame["r"] / spacing).astype(np.int64)
    order = np.lexsort((frame["h"], ring))
    top = order[np.r_[ring[order][1:] != ring[order][:-1], True]]
    # Down to the floor beyond the last ring, so the rim (the initial column's vertical face) shows.
    return np.r_[frame["r"][top], frame["r"][top[-1]]] * CM, np.r_[frame["h"][top], 0.0] * CM


def plot_section(run, axis):
    indices = sorted(set(np.linspace(0, len(run.names) - 1, 4).round().astype(int)))
    frames = [frame_3d(run, axis, i) for i in indices]
    band = [np.abs(f["b"]) <= run.spacing for f in frames]
    a_all = np.concatenate([f["a"][m] for f, m in zip(frames, band)]) * CM
    h_all = np.concatenate([f["h"][m] for f, m in zip(frames, band)]) * CM
    pad = run.spacing * CM
    limits = (GRID_CM * np.floor((a_all.min() - pad) / GRID_CM), GRID_CM * np.ceil((a_all.max() + pad) / GRID_CM),
              min(h_all.min() - 2 * pad, -0.5), GRID_CM * np.ceil((h_all.max() + pad) / GRID_CM))
    coloured = all("speed" in f for f in frames)
    vmax = max(max(float(f["speed"].max()) for f in frames), 1e-12) if coloured else 1.0
    fig, axes = plt.subplots(2, 2, figsize=(13, 7.5), dpi=150, constrained_layout=True)
    for ax, frame, inside in zip(axes.flat, frames, band):
        floor = (np.array([limits[0], limits[1]]), np.array([-0.5 * pad, -0.5 * pad]))
        prepare_axes(ax, limits, [floor])
        ax.set_xlabel("distance along the section from the axis (cm)")
        ax.set_ylabel("height (cm)")
        colour = frame["speed"][inside] if coloured else "#b08850"
        points = ax.scatter(frame["a"][inside] * CM, frame["h"][inside] * CM, c=colour, cmap="turbo", vmin=0.0,
                            vmax=vmax, marker="s", s=marker_area(ax, run.spacing), linewidths=0, zorder=2)
        ax.axvline(0.0, color="0.4", linestyle=":", linewidth=1.0)
        ax.set_title(f"t = {frame['time']:.3f} s")
    for ax in list(axes.flat)[len(frames):]:
        ax.set_visible(False)
    if coloured:
        fig.colorbar(points, ax=axes, shrink=0.8, label="velocity magnitude (m/s)")
    else:
        print(f"plot_collapse: {run.dir / 'frames.h5'} has no velocity or speed field ([output] fields): "
              "section.png drawn without speeds", file=sys.stderr)
    fig.suptitle(f"{run.label}: vertical section through the axis (particles within one spacing of it)")
    fig.savefig(run.dir / "section.png")
    plt.close(fig)


def initial_rim(run, axis):
    """The initial column's radius (m): the farthest particle of the first frame's bottom layer."""
    first = frame_3d(run, axis, 0)
    return float(first["r"][first["h"] <= run.spacing].max(initial=first["r"].max()))


def plot_height_map(run, axis):
    final = frame_3d(run, axis, len(run.names) - 1)
    dx = run.spacing
    i, j = np.floor(final["a"] / dx).astype(np.int64), np.floor(final["b"] / dx).astype(np.int64)
    i0, j0 = i.min(), j.min()
    height = np.full((j.max() - j0 + 1, i.max() - i0 + 1), np.nan)
    np.fmax.at(height, (j - j0, i - i0), final["h"] * CM)
    fig, ax = plt.subplots(figsize=(7.5, 6.5), dpi=150)
    extent = np.array([i0, i.max() + 1, j0, j.max() + 1]) * dx * CM
    image = ax.imshow(height, origin="lower", extent=extent, cmap="viridis", interpolation="nearest", zorder=2)
    fig.colorbar(image, ax=ax, shrink=0.8, label="height of the top particle (cm)")
    theta = np.linspace(0.0, 2.0 * np.pi, 361)
    rim = initial_rim(run, axis) * CM
    ax.plot(rim * np.cos(theta), rim * np.sin(theta), color="black", linestyle="--", linewidth=1.2, zorder=3,
            label="initial column")
    runout = run.summary.get("runout_radius_m")
    if run.complete and isinstance(runout, (int, float)):
        ax.plot(runout * CM * np.cos(theta), runout * CM * np.sin(theta), color="red", linewidth=1.2, zorder=3,
                label=f"runout_radius_m = {runout * CM:.2f} cm")
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.set_xlabel("horizontal (cm), e1")
    ax.set_ylabel("horizontal (cm), e2")
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(f"{run.label}: deposit height at t = {final['time']:.3f} s (plan view)")
    fig.savefig(run.dir / "height_map.png", bbox_inches="tight")
    plt.close(fig)


def plot_radial_profile(runs):
    first = runs[0]
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=150)
    axis = Axis(first)
    r, h = radial_profile(frame_3d(first, axis, 0), first.spacing)
    ax.plot(r, h, color="0.5", linestyle="--", drawstyle="steps-mid", label="initial column")
    for run in runs:
        final = frame_3d(run, Axis(run), len(run.names) - 1)
        r, h = radial_profile(final, run.spacing)
        line, = ax.plot(r, h, drawstyle="steps-mid", linewidth=1.8,
                        label=f"{run.label}, dx = {run.spacing * 1e3:g} mm (t = {final['time']:.2f} s)")
        runout = run.summary.get("runout_radius_m")
        if run.complete and isinstance(runout, (int, float)):
            ax.plot([runout * CM], [0.0], marker="^", markersize=9, color=line.get_color(), clip_on=False, zorder=4)
    scene = first.summary.get("inputs", {}).get("scene", {})
    r0, h0 = scene.get("column_radius"), scene.get("column_height")
    if isinstance(r0, (int, float)) and isinstance(h0, (int, float)) and r0 > 0:
        runout_ratio, height_ratio = lube_2004(h0 / r0)
        ax.axvline((1.0 + runout_ratio) * r0 * CM, color="black", linestyle=":",
                   label=f"Lube et al. 2004: r_inf, H_inf for a = {h0 / r0:.2f}")
        ax.plot([0.0], [height_ratio * r0 * CM], marker="o", color="black", clip_on=False, zorder=4)
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("distance from the axis (cm)")
    ax.set_ylabel("height of the top particle (cm)")
    ax.grid(True, color="0.85", linewidth=0.6)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title("radial profile (▲: runout_radius_m)")
    fig.savefig(first.dir / "radial_profile.png", bbox_inches="tight")
    plt.close(fig)


def plot_3d(run, others, labels):
    """The pictures of a 3D run; `others` (--compare) add their final profiles to radial_profile.png."""
    for r, label in zip([run] + others, labels):
        r.label = label + (" [INCOMPLETE RUN]" if not r.complete else "")
    axis = Axis(run)
    plot_section(run, axis)
    plot_height_map(run, axis)
    plot_radial_profile([run] + others)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir", help="run directory with frames.h5 and summary.json")
    parser.add_argument("--compare", nargs="+", default=[], metavar="DIR2",
                        help="other runs whose final surface profiles are overlaid in DIR/profiles.png")
    parser.add_argument("--colour", choices=("layer", "material"), default="layer",
                        help="deposit.png: colour by horizontal layer (default) or by material")
    parser.add_argument("--labels", nargs="+", default=[], metavar="LABEL",
                        help="names of DIR and each DIR2 in the pictures (default: the model of summary.json)")
    args = parser.parse_args()
    if args.labels and len(args.labels) != 1 + len(args.compare):
        parser.error(f"--labels: {len(args.labels)} labels for {1 + len(args.compare)} runs (DIR and each DIR2)")
    run = Run(args.dir)
    if args.labels:
        run.label = args.labels[0] + (" [INCOMPLETE RUN]" if not run.complete else "")
    if run.dimension == 3:
        plot_3d(run, [Run(d) for d in args.compare], args.labels)
        plot_histories(run)
        written = sorted(p.name for p in run.dir.glob("*.png"))
        print(f"plot_collapse: wrote {', '.join(written) or 'no picture'} in {run.dir}")
        return
    plot_velocity(run)
    plot_deposit(run, args.colour)
    plot_histories(run)
    if args.compare:
        runs = [run] + [Run(d) for d in args.compare]
        for r, label in zip(runs, args.labels):
            r.label = label + (" [INCOMPLETE RUN]" if not r.complete else "")
        plot_profiles(runs)
        plot_compare_velocity(runs)
    written = sorted(p.name for p in run.dir.glob("*.png"))
    print(f"plot_collapse: wrote {', '.join(written) or 'no picture'} in {run.dir}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Writes a synthetic 3D run (frames.h5 with external links to frames/frame_NNNNNN.h5, positions and
velocities N x 3, the six stress components; summary.json with inputs.scene.dimension = 3) of a quarter
column collapsing to a cone, runs scripts/plot_collapse.py on it and checks that it draws the 3D
pictures (section.png, height_map.png, radial_profile.png: PNG, a sensible size, not blank) and none
of the 2D ones. Usage: check_plots_3d.py PLOT_SCRIPT"""
import json
import pathlib
import subprocess
import sys
import tempfile

import h5py
import matplotlib.image as mpimg
import numpy as np

R0, H0, DX = 0.05, 0.05, 0.005  # a = 1, r0/dx = 10


def quarter_column():
    """Lattice nodes (i + 1/2, j + 1/2, k + 1/2) dx of the quarter cylinder x, z > 0 about the y axis."""
    n = int(round(R0 / DX))
    i, j, k = np.meshgrid(*(np.arange(n) + 0.5,) * 3, indexing="ij")
    p = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1) * DX
    return p[np.hypot(p[:, 0], p[:, 2]) <= R0]


def slumped(p, s):
    """The column flattened towards a cone by the share s in [0, 1]: radii stretched, heights squashed,
    volume roughly kept."""
    r = np.hypot(p[:, 0], p[:, 2])
    stretch = 1.0 + 1.2 * s * (1.0 - p[:, 1] / H0)
    q = p.copy()
    q[:, 0] *= stretch
    q[:, 2] *= stretch
    q[:, 1] = DX / 2 + (p[:, 1] - DX / 2) * (1.0 - 0.5 * s * r / R0)
    return q


def write_frame(directory, index, time, position, velocity):
    n = len(position)
    with h5py.File(directory / "frames" / f"frame_{index:06d}.h5", "w") as f:
        f.attrs["time"] = time
        f["position"] = position
        f["velocity"] = velocity
        depth = H0 - position[:, 1]
        for name, value in (("sxx", -0.5), ("syy", -1.0), ("szz", -0.5), ("sxy", 0.0), ("sxz", 0.0), ("syz", 0.0)):
            f[name] = value * 1800.0 * 9.81 * depth  # tension-positive, K0 = 0.5
        f["layer"] = (position[:, 1] / 0.01).astype(np.int32)
        f["material"] = np.zeros(n, dtype=np.int32)


def write_run(directory):
    (directory / "frames").mkdir(parents=True)
    column = quarter_column()
    times = (0.0, 0.1, 0.2, 0.3)
    with h5py.File(directory / "frames.h5", "w") as f:
        f.attrs["conventions"] = "synthetic 3D run (tests/sph_output/check_plots_3d.py)"
        for index, t in enumerate(times):
            s = min(t / 0.2, 1.0)
            position = slumped(column, s)
            velocity = (position - slumped(column, max(s - 0.05, 0.0))) / 0.01 if t < 0.25 else 0 * position
            write_frame(directory, index, t, position, velocity)
            f[f"frame_{index:06d}"] = h5py.ExternalLink(f"frames/frame_{index:06d}.h5", "/")
    final = slumped(column, 1.0)
    summary = {"complete": True, "stop_reason": "at rest", "model": "drucker-prager", "particle_spacing": DX,
               "runout_radius_m": float(np.hypot(final[:, 0], final[:, 2])[final[:, 1] <= DX].max()),
               "runout_radius_spread_m": 0.0, "height_m": float(final[:, 1].max()), "end_time": times[-1],
               "inputs": {"scene": {"dimension": 3, "gravity": 9.81, "column_radius": R0, "column_height": H0,
                                    "particle_spacing": DX}}}
    (directory / "summary.json").write_text(json.dumps(summary, indent=2))


def main():
    script = sys.argv[1]
    with tempfile.TemporaryDirectory(prefix="soilsph_plots_3d_") as tmp:
        run = pathlib.Path(tmp) / "column"
        write_run(run)
        subprocess.run([sys.executable, script, str(run)], check=True)
        failures = []
        for name in ("section.png", "height_map.png", "radial_profile.png"):
            path = run / name
            if not path.exists():
                failures.append(f"{name} was not written")
                continue
            image = mpimg.imread(path)
            if image.shape[0] < 200 or image.shape[1] < 300:
                failures.append(f"{name} is only {image.shape[1]} x {image.shape[0]} pixels")
            if image[..., :3].std() < 0.01:
                failures.append(f"{name} is blank")
        for name in ("velocity.png", "deposit.png", "velocity_t0.05.png"):
            if (run / name).exists():
                failures.append(f"{name} (a 2D picture) was written for a 3D run")
    for failure in failures:
        print("FAIL:", failure)
    print("3D plots ok" if not failures else "3D plots FAILED")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

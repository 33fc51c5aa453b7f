#!/usr/bin/python3
"""`soilsph check` and `soilsph collapse` as a user meets them, each run in its own temporary folder.

- check refuses a bad scene with exit 2 and the very message collapse gives; on a good scene (2D
  and 3D) it prints the particle counts collapse announces and the scene that collapse then writes
  as run;
- collapse without --out writes to results/<the scene file's stem>;
- a scene of regions without [deposit] reports its deposit measures as undefined (null in
  summary.json, a console line asking for [deposit]); the region column with its [deposit] table
  measures them.

Usage: check_collapse_cli.py SOILSPH SOURCE_DIR"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import tomllib

soilsph, source = sys.argv[1], pathlib.Path(sys.argv[2])
scenes = source / "data" / "scenes"
QUICK = ["--set", "scene.particle_spacing=0.004", "--set", "scene.end_time=0.02", "--threads", "1"]
failures = []


def run(args, cwd):
    return subprocess.run([soilsph, *args], capture_output=True, text=True, cwd=cwd)


def expect(condition, message):
    if not condition:
        failures.append(message)


# Refusals: an unknown key, an impossible time step, a run estimated too long, imported particles
# closer than the spacing, a region left empty, a material too soft for its weight; in 3D too.
BAD = [("collapse-dp", ["--set", "scene.column_widht=0.05"]),
       ("collapse-dp", ["--set", "numerics.cfl=5e-324"]),
       ("collapse-dp", ["--set", "scene.floor_length=999.9", "--set", "scene.particle_spacing=0.004",
                        "--set", "scene.max_run_hours=0.002"]),
       ("imported-column", ["--set", "scene.particle_spacing=0.01"]),
       ("slope", ["--set", "scene.particle_spacing=4.0"]),
       ("two-material-column", ["--set", "materials.clay.density=2e303"]),
       # The same refusals in space: memory, run time, time step, a soil too soft for its weight.
       ("axisymmetric-column", ["--set", "scene.particle_spacing=0.0002"]),
       ("axisymmetric-column", ["--set", "scene.max_run_hours=0.0001"]),
       ("slab-3d", ["--set", "numerics.cfl=5e-324"]),
       ("axisymmetric-column", ["--set", "material.young_modulus=1"])]
with tempfile.TemporaryDirectory() as temp:
    temp = pathlib.Path(temp)
    for scene, args in BAD:
        file = str(scenes / f"{scene}.toml")
        checked = run(["check", file, *args], temp)
        collapsed = run(["collapse", file, "--out", str(temp / "refused"), *args], temp)
        label = f"{scene} {' '.join(args)}"
        expect(checked.returncode == 2, f"check {label}: exit {checked.returncode}, not 2")
        expect(collapsed.returncode == 2, f"collapse {label}: exit {collapsed.returncode}, not 2")
        expect(checked.stderr.splitlines()[-1:] and checked.stderr.splitlines()[-1].startswith("error: ")
               and checked.stderr == collapsed.stderr,
               f"{label}: check says {checked.stderr!r}, collapse {collapsed.stderr!r}")
        expect(not (temp / "refused").exists(), f"collapse {label} wrote its folder before refusing")

    def check_agrees(scene, check_args, collapse_args):
        """check's counts and resolved scene are what the collapse then runs; returns its summary."""
        file, out = str(scenes / f"{scene}.toml"), temp / scene
        checked = run(["check", file, *check_args], temp)
        expect(checked.returncode == 0, f"check {scene}: exit {checked.returncode}: {checked.stderr}")
        collapsed = run(["collapse", file, "--out", str(out), *check_args, *collapse_args], temp)
        expect(collapsed.returncode == 0, f"collapse {scene}: exit {collapsed.returncode}: {collapsed.stderr}")
        counts = re.search(r"(\d+) soil (\+|and) (\d+) boundary", collapsed.stdout)
        expect(counts and f"particles: {counts[1]} soil + {counts[3]} boundary" in checked.stdout,
               f"{scene}: check's particle counts differ from collapse's: {checked.stdout[:300]!r}")
        for word in ("memory: about", "MB", "steps", "run time: at most about"):
            expect(word in checked.stdout, f"check {scene} prints no {word!r}")
        resolved = checked.stdout.split("# the scene as it would run, every key resolved\n", 1)
        expect(len(resolved) == 2, f"check {scene} prints no resolved scene")
        if len(resolved) == 2:
            as_run = tomllib.loads((out / "scene.toml").read_text())
            expect(tomllib.loads(resolved[1]) == as_run, f"check's resolved {scene} differs from the collapse's scene.toml")
        return collapsed

    # A good scene of the plane and one of space.
    collapsed = check_agrees("two-material-column", QUICK[:4], QUICK[4:])
    check_agrees("axisymmetric-column", ["--set", "scene.particle_spacing=0.01", "--set", "scene.end_time=0.04"],
                 ["--threads", "1"])
    summary = json.loads((temp / "two-material-column" / "summary.json").read_text())
    expect(all(isinstance(summary[k], (int, float)) for k in ("runout_m", "height_m", "repose_angle_deg")),
           "the region column with [deposit] has no deposit measures")
    expect("runout " in collapsed.stdout, "the region column's console has no runout")

    # A scene of regions without [deposit]: its measures undefined, not taken from a column's frame.
    slope = run(["collapse", str(scenes / "slope.toml"), "--out", str(temp / "slope"), *QUICK], temp)
    expect(slope.returncode == 0, f"collapse slope: exit {slope.returncode}: {slope.stderr}")
    summary = json.loads((temp / "slope" / "summary.json").read_text())
    for key in ("runout_m", "height_m", "repose_angle_deg", "runout_thick_m"):
        expect(key in summary and summary[key] is None, f"slope: summary.json {key} = {summary.get(key)!r}, not null")
    expect("undefined: add a [deposit] table" in slope.stdout and "runout " not in slope.stdout,
           f"slope's console does not say the deposit is undefined: {slope.stdout[-400:]!r}")
    expect("deposit" not in summary["inputs"], "slope: the scene as run has a [deposit] table it was not given")

    # Without --out: results/<stem> of the working folder.
    default = run(["collapse", str(scenes / "collapse-dp.toml"), *QUICK], temp)
    expect(default.returncode == 0, f"collapse without --out: exit {default.returncode}: {default.stderr}")
    expect((temp / "results" / "collapse-dp" / "summary.json").exists(),
           "collapse without --out did not write results/collapse-dp/summary.json")

print("\n".join(failures) or "check and collapse agree")
sys.exit(1 if failures else 0)

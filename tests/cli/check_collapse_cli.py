#!/usr/bin/python3
"""`soilsph check` and `soilsph collapse` as a user meets them, each run in its own temporary folder.

- check refuses a bad scene with exit 2 and the very message collapse gives; on a good scene (2D
  and 3D) it prints the particle counts collapse announces and the scene that collapse then writes
  as run;
- collapse without --out writes to results/<the scene file's stem>;
- a half cylinder of space without a mirror in its cut plane is warned of, with one not;
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
    # At 0.04 s the column (r0 = H0 = 0.1 m, Δp = 1 cm) has barely moved: its top cell reads H0 within
    # half a spacing (its top centre lies half a spacing lower), and the radius where it is H0/10
    # thick lies near r0, inside the runout radius plus a strip.
    column = json.loads((temp / "axisymmetric-column" / "summary.json").read_text())
    thick, runout = column.get("runout_radius_thick_m"), column.get("runout_radius_m")
    expect(isinstance(thick, float) and 0.08 < thick <= runout + 0.01,
           f"axisymmetric-column: runout_radius_thick_m {thick!r} against runout_radius_m {runout!r}")
    expect(abs(column["height_m"] - 0.1) < 0.005, f"axisymmetric-column: height_m {column['height_m']!r}, not H0")
    # The shorthand's own symmetry planes close its quarter's cuts: no warning.
    quarter = run(["check", str(scenes / "axisymmetric-column.toml"), "--set", "scene.particle_spacing=0.01"], temp)
    expect("warning" not in quarter.stderr, f"check axisymmetric-column warns: {quarter.stderr!r}")
    summary = json.loads((temp / "two-material-column" / "summary.json").read_text())
    expect(all(isinstance(summary[k], (int, float)) for k in ("runout_m", "height_m", "repose_angle_deg")),
           "the region column with [deposit] has no deposit measures")
    expect("runout " in collapsed.stdout, "the region column's console has no runout")

    # A half cylinder of space: check warns of its cut plane z = 0 until a symmetry plane closes it
    # (the example of docs/guide/writing-a-scene.md), and exits 0 either way.
    half = """[scene]
dimension = 3
particle_spacing = 0.005
smoothing_ratio = 1.3
end_time = 0.5
[material]
model = "linear-elastic"
density = 2000.0
young_modulus = 5.0e6
poisson_ratio = 0.3
[[regions]]
shape = "cylinder"
base_centre = [0.0, 0.0, 0.0]
radius = 0.05
height = 0.05
part = "half"
"""
    mirror = """[[boundaries]]
shape = "rectangle"
name = "symmetry_xy"
kind = "symmetry"
corner = [-0.3, 0.0, 0.0]
edges = [[0.6, 0.0, 0.0], [0.0, 0.1, 0.0]]
"""
    for name, text, warned in (("open", half, True), ("mirrored", half + mirror, False)):
        file = temp / f"half-cylinder-{name}.toml"
        file.write_text(text)
        checked = run(["check", str(file)], temp)
        expect(checked.returncode == 0, f"check the {name} half cylinder: exit {checked.returncode}: {checked.stderr}")
        warning = f"warning: {file}: [regions #1], a half cylinder, has no symmetry or free-slip wall in its cut plane z = 0 m"
        expect((warning in checked.stderr) == warned,
               f"check the {name} half cylinder: {'no' if warned else 'a'} warning of its cut: {checked.stderr!r}")
        if not warned:
            resolved = tomllib.loads(checked.stdout.split("every key resolved\n", 1)[-1])
            expect(resolved.get("boundaries", [{}])[0].get("kind") == "symmetry",
                   f"the {name} half cylinder's resolved scene lost its kind: {resolved.get('boundaries')!r}")

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

#!/usr/bin/python3
"""What soilsph says to a user who took a wrong turn, each run in its own temporary folder:

- an unknown key gets the nearest known key, when one is close;
- a misplaced option names the help of the command it was given to;
- `point` and `material` on a scene of named materials name them and --material, which tests one;
- `check` warns (exit 0) that a scene of regions without [deposit] will take no deposit measures;
- `examples` shows a description whole even where its first line breaks mid-sentence.

Usage: check_guidance.py SOILSPH SOURCE_DIR"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

soilsph, source = sys.argv[1], pathlib.Path(sys.argv[2])
scenes, materials = source / "data" / "scenes", source / "data" / "materials"
two_materials = str(scenes / "two-material-column.toml")
failures = []


def run(args, cwd, env=None):
    return subprocess.run([soilsph, *args], capture_output=True, text=True, cwd=cwd, env=env)


def expect(condition, message):
    if not condition:
        failures.append(message)


def refused_with(result, text, label):
    last = result.stderr.strip().splitlines()[-1:] or [""]
    expect(result.returncode == 2 and text in last[0], f"{label}: exit {result.returncode}, {result.stderr!r}; expected {text!r}")


with tempfile.TemporaryDirectory() as temp:
    temp = pathlib.Path(temp)
    dp = str(materials / "dp-table1.toml")

    # The nearest known key.
    refused_with(run(["point", dp, "--test", "triaxial-drained", "--set", "material.frictionangle=30"], temp),
                 'frictionangle: is not a known key (did you mean "friction_angle"?)', "point --set frictionangle")
    refused_with(run(["check", str(scenes / "collapse-dp.toml"), "--set", "scene.column_heigth=0.05"], temp),
                 '[scene] column_heigth: is not a known key (did you mean "column_height"?)', "check column_heigth")
    far = run(["check", str(scenes / "collapse-dp.toml"), "--set", "scene.colour=1"], temp)
    refused_with(far, "[scene] colour: is not a known key", "check colour")
    expect("did you mean" not in far.stderr, f"check colour: a far key suggested: {far.stderr!r}")

    # A misplaced option: the help of the command it was given to.
    refused_with(run(["point", dp, "--test", "triaxial-drained", "--confining", "200kPa"], temp),
                 "(soilsph point --help lists its options)", "point --confining")
    refused_with(run(["bench", "point", "--frobnicate"], temp), "(soilsph bench point --help lists its options)",
                 "bench point --frobnicate")
    refused_with(run(["frobnicate"], temp), "(soilsph --help lists the commands and options)", "frobnicate")

    # A scene of named materials: what it holds and how to pick one.
    for command in (["point", two_materials, "--test", "triaxial-drained"], ["material", two_materials]):
        refused_with(run(command, temp), "a scene of named materials (clay, sand): pick one with --material NAME",
                     " ".join(command[:1]))
    clay = temp / "clay.csv"
    tested = run(["point", two_materials, "--material", "clay", "--test", "triaxial-drained", "--increments", "10",
                  "--out", str(clay)], temp)
    expect(tested.returncode == 0 and clay.exists(), f"point --material clay: exit {tested.returncode}: {tested.stderr}")
    if clay.exists():
        header = clay.read_text()
        expect("[materials.clay]" in header and 'model = "modified-cam-clay"' in header,
               "point --material clay: the CSV header does not name [materials.clay] and its model")
    described = run(["material", two_materials, "--material", "sand"], temp)
    expect(described.returncode == 0 and "[materials.sand]: drucker-prager" in described.stdout,
           f"material --material sand: exit {described.returncode}: {described.stdout[:200]!r} {described.stderr!r}")
    refused_with(run(["point", two_materials, "--material", "silt", "--test", "triaxial-drained"], temp),
                 "--material silt: " + two_materials + " has no [materials.silt] table (its named materials: clay, sand)",
                 "point --material silt")
    refused_with(run(["point", two_materials, "--material", "clay", "--test", "triaxial-drained",
                      "--set", "material.friction_angle=30"], temp),
                 "soilsph point reads only the [materials.clay] table", "point --material clay --set material.")
    overridden = run(["point", two_materials, "--material", "clay", "--test", "triaxial-drained", "--increments", "10",
                      "--set", "materials.clay.friction_angle=30"], temp)
    expect(overridden.returncode == 0 and "friction_angle = 30;" in overridden.stdout,
           f"point --material clay --set materials.clay.friction_angle=30: exit {overridden.returncode}: {overridden.stderr}")

    # check: regions without [deposit] warn, with [deposit] do not.
    slope = run(["check", str(scenes / "slope.toml")], temp)
    expect(slope.returncode == 0 and "warning:" in slope.stderr and "no [deposit] table" in slope.stderr,
           f"check slope: exit {slope.returncode}, no warning about [deposit]: {slope.stderr!r}")
    column = run(["check", two_materials], temp)
    expect(column.returncode == 0 and "[deposit]" not in column.stderr,
           f"check two-material-column (with [deposit]): {column.stderr!r}")

    # examples: a first line that breaks mid-sentence is shown with the rest of its sentence.
    data = temp / "share"
    for folder in ("data/scenes", "data/materials", "data/programmes", "data/strain-paths", "verification/cases"):
        (data / folder).mkdir(parents=True)
    shutil.copy(materials / "dp-table1.toml", data / "data" / "materials")
    (data / "data" / "scenes" / "wide.toml").write_text(
        "# A scene whose description goes on\n# over two lines.\n#\n# Not this.\n[scene]\n")
    listed = run(["examples"], temp, env={**os.environ, "SOILSPH_DATA_DIR": str(data)})
    expect("  wide: A scene whose description goes on over two lines.\n" in listed.stdout,
           f"examples: the two-line description is not whole: {listed.stdout!r}")

print("\n".join(failures) or "the guidance is as documented")
sys.exit(1 if failures else 0)

#!/usr/bin/python3
"""`soilsph examples` lists every shipped file, each with its description and a command that runs.

The expected list is the source tree's data/scenes, data/materials, data/programmes (*.toml),
data/strain-paths (*.csv) and verification/cases (*.toml); each file must begin with a description
("# ..."), whose first sentence the listing must show. Every command printed is run in a temporary
folder: each scene through `soilsph check` (the same scene a collapse would start), each point test
and programme with --out, each verification case file with --no-plots.

Usage: check_examples.py SOILSPH SOURCE_DIR"""
import pathlib
import shlex
import subprocess
import sys
import tempfile

soilsph, source = sys.argv[1], pathlib.Path(sys.argv[2])
KINDS = (("data/scenes", ".toml"), ("data/materials", ".toml"), ("data/programmes", ".toml"),
         ("data/strain-paths", ".csv"), ("verification/cases", ".toml"))
shipped = [path for folder, extension in KINDS for path in sorted((source / folder).glob("*" + extension))]

lines = subprocess.run([soilsph, "examples"], capture_output=True, text=True, check=True).stdout.splitlines()
entries = [line for line in lines if line.startswith("  ") and not line.startswith("   ")]
failures = []
if len(entries) != len(shipped):
    failures.append(f"{len(entries)} entries listed for {len(shipped)} shipped files")


def run(words, folder):
    """Runs a listed command (its first word `soilsph` being this executable); returns why it failed."""
    if words[0] != "soilsph":
        return f"does not start with soilsph: {shlex.join(words)}"
    words = [soilsph, *words[1:]]
    if words[1] == "collapse":
        words[1] = "check"
    elif words[1] == "point":
        words += ["--out", str(folder / "point.csv")]
    elif words[1] == "verify":
        words += ["--no-plots", "--out", str(folder / "verification")]
    result = subprocess.run(words, capture_output=True, text=True, cwd=folder)
    return "" if result.returncode == 0 else f"{shlex.join(words)}: exit {result.returncode}: {result.stderr.strip()}"


with tempfile.TemporaryDirectory() as temp:
    for path in shipped:
        first = path.read_text().splitlines()[0]
        if not first.startswith("# ") or len(first) < 12:
            failures.append(f"{path}: its first line is not a one-line description")
            continue
        # The description is the header's first sentence: the first line, continued over the
        # header's next lines where the sentence goes on.
        header = []
        for line in path.read_text().splitlines():
            if not line.startswith("# "):
                break
            header.append(line[2:].strip())
        paragraph = " ".join(header)
        start = f"  {path.stem}: {first[2:]}"
        listed = [k for k, line in enumerate(lines) if line.startswith(start)]
        if not listed:
            failures.append(f"not listed as {start!r}")
            continue
        described = lines[listed[0]][len(f"  {path.stem}: "):]
        if not (paragraph.startswith(described) and described.endswith(".")):
            failures.append(f"{path.name}: listed as {described!r}, not the first sentence of {paragraph!r}")
            continue
        command = lines[listed[0] + 1]
        words = shlex.split(command)
        if not any(word == str(path) or word.endswith(":" + str(path)) for word in words):
            failures.append(f"{path.name}: the command does not name {path}: {command.strip()}")
        elif why := run(words, pathlib.Path(temp)):
            failures.append(why)

print("\n".join(failures) or f"all {len(shipped)} shipped files listed and run")
sys.exit(1 if failures else 0)

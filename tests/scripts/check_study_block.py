#!/usr/bin/python3
"""`sph_study.py resolution --block paper|fixed` at 4 mm for both shipped scenes (ctest
scripts.study_block). Checked against the geometry, not against the code's output: the column keys
put particle centres on the edges of W x H, so the paper's block holds (W/dp + 1)(H/dp + 1) particles
of dp^2 each, and the fixed block W/dp x H/dp, whose cells fill exactly W x H; every face measure is
its summary measure plus dp, and the fixed block's toe thickness is H/10. With --smoothing-length h
each run's smoothing ratio is h/dp (h = 5 mm at 4 and 2.5 mm: 1.25 and 2), and an h outside 1 to 2
spacings is refused before anything runs.

usage: check_study_block.py STUDY_SCRIPT OUT_DIR"""
import csv
import os
import pathlib
import subprocess
import sys
import tomllib

script, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
root = script.resolve().parent.parent
dp = 0.004
for block in ("paper", "fixed"):
    folder = out / block
    subprocess.run(["/usr/bin/python3", str(script), "resolution", "--block", block, "--spacings", "4",
                    "--out", str(folder)], check=True, env=os.environ, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(line for line in open(folder / "resolution.csv") if not line.startswith("#")))
    assert len(rows) == 2, rows
    for r in rows:
        scene_name = r["run"].rsplit("-", 1)[0]  # collapse-dp-4mm -> collapse-dp
        scene = tomllib.loads((root / "data" / "scenes" / f"{scene_name}.toml").read_text())["scene"]
        W, H = scene["column_width"], scene["column_height"]
        nx, ny = round(W / dp), round(H / dp)
        expected = (nx + 1) * (ny + 1) if block == "paper" else nx * ny
        assert r["status"] == "ok" and r["block"] == block, r
        assert int(r["particles"]) == expected, (block, r["particles"], expected)
        if block == "fixed":
            assert abs(int(r["particles"]) * dp * dp - W * H) < 1e-12, "the fixed block's cells fill W x H"
            assert "'toe_thickness': %r" % (0.1 * H) in r["inputs"], r["inputs"]
        for key in ("runout_m", "runout_thick_m", "height_m"):
            face = float(r[key.replace("_m", "_face_m")])
            assert abs(face - (float(r[key]) + dp)) < 1e-12, (key, face, r[key])
    print(block, "ok:", [(r["model"], r["particles"]) for r in rows])

folder = out / "fixed-h"
subprocess.run(["/usr/bin/python3", str(script), "resolution", "--smoothing-length", "5", "--spacings", "4,2.5",
                "--out", str(folder)], check=True, env=os.environ, stdout=subprocess.DEVNULL)
rows = list(csv.DictReader(line for line in open(folder / "resolution.csv") if not line.startswith("#")))
assert len(rows) == 4 and all(r["status"] == "ok" for r in rows), rows
for r in rows:
    dp_r = float(r["particle_spacing"])
    assert abs(float(r["smoothing_ratio"]) - 0.005 / dp_r) < 1e-12, (r["run"], r["smoothing_ratio"])
    assert float(r["smoothing_length_mm"]) == 5.0, r["smoothing_length_mm"]
assert sorted({round(float(r["smoothing_ratio"]), 12) for r in rows}) == [1.25, 2.0]
refused = subprocess.run(["/usr/bin/python3", str(script), "resolution", "--smoothing-length", "10", "--spacings", "4",
                          "--out", str(out / "fixed-h-refused")], env=os.environ, capture_output=True, text=True)
assert refused.returncode != 0 and "h/dp = 2.5" in refused.stderr, (refused.returncode, refused.stderr)
assert not (out / "fixed-h-refused" / "runs").exists(), "nothing runs when h/dp is out of range"
print("fixed h ok:", [(r["run"], r["smoothing_ratio"]) for r in rows])

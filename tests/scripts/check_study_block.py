#!/usr/bin/python3
"""`sph_study.py resolution --block paper|fixed` at 4 mm for both shipped scenes (ctest
scripts.study_block). Checked against the geometry, not against the code's output: the column keys
put particle centres on the edges of W x H, so the paper's block holds (W/dp + 1)(H/dp + 1) particles
of dp^2 each, and the fixed block W/dp x H/dp, whose cells fill exactly W x H; every face measure is
its summary measure plus dp, and the fixed block's toe thickness is H/10.

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

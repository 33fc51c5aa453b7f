#!/usr/bin/python3
"""scripts/equal_error.py on a made-up work-precision CSV whose fronts are known: implicit at
(1e-3, 1 s) and (1e-4, 2 s); substep at (1e-3, 1.5 s) and (1e-4, 5 s), with a dominated substep row
(5e-4, 6 s) that must not count, and rows of other integrators and paths that must be ignored.
Expected cells by hand: at 1e-3 both metrics 1.5/1; at 3e-4 the grid takes the 1e-4 rows (5/2) and
the interpolation w = ln 0.3 / ln 0.1 gives 1.5^(1-w) 5^w / 2^w; at 1e-4 5/2; at 3e-5 nothing.

usage: check_equal_error.py SCRIPT WORKDIR
"""
import math
import os
import subprocess
import sys

script, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
rows = [("implicit(0.01)", 1e-3, 1.0), ("implicit", 1e-4, 2.0), ("substep(0.01)", 1e-3, 1.5),
        ("substep(0.001)", 1e-4, 5.0), ("substep(0.002)", 5e-4, 6.0), ("explicit", 1e-5, 0.1)]
with open(f"{work}/work_precision.csv", "w") as f:
    f.write("# made up\nmaterial,path,integrator,increments,error_q,error_p,cpu_seconds,repeats\n")
    for name, error, seconds in rows:
        f.write(f"clay,triaxial-undrained,{name},10,{error},{error / 2},{seconds},3\n")
    f.write("clay,oedometer,implicit,10,1e-3,1e-3,9.0,3\n")
out = subprocess.run(["/usr/bin/python3", script, work, work], check=True, capture_output=True, text=True).stdout
cells = {}
for line in out.splitlines():
    parts = [p.strip() for p in line.strip("|").split("|")]
    if len(parts) == 7 and parts[0] == "clay":
        cells[(parts[1], parts[2])] = parts[3:]
w = math.log(0.3) / math.log(0.1)
interpolated = 1.5 ** (1 - w) * 5.0 ** w / 2.0 ** w
expected = {("triaxial-undrained", "interpolated"): ["1.50", f"{interpolated:.2f}", "2.50", "-"],
            ("triaxial-undrained", "grid"): ["1.50", "2.50", "2.50", "-"],
            ("oedometer", "interpolated"): ["-"] * 4, ("oedometer", "grid"): ["-"] * 4}
if cells != expected:
    sys.exit(f"equal_error.py printed\n{out}\nexpected cells {expected}")
print("ok:", cells)

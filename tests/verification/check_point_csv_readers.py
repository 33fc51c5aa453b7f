"""Runs the documented one-line readers of a `soilsph point` CSV (numpy or pandas) on a real CSV.

Usage: check_point_csv_readers.py DOC.md CURVE.csv numpy|pandas
DOC.md is docs/reference/output-formats.md, which shows the readers.
The CSV is a drained triaxial test to eps_a = 0.02 in 4 increments from p_initial = 100 kPa, so the
imposed facts are known without the code: eps_a = 0, 0.005, ..., 0.02 and sig_r = 100 kPa in every row.
"""
import sys

doc, csv, library = sys.argv[1:4]
prefix = {"numpy": "data = np.genfromtxt(", "pandas": "data = pd.read_csv("}[library]
lines = [line.strip() for line in open(doc) if line.strip().startswith(prefix)]
if len(lines) != 1:
    sys.exit(f"{doc} should hold one line starting with {prefix!r}, found {len(lines)}")
import numpy as np  # noqa: E402  (the documented lines use these names)
if library == "pandas":
    import pandas as pd  # noqa: F401,E402
scope = {"np": np, "pd": pd if library == "pandas" else None}
exec(lines[0].replace('"curve.csv"', repr(csv)), scope)
data = scope["data"]

columns = ["eps_a", "eps_r", "eps_v", "eps_q", "sig_a", "sig_r", "p", "q", "p_c", "u", "tau_xy", "gamma_xy"]
names = list(data.dtype.names) if library == "numpy" else list(data.columns)
assert names == columns, names
eps_a = np.asarray(data["eps_a"], dtype=float)
assert eps_a.shape == (5,), eps_a.shape
assert np.allclose(eps_a, [0.0, 0.005, 0.01, 0.015, 0.02], rtol=0, atol=1e-15), eps_a
assert np.allclose(np.asarray(data["sig_r"], dtype=float), 100e3, rtol=1e-9), data["sig_r"]
print(f"{library}: documented line reads {len(eps_a)} rows of {len(names)} columns")

#!/usr/bin/python3
"""Check a calibration of the worked example against the truth its readings were made with.

    check_example_fit.py MAKE_MEASURED.py FIT.json

The true parameters are make_measured.py's TRUE table; each must lie inside the fit's 95 % interval,
the fit must have converged, and no parameter may sit on a bound. Exit status 1 with one line per
failure otherwise.
"""
import ast
import json
import sys
from pathlib import Path


def true_parameters(script):
    """The TRUE = {...} assignment of make_measured.py, read without running the script."""
    for node in ast.parse(Path(script).read_text()).body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "TRUE" for t in node.targets):
            return ast.literal_eval(node.value)
    raise SystemExit(f"error: {script}: no TRUE table")


def main(script, fit_path):
    truth = true_parameters(script)
    fit = json.loads(Path(fit_path).read_text())
    failures = [] if fit["converged"] else [f"not converged: {fit['stop']}"]
    for p in fit["parameters"]:
        low, high = p["interval_95"]
        if not low <= truth[p["key"]] <= high:
            failures.append(f"{p['key']}: true {truth[p['key']]} outside the 95 % interval [{low}, {high}]")
        if p["on_bound"]:
            failures.append(f"{p['key']} sits on a bound")
    for failure in failures:
        print(f"error: {fit_path}: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))

#!/usr/bin/python3
"""Deposit and rest time of SPHinXsys's test_3d_repose_angle from its particle files.

Reads the GranularBody_*.vtp files SPHinXsys writes (ASCII: Position, Velocity, TimeValue) and
measures, on particle centres, what soilsph measures on its own axisymmetric column
(sph/analysis/axisymmetric_deposit.h and the rest criterion of docs/reference/scenes.md):

- runout radius: 36 azimuth sectors of 10 deg; per sector the farthest particle of the bottom layer
  (height <= dp) that is linked to the body (gaps <= 2 dp from the next one inwards); mean over
  sectors and the spread (largest - smallest). Also the farthest particle at all (tip).
- height on the axis: particles within 2 dp of the axis sorted by height, from the lowest (within
  2 dp of the floor) up to the first gap > 2 dp.
- repose angle: top particle of each radial strip of width dp (all azimuths pooled), least-squares
  slope of those between 10 % and 90 % of the axis height, from the toe to the crest (the 2D
  measure of sph/analysis/deposit.h applied to the radial profile).
- rest: the first output time from which, for rest_duration = sqrt(H0/g), at least 99 % of the
  particles move slower than rest_speed = 0.01 sqrt(2 g H0) (soilsph's defaults).

Usage: extract.py OUTPUT_DIR DP > deposit.json
"""
import glob
import json
import math
import re
import sys

import numpy as np

R0 = H0 = 0.1
G = 9.8  # SPHinXsys's gravity_g
DL = 2 * R0 * (1 + 1.24 * H0 / R0) + 0.1  # tank length, the column's axis at (DL/2, DW/2), DW = DL
AXIS = np.array([DL / 2, 0.0, DL / 2])


def read_vtp(path):
    text = open(path).read()
    time = float(re.search(r'Name="TimeValue"[^>]*>\s*([-0-9.eE+]+)', text).group(1))

    def array(name):
        m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        return np.array(m.group(1).split(), dtype=float).reshape(-1, 3)

    return time, array("Position"), array("Velocity")


def last_linked(sorted_values, gap):
    k = 0
    while k + 1 < len(sorted_values) and abs(sorted_values[k + 1] - sorted_values[k]) <= gap:
        k += 1
    return sorted_values[k]


def deposit(pos, dp, sectors=36):
    d = pos - AXIS
    height = d[:, 1]
    radius = np.hypot(d[:, 0], d[:, 2])
    azimuth = np.mod(np.arctan2(d[:, 2], d[:, 0]), 2 * math.pi)
    link = 2.0 * dp
    sector_runout = []
    bottom = height <= dp
    for s in range(sectors):
        lo, hi = 2 * math.pi * s / sectors, 2 * math.pi * (s + 1) / sectors
        r = np.sort(radius[bottom & (azimuth >= lo) & (azimuth < hi)])[::-1]
        k = 0
        while k + 1 < len(r) and r[k] - r[k + 1] > link:
            k += 1
        sector_runout.append(float(r[k]) if len(r) else 0.0)
    axis_h = np.sort(height[radius <= 2 * dp])
    h_axis = 0.0 if len(axis_h) == 0 or axis_h[0] > link else float(last_linked(list(axis_h), link))
    # radial profile: top particle per strip of width dp
    strips = np.floor(radius / dp).astype(int)
    tops = {}
    for s, r, h in zip(strips, radius, height):
        if s not in tops or h > tops[s][1]:
            tops[s] = (r, h)
    profile = sorted(tops.values())
    crest = next(r for r, h in profile if h >= 0.9 * h_axis)
    pts = [(r, h) for r, h in profile if r >= crest and 0.1 * h_axis < h <= 0.9 * h_axis]
    if len(pts) >= 2:
        slope = np.polyfit([p[0] for p in pts], [p[1] for p in pts], 1)[0]
        angle = math.degrees(math.atan(-slope))
    else:
        angle = 90.0
    return {
        "runout_radius_m": float(np.mean(sector_runout)),
        "runout_radius_spread_m": float(max(sector_runout) - min(sector_runout)),
        "runout_radius_tip_m": float(radius.max()),
        "sector_runout_m": sector_runout,
        "height_on_axis_m": h_axis,
        "highest_particle_m": float(height.max()),
        "repose_angle_deg": angle,
        "repose_angle_points": len(pts),
        "surface_profile_r_h_m": [[float(r), float(h)] for r, h in profile],
    }


def main():
    out, dp = sys.argv[1], float(sys.argv[2])
    frames = sorted((read_vtp(f) for f in glob.glob(out + "/GranularBody_*.vtp")), key=lambda f: f[0])
    rest_speed, rest_duration = 0.01 * math.sqrt(2 * G * H0), math.sqrt(H0 / G)
    history = []
    for t, pos, vel in frames:
        speed = np.linalg.norm(vel, axis=1)
        history.append((t, float(np.mean(speed < rest_speed)), float(speed.max())))
    rest_time = None
    for i, (t, _, _) in enumerate(history):
        window = [f for f in history[i:] if f[0] <= t + rest_duration + 1e-9]
        if history[-1][0] >= t + rest_duration - 1e-9 and all(f[1] >= 0.99 for f in window):
            rest_time = t
            break
    t_end, pos, vel = frames[-1]
    result = {
        "particle_spacing_m": dp,
        "soil_particles": int(len(pos)),
        "end_time_s": t_end,
        "rest_speed_m_per_s": rest_speed,
        "rest_duration_s": rest_duration,
        "time_to_rest_s": rest_time,
        "max_speed_at_end_m_per_s": history[-1][2],
        "fraction_at_rest_at_end": history[-1][1],
        "frames": [{"time_s": t, "fraction_below_rest_speed": f, "max_speed_m_per_s": v} for t, f, v in history],
    }
    result.update(deposit(pos, dp))
    json.dump(result, sys.stdout, indent=1)


if __name__ == "__main__":
    main()

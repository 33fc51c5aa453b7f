#!/usr/bin/python3
"""Limit-equilibrium factor of safety of a slope by Bishop's simplified method over circular slip
surfaces (Bishop 1955, "The use of the slip circle in the stability analysis of slopes",
Geotechnique 5(1) 7-17), independent of soilsph: numpy and the scene's TOML only.

    /usr/bin/python3 scripts/slope_bishop.py SCENE.toml [--set cohesion=C] [--set friction_angle=PHI]
    /usr/bin/python3 scripts/slope_bishop.py --check

SCENE.toml: a soilsph scene whose [[regions]] are polygons or boxes of one Mohr-Coulomb-matched
material ([material] or one [materials.NAME] with density, cohesion, friction_angle) on a rigid base
at the lowest point of the soil, gravity along -y. The ground surface is the top of the regions on
each vertical (as soilsph's "local-surface" initial stress). The slope must face -x (toe on the left,
crest on the right), as data/scenes/slope.toml: the sliding mass moves towards -x.

Bishop's simplified method (moment equilibrium about the circle's centre, inter-slice shear
neglected), for n vertical slices of width b, weight W, base inclination alpha:

    F = sum[(c b + W tan(phi)) / m_alpha] / sum[W sin(alpha)],  m_alpha = cos(alpha) + sin(alpha) tan(phi) / F

solved by fixed-point iteration from Fellenius' value. No pore pressure. A circle is admissible if
it cuts the ground in one arc, stays above the rigid base (touching it at most), ends inside the
soil's extent, and every slice with a base dipping towards the toe (alpha < 0) has m_alpha > 0.2
(Whitman & Bailey 1967: below it the method's normal forces there are unreliable). The critical
circle: a grid of centres (14 x 14) and radii (14 per centre), then a compass search from the best
three (steps along x, y, r and along y and r together, which keeps a circle on the rigid base).

--check (each within 1.5 %, exit status 1 otherwise):
  - Taylor's (1937, "Stability of earth slopes", J. Boston Soc. Civ. Eng. 24, 197-246; Taylor 1948,
    Fundamentals of Soil Mechanics, Fig. 16.37) stability number N = c/(gamma H F) = 0.191 for
    phi = 0 and beta = 60 deg, a toe circle (critical for beta >= 53 deg): its lowest point lies at
    the toe's level, so a rigid base there (as under the shipped slope) does not change it. For
    phi = 0 Bishop's method is exact moment equilibrium of the circle. (Taylor's steeper values, 0.219
    at 75 deg and 0.261 at 90 deg, come from toe circles that dip below the toe in front of it,
    which a rigid base at the toe forbids: this script gives 0.2135 at 75 deg with the base there.)
  - one circle in closed form: the vertical cut's quarter circle through the toe, centre at the
    crest's height above the toe, phi = 0: F = 3 pi c / (2 gamma H) (the slice integration);
  - c = 0, phi = 30 deg, a 2:1 slope: the critical circle shrinks to a shallow slide along the face
    and F tends to the infinite slope's tan(phi)/tan(beta) = 1.1547 (the phi terms and m_alpha).
"""
import argparse
import math
import pathlib
import sys
import tomllib

import numpy as np


class Ground:
    """The top of the soil on each vertical: the highest crossing of the regions' outlines."""

    def __init__(self, outlines, base):
        self.edges = [(np.asarray(o[k], float), np.asarray(o[(k + 1) % len(o)], float))
                      for o in outlines for k in range(len(o))]
        xs = [p[0] for o in outlines for p in o]
        self.x_min, self.x_max = min(xs), max(xs)
        self.base = base

    def __call__(self, x):
        x = np.asarray(x, float)
        top = np.full(x.shape, -np.inf)
        for a, b in self.edges:
            if a[0] == b[0]:
                top = np.where(x == a[0], np.maximum(top, max(a[1], b[1])), top)
                continue
            t = (x - a[0]) / (b[0] - a[0])
            inside = (t >= 0.0) & (t <= 1.0)
            top = np.where(inside, np.maximum(top, a[1] + t * (b[1] - a[1])), top)
        return np.where(np.isfinite(top), top, self.base)  # no soil: the rigid base


def factor_of_safety(ground, xc, yc, r, c, phi_deg, gamma, slices=80):
    """Bishop's F of the circle (xc, yc, r), or None if the circle is not admissible."""
    if r <= 0.0 or yc - r < ground.base - 1e-12 * r:
        return None
    lo, hi = max(xc - r, ground.x_min), min(xc + r, ground.x_max)
    if hi <= lo:
        return None
    arc = lambda x: yc - np.sqrt(np.maximum(r * r - (x - xc) ** 2, 0.0))
    xs = np.linspace(lo, hi, 241)
    below = arc(xs) < ground(xs)
    if not below.any():
        return None
    first, last = np.argmax(below), len(below) - 1 - np.argmax(below[::-1])
    if not below[first:last + 1].all() or first == 0 or last == len(xs) - 1:
        return None  # two arcs, or the mass runs past the soil's extent (into a wall)

    def crossing(x_out, x_in):
        for _ in range(40):
            m = 0.5 * (x_out + x_in)
            (x_in, x_out) = (m, x_out) if arc(m) < ground(m) else (x_in, m)
        return 0.5 * (x_out + x_in)

    x1, x2 = crossing(xs[first - 1], xs[first]), crossing(xs[last + 1], xs[last])
    b = (x2 - x1) / slices
    xm = x1 + b * (np.arange(slices) + 0.5)
    h = np.maximum(ground(xm) - arc(xm), 0.0)
    w = gamma * b * h
    sin_a = (xm - xc) / r
    cos_a = np.sqrt(1.0 - sin_a ** 2)
    # The base length of each slice along the arc, exact (b / cos(alpha) at the midpoint diverges
    # where the arc leaves the ground steeply); Bishop's c b becomes c l cos(alpha).
    edges = np.clip((x1 + b * np.arange(slices + 1) - xc) / r, -1.0, 1.0)
    length = r * np.diff(np.arcsin(edges))
    driving = np.sum(w * sin_a)
    if driving <= 0.0:
        return None
    tan_phi = math.tan(math.radians(phi_deg))
    f = np.sum(c * length + w * cos_a * tan_phi) / driving  # Fellenius
    for _ in range(200):
        m_alpha = cos_a + sin_a * tan_phi / f
        if np.any((m_alpha <= 0.2) & (sin_a < 0.0)):
            return None
        f_new = np.sum((c * length * cos_a + w * tan_phi) / m_alpha) / driving
        if abs(f_new - f) < 1e-10 * f:
            return f_new, (x1, float(ground(np.array([x1]))[0])), (x2, float(ground(np.array([x2]))[0]))
        f = f_new
    return None


def critical_circle(ground, c, phi_deg, gamma, box):
    """Smallest F over circles with centres in box = (x_lo, x_hi, y_lo, y_hi)."""
    x_lo, x_hi, y_lo, y_hi = box
    found = []
    for xc in np.linspace(x_lo, x_hi, 14):
        for yc in np.linspace(y_lo, y_hi, 14):
            for r in np.linspace(0.05, 1.0, 14) * (yc - ground.base):
                res = factor_of_safety(ground, xc, yc, r, c, phi_deg, gamma)
                if res:
                    found.append((res[0], xc, yc, r))
    if not found:
        sys.exit("slope_bishop: no admissible circle in the search box")
    found.sort()
    best = None
    for f, xc, yc, r in found[:3]:
        step = 0.05 * max(x_hi - x_lo, y_hi - y_lo)
        point = np.array([xc, yc, r])
        while step > 1e-6 * (y_hi - ground.base):
            moved = False
            # the axes, and the centre moving with a fixed lowest point (along the rigid base)
            for d in np.vstack([np.eye(3), -np.eye(3), [[0, 1, 1], [0, -1, -1]]]):
                trial = point + step * d
                res = factor_of_safety(ground, *trial, c, phi_deg, gamma)
                if res and res[0] < f:
                    f, point, moved = res[0], trial, True
            if not moved:
                step *= 0.5
        if best is None or f < best[0]:
            best = (f, *point)
    f, xc, yc, r = best
    _, entry, exit_ = factor_of_safety(ground, xc, yc, r, c, phi_deg, gamma)
    return {"F": f, "centre": (xc, yc), "radius": r, "toe_side": entry, "crest_side": exit_}


def read_scene(path, overrides):
    scene = tomllib.loads(pathlib.Path(path).read_text())
    materials = scene.get("materials")
    material = dict(scene["material"] if "material" in scene else next(iter(materials.values())))
    for o in overrides:
        key, value = o.split("=", 1)
        material[key.strip()] = float(value)
    outlines = []
    for region in scene["regions"]:
        if region["shape"] == "box":
            (x0, y0), (x1, y1) = region["min"], region["max"]
            outlines.append([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
        else:
            outlines.append([tuple(p) for p in region["points"]])
    g = scene["scene"]["gravity"]
    g = -g[1] if isinstance(g, list) else g
    if isinstance(scene["scene"]["gravity"], list) and scene["scene"]["gravity"][0] != 0.0:
        sys.exit("slope_bishop: gravity must be along -y")
    base = min(p[1] for o in outlines for p in o)
    return Ground(outlines, base), material["cohesion"], material["friction_angle"], material["density"] * g


def check():
    """Published and closed-form values against this script's critical circle (module docstring)."""
    H, gamma, c = 1.0, 1.0, 1.0
    results = []
    # Taylor, phi = 0, beta = 60 deg, rigid base at the toe (D = 1): the toe circle, N = 0.191.
    crest = H / math.tan(math.radians(60.0))
    ground = Ground([[(0.0, 0.0), (6.0, 0.0), (6.0, H), (crest, H)]], 0.0)
    res = critical_circle(ground, c, 0.0, gamma, (-0.5, 1.5, 0.5, 2.5))
    results.append(("Taylor phi = 0, beta = 60 deg: N = c/(gamma H F)", c / (gamma * H * res["F"]), 0.191, res))
    # One circle in closed form: the vertical cut's quarter circle, centre (0, H), R = H, phi = 0:
    # F = c (pi R / 2) R / (gamma R^3 / 3) = 3 pi c / (2 gamma H).
    cut = Ground([[(0.0, 0.0), (6.0, 0.0), (6.0, H), (1e-12, H)]], 0.0)
    f = factor_of_safety(cut, 0.0, H, H, c, 0.0, gamma)[0]
    results.append(("quarter circle, phi = 0: F", f, 1.5 * math.pi * c / (gamma * H), None))
    # c = 0, 2:1 slope, phi = 30 deg: the critical circles shrink to shallow slides along the face,
    # the infinite slope's F = tan(phi) / tan(beta) = 1.1547 (from above).
    slope = Ground([[(0.0, 0.0), (6.0, 0.0), (6.0, H), (2.0 * H, H)]], 0.0)
    res = critical_circle(slope, 0.0, 30.0, gamma, (-0.5, 2.5, 0.5, 4.0))
    results.append(("c = 0, phi = 30 deg, 2:1: F", res["F"], math.tan(math.radians(30.0)) / 0.5, res))
    ok = True
    for name, value, expected, res in results:
        good = abs(value / expected - 1.0) < 0.015
        ok = ok and good
        where = "" if res is None else (f"; circle centre ({res['centre'][0]:.3f}, {res['centre'][1]:.3f}) H, "
                                        f"R = {res['radius']:.3f} H, ends at x = {res['toe_side'][0]:.3f} and "
                                        f"{res['crest_side'][0]:.3f} H")
        print(f"{name} = {value:.4f}, expected {expected:.4f} ({100 * (value / expected - 1):+.2f} %){where}: "
              f"{'ok' if good else 'FAIL'}")
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", nargs="?")
    parser.add_argument("--set", action="append", default=[], help="material key=value (cohesion, friction_angle)")
    parser.add_argument("--check", action="store_true", help="Taylor's phi = 0 values")
    args = parser.parse_args()
    if args.check:
        sys.exit(0 if check() else 1)
    if not args.scene:
        parser.error("a scene or --check")
    ground, c, phi, gamma = read_scene(args.scene, args.set)
    xs = np.linspace(ground.x_min, ground.x_max, 2001)
    top = float(ground(xs).max())
    height = top - ground.base
    res = critical_circle(ground, c, phi, gamma,
                          (ground.x_min - height, ground.x_max, ground.base + 0.5 * height, top + 3.0 * height))
    print(f"c = {c:g} Pa, phi = {phi:g} deg, gamma = {gamma:g} N/m^3, H = {height:g} m")
    print(f"FoS_Bishop = {res['F']:.4f}")
    print(f"critical circle: centre ({res['centre'][0]:.5f}, {res['centre'][1]:.5f}) m, radius {res['radius']:.5f} m; "
          f"meets the ground at x = {res['toe_side'][0]:.5f} and {res['crest_side'][0]:.5f} m")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The deposit of a column collapse run to rest against bands derived from references, not from runs.

  check_deposit_band.py OUT_DIR [--peer-runout-ratio R] [--like OTHER_OUT_DIR]
      (OUT_DIR holds the run's scene.toml, as run, and summary.json)

The soil's plane-strain friction angle phi_ps (the angle of the Mohr-Coulomb line it fails on in plane
strain, from its model's parameters):
  - Mohr-Coulomb: phi itself (its yield function does not involve the intermediate stress);
  - Drucker-Prager matched to plane strain (eq 19), alpha_phi, alpha_psi: with the plastic strain out
    of the plane zero, s_2 = -2 alpha_psi sqrt(J2), and sqrt(J2) + alpha_phi I1 = 0 on the yield surface
    gives sin(phi_ps) = 3 alpha_phi sqrt(1 - 3 alpha_psi^2) / (1 - 3 alpha_phi alpha_psi) (= sin(phi)
    when alpha_psi = alpha_phi, associated flow; 33.0 deg for phi = 35 deg, psi = 0);
  - Modified Cam-Clay at the critical state q = M p with no plastic volume change, s_2 = 0 in plane
    strain: q = sqrt(3) (sigma_1 - sigma_3)/2 and p = (sigma_1 + sigma_3)/2, so sin(phi_ps) = M/sqrt(3)
    (55.0 deg for M = 1.418): a weak bound, MCC's critical state line is steep in plane strain.
With several materials the largest phi_ps is taken (every bound below then holds for each).

Bands (A = N dp^2 the soil's area from its particle count, H0 the column's initial height as a
continuum, L0 = A/H0, a = H0/L0; measures on particle centres as sph/analysis/deposit.h defines them,
dp the spacing; a centre lies within a spacing of the continuum's edge, the margin of each band):
  1. at rest: the run stopped at rest (sph/rest.h).
  2. repose angle <= phi_ps + the discretisation margin: a cohesionless slope steeper than phi_ps is not
     in limit equilibrium (the infinite slope, Taylor 1948, ch. 16); the fitted slope may be off by
     dp / l (two surface points each off by dp/2, l = 0.8 H_inf / tan(phi_ps) the fit's horizontal
     extent at the steepest admissible slope).
  3. runout >= L_min - dp (lower bound, statics): of all deposits of area A with no slope steeper than
     phi_ps and not higher than H0, the one leaning on the fixed wall at phi_ps spreads least:
     L_min = sqrt(2 A / tan(phi_ps)) (a triangle) when that is not higher than H0, otherwise
     A/H0 + H0/(2 tan(phi_ps)) (a trapezoid); a particle centre lies half a spacing inside each edge.
  4. runout <= L0 (1 + 1.8 a) x 1.12 + dp (upper bound, scaling laws): the most mobile of the
     laboratory laws for plane collapses, Lajeunesse, Monnier & Chambon (2005, Phys. Fluids 17,
     103302; glass beads, phi ~ 22 deg, less frictional than any soil here), with the +-12 % by which
     the experimental groups differ (Lube et al. 2005, Phys. Rev. E 72, 041301: (L - L0)/L0 = 1.2 a).
  5. height <= min(H0, sqrt(2 A tan(phi_ps))) + dp: no deposit at rest rises above the column, nor
     above the highest triangle of area A at slopes <= phi_ps.
  6. height >= A / (upper runout + dp) - dp: the area A must fit under the deposit's height over its
     length.
  7. height >= H0 - 3 dp / 2 when a < 1.15 (a low column): its back keeps its height (Lube et al. 2005:
     plane columns below a = 1.15 collapse only at their front, the failure wedge behind the released
     face sliding off while the top behind it stays at H0). The height is measured from the lowest
     centres, half a spacing above the floor, and the top centres lie within a spacing below the
     continuum's top. A column with a >= 1.15 gets no such band.
With --peer-runout-ratio R, another code's (L - L0)/L0 for this scene at its own resolution, the run
has a thin toe (one or two particles, which the laboratory laws do not measure: they see the front of
the deposit), and band 4 bounds the runout where the deposit is H0/10 thick (runout_thick_m) instead of
the toe's; the toe's runout must then be <= L0 (1 + 1.1 R) + dp (our goal: within 10 % of the peer).
With --like OTHER_OUT_DIR, a run of the same soil, lattice and walls given another way (the imported
column and the column keys' column): runout and height within dp of it and the angle within the fit's
margin (atan(dp / l) above).
Exits 1 with every violated band named.
"""
import argparse
import csv
import json
import math
import sys
import tomllib
from pathlib import Path


def alpha(angle_deg: float) -> float:
    t = math.tan(math.radians(angle_deg))
    return t / math.sqrt(9.0 + 12.0 * t * t)  # eq 19


def plane_strain_friction(material: dict) -> float:
    """phi_ps in degrees of one [material] table (see the module docstring)."""
    model, phi = material["model"], material["friction_angle"]
    if model == "mohr-coulomb":
        return phi
    if model == "drucker-prager":
        if material.get("plastic_potential", "matched") != "matched":
            raise SystemExit("error: check_deposit_band.py knows the matched D-P potential only")
        a_phi, a_psi = alpha(phi), alpha(material.get("dilatancy_angle", 0.0))
        s = 3.0 * a_phi * math.sqrt(1.0 - 3.0 * a_psi * a_psi) / (1.0 - 3.0 * a_phi * a_psi)
        return math.degrees(math.asin(s))
    if model == "modified-cam-clay":
        sin_phi = math.sin(math.radians(phi))
        M = 6.0 * sin_phi / (3.0 - sin_phi)  # eq 26
        return math.degrees(math.asin(min(1.0, M / math.sqrt(3.0))))
    raise SystemExit(f"error: check_deposit_band.py: no plane-strain friction for model {model!r}")


def initial_height(scene: dict) -> float:
    """The column's height as a continuum: column keys put particle centres on [0, H], so their cells
    reach half a spacing below and above; box regions fill their box; imported particles' cells reach
    half a spacing beyond the lowest and highest centre (the scene as run names the file by its full
    path)."""
    s = scene["scene"]
    if "column_height" in s:
        return s["column_height"] + s["particle_spacing"]
    regions = scene.get("regions", [])
    tops = [r["max"][1] for r in regions if r.get("shape") == "box"]
    for r in regions:
        if r.get("shape") == "particles":
            with open(r["file"], newline="") as f:
                ys = [float(row["y"]) for row in csv.DictReader(f)]
            tops.append(max(ys) - min(ys) + s["particle_spacing"])
    if not tops:
        raise SystemExit("error: check_deposit_band.py: the scene has no column_height, box or particle region")
    return max(tops)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--peer-runout-ratio", type=float)
    ap.add_argument("--like")
    args = ap.parse_args()
    out = Path(args.out)
    scene = tomllib.loads((out / "scene.toml").read_text())
    summary = json.loads((out / "summary.json").read_text())
    materials = [scene["material"]] if "material" in scene else list(scene["materials"].values())
    if any(m.get("cohesion", 0.0) != 0.0 for m in materials):
        raise SystemExit("error: check_deposit_band.py: the bands hold for cohesionless soil only")
    phi = max(plane_strain_friction(m) for m in materials)
    tan_phi = math.tan(math.radians(phi))
    dp = summary["particle_spacing"]
    area = summary["particles"] * dp * dp
    h0 = initial_height(scene)
    l0 = area / h0
    a = h0 / l0
    triangle_height = math.sqrt(2.0 * area * tan_phi)
    l_min = math.sqrt(2.0 * area / tan_phi) if triangle_height <= h0 else area / h0 + h0 / (2.0 * tan_phi)
    l_max = l0 * (1.0 + 1.8 * a) * 1.12
    runout, height, angle = summary["runout_m"], summary["height_m"], summary["repose_angle_deg"]
    fit_length = 0.8 * height / tan_phi
    angle_margin = math.degrees(math.atan(tan_phi + dp / fit_length)) - phi
    bands = [
        ("at rest", summary["stopped_at_rest"], f"stopped_at_rest = {summary['stopped_at_rest']}"),
        ("repose angle", angle <= phi + angle_margin, f"{angle:.2f} deg <= {phi + angle_margin:.2f} (phi_ps {phi:.2f} + margin)"),
        ("runout, statics", runout >= l_min - dp, f"{runout:.4f} m >= {l_min - dp:.4f}"),
        ("height, statics", height <= min(h0, triangle_height) + dp,
         f"{height:.4f} m <= {min(h0, triangle_height) + dp:.4f}"),
        ("height, area", height >= area / (l_max + 2 * dp) - dp, f"{height:.4f} m >= {area / (l_max + 2 * dp) - dp:.4f}"),
    ]
    if args.peer_runout_ratio is None:
        bands.append(("runout, scaling laws", runout <= l_max + dp, f"{runout:.4f} m <= {l_max + dp:.4f}"))
    else:
        thick = summary["runout_thick_m"]
        peer_max = l0 * (1.0 + 1.1 * args.peer_runout_ratio) + dp
        bands += [("runout where H0/10 thick, scaling laws", thick <= l_max + dp, f"{thick:.4f} m <= {l_max + dp:.4f}"),
                  ("runout, peer", runout <= peer_max,
                   f"{runout:.4f} m <= {peer_max:.4f} (L0 (1 + 1.1 x {args.peer_runout_ratio}) + dp)")]
    if a < 1.15:
        low = h0 - 1.5 * dp
        bands.append(("height, low column", height >= low, f"{height:.4f} m >= {low:.4f} (a = {a:.3f} < 1.15)"))
    if args.like:
        other = json.loads((Path(args.like) / "summary.json").read_text())
        for key, margin, unit in (("runout_m", dp, "m"), ("height_m", dp, "m"), ("repose_angle_deg", angle_margin, "deg")):
            bands.append((f"{key} like {args.like}", abs(summary[key] - other[key]) <= margin,
                          f"|{summary[key]:.4f} - {other[key]:.4f}| <= {margin:.4f} {unit}"))
    failed = [b for b in bands if not b[1]]
    print(f"{out}: phi_ps = {phi:.2f} deg, A = {area:.6f} m^2, H0 = {h0} m, a = {a:.3f}")
    for name, ok, words in bands:
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: {words}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

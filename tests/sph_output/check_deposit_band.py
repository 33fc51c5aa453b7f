#!/usr/bin/env python3
"""The deposit of a column collapse run to rest against bands derived from references, not from runs.

  check_deposit_band.py OUT_DIR     (OUT_DIR holds the run's scene.toml, as run, and summary.json)

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
Exits 1 with every violated band named.
"""
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
    reach half a spacing below and above; box regions fill their box."""
    s = scene["scene"]
    if "column_height" in s:
        return s["column_height"] + s["particle_spacing"]
    tops = [r["max"][1] for r in scene.get("regions", []) if r.get("shape") == "box"]
    if not tops:
        raise SystemExit("error: check_deposit_band.py: the scene has no column_height and no box region")
    return max(tops)


def main() -> int:
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    out = Path(sys.argv[1])
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
    angle_max = math.degrees(math.atan(tan_phi + dp / fit_length))
    bands = [
        ("at rest", summary["stopped_at_rest"], f"stopped_at_rest = {summary['stopped_at_rest']}"),
        ("repose angle", angle <= angle_max, f"{angle:.2f} deg <= {angle_max:.2f} (phi_ps {phi:.2f} + margin)"),
        ("runout, statics", runout >= l_min - dp, f"{runout:.4f} m >= {l_min - dp:.4f}"),
        ("runout, scaling laws", runout <= l_max + dp, f"{runout:.4f} m <= {l_max + dp:.4f}"),
        ("height, statics", height <= min(h0, triangle_height) + dp,
         f"{height:.4f} m <= {min(h0, triangle_height) + dp:.4f}"),
        ("height, area", height >= area / (l_max + 2 * dp) - dp, f"{height:.4f} m >= {area / (l_max + 2 * dp) - dp:.4f}"),
    ]
    failed = [b for b in bands if not b[1]]
    print(f"{out}: phi_ps = {phi:.2f} deg, A = {area:.6f} m^2, H0 = {h0} m, a = {a:.3f}")
    for name, ok, words in bands:
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: {words}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

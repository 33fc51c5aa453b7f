#pragma once
/// @file
/// `implicit` for Mohr–Coulomb: backward Euler (closest-point projection in the energy norm of the
/// potential's flow) in principal stresses, after de Souza Neto, Perić & Owen, "Computational
/// Methods for Plasticity" (2008), Boxes 8.4–8.5, extended to the tension cut-off.
/// With constant elasticity and the linear planes f_k = a_k·σ − b_k, flow directions g_k, the return
/// from the principal trial stresses σ_tr (sorted σ1 ≥ σ2 ≥ σ3, eigenvectors kept) onto a set J of
/// active planes is linear:
///   σ = σ_tr − Σ_{l∈J} Δγ_l D g_l,   Σ_{l∈J} (a_k · D g_l) Δγ_l = f_k(σ_tr)  (k ∈ J),
/// with D = (K − 2G/3) 1⊗1 + 2G I the principal stiffness. The sets are tried in order: the main
/// plane f1 = (σ1 − σ3) + (σ1 + σ3) sinφ − 2c cosφ; the right edge σ1 = σ2 (f1 and f2, the plane with
/// σ2 for σ1: triaxial compression); the left edge σ2 = σ3 (f1 and f3, σ2 for σ3: triaxial
/// extension); with a cut-off T, the planes σ_i = T alone and with f1 (and f3), and the corner
/// σ1 = σ2 = T on f1 and f2 as each of its four triples of planes; finally the apex
/// σ1 = σ2 = σ3 = c cotφ (or the cut-off's corner σ_i = T). The first set whose multipliers are ≥ 0,
/// whose stresses keep their order and lie on or inside every plane is the return: for one active
/// plane Δγ = f_tr/(a·D·g), as Box 8.5; docs/method/derivations.md derives the edges and the apex.
/// The consistent tangent is that of an isotropic tensor function of σ_tr (de Souza Neto et al.
/// Appendix A): the principal Jacobian I − D G_J A_J⁻¹ N_Jᵀ plus the spin of the eigenvectors,
/// (σ_i − σ_j)/(σ_tr,i − σ_tr,j) on the shear components, times D.
#include "constitutive/models/mohr_coulomb.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// The return of a principal trial stress.
struct MohrCoulombReturn {
  enum class Kind { Elastic, Plane, RightEdge, LeftEdge, Cutoff, Apex };
  Kind kind = Kind::Elastic;
  Vec3 stress;                         ///< principal stresses after the return, σ1 ≥ σ2 ≥ σ3
  Vec3 plastic_strain = Vec3::Zero();  ///< principal plastic strain, D⁻¹(σ_tr − σ)
  double multiplier = 0.0;             ///< Σ Δγ (the apex: the norm of the plastic strain)
  Mat3 jacobian = Mat3::Identity();    ///< ∂σ_i/∂σ_tr,j
};

/// The return of sorted principal trial stresses with moduli D.
MohrCoulombReturn return_principal(const MohrCoulomb& model, const Vec3& trial, const Moduli& D);

/// One implicit update (no spin); writes the consistent tangent ∂σ/∂Δε when `tangent` is not null.
State implicit_update(const MohrCoulomb& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent = nullptr);

}  // namespace soilsph

#pragma once
/// \file
/// A two-node shear-deformable beam element with full 6 × 6 sections (section6.hpp), written in the
/// body frame: 6 DOF per node [u_x, u_y, u_z, θ_x, θ_y, θ_z] (body axes, as beam_model.hpp), linear
/// interpolation of displacements and small rotations along the straight chord from node 1 to node 2.
///
/// Strains (geometrically linear Timoshenko/Reissner beam [Hodges2006, ch. 4]): γ = u' + t × θ
/// (extension along the tangent t, shear across it) and κ = θ' (torsion along t, bending across),
/// both in body axes; K_e = ∫ Bᵀ C B dx. One-point (reduced) integration at the element middle makes
/// the linear element free of shear locking and exact for constant strain [Prathap1982; Bathe2014,
/// §5.4]: it converges as h² to the shear-deformable beam for any ratio of shear to bending stiffness.
/// The mass is consistent, M_e = ∫ Nᵀ 𝓜 N dx (3-point Gauss, exact for a section varying linearly
/// along the element), so the section's mass-centre offsets couple translations and rotations.
#include "src/fem/section6.hpp"

namespace whirl::fem {

using Mat12e = Eigen::Matrix<double, 12, 12>;

/// Strain–displacement matrix at the element middle (6 × 12): [γ; κ] = B [u₁; θ₁; u₂; θ₂].
Eigen::Matrix<double, 6, 12> strainMatrix6(const Vec3& x1, const Vec3& x2);

/// K_e = L Bᵀ C B with C the section at the element middle (body axes) [N/m …].
Mat12e elementStiffness6(const Vec3& x1, const Vec3& x2, const Mat6s& C_mid);

/// M_e = ∫ Nᵀ 𝓜 N dx, 𝓜 linear from s1 (node 1) to s2 (node 2), body axes.
Mat12e elementMass6(const Vec3& x1, const Vec3& x2, const Mat6s& M1, const Mat6s& M2);

}  // namespace whirl::fem

#pragma once
/// \file
/// Mechanical energy of the model, for conservation checks of a simulation with damping and inputs off:
///   kinetic   T = ½ q̇ᵀ M(q) q̇   (the whole kinetic energy when every frozen coordinate is at rest:
///                                 velocities are then linear in q̇ [Branlard2019, eq. 8]),
///   gravity   V_g = −gᵀ Σ_b (m_b r_b + R_b m1_b c_b)   (∫ r_P dm with s_P = P c, body.hpp),
///   elastic   V_e = Σ_b ½ q_eᵀ K_b q_e + Σ springs ½ k (q − q0)² + Σ 6×6 matrices ½ Δxᵀ K Δx.
/// Axial shortening is in the basis c, so its gravity and centrifugal work is in V_g and T.
#include "src/dynamics/workspace.hpp"

namespace whirl {

struct MechanicalEnergy {
  double kinetic = 0, gravity = 0, elastic = 0;  ///< [J]
  double total() const { return kinetic + gravity + elastic; }
};

/// \param[in] q, qd  all coordinates and rates (dim model.ndof())
MechanicalEnergy mechanicalEnergy(const Model& model, Workspace<double>& ws, const VecX& q, const VecX& qd);

}  // namespace whirl

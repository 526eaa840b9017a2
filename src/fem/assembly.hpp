#pragma once
/// \file
/// Sparse assembly of a beam FE model (all 6 × nnodes DOFs, constraints not applied; see
/// boundary.hpp): elastic stiffness with springs, consistent mass, geometric stiffness, and the
/// direction-wise mass integrals that make the model a whirl Ritz body (src/model/body.hpp).
///
/// The mass integrals use the extended coordinate c = [1; u] (u: all FE DOFs, body frame): every
/// material point sits at s = P c with P = [X₀, N] (reference position, interpolation), sections
/// add their rotary inertia through s = X₀ + r + θ × r. Then m1 = ∫ P dm (3 × (n+1)) and
/// S_jl = ∫ P_jᵀ P_l dm ((n+1) × (n+1)); the consistent mass is M = Σ_j S_jj without row/column 0:
/// the FE mass matrix and the Ritz body carry the same kinetic energy.
#include <array>

#include <Eigen/Sparse>

#include "src/fem/beam_model.hpp"

namespace whirl::fem {

using SpMat = Eigen::SparseMatrix<double>;

/// ∫ P dm and ∫ P_jᵀ P_l dm over c = [1; u] (dims 3 × (n+1), 9 of (n+1) × (n+1), S[3j + l]).
struct MassIntegrals {
  double mass = 0;
  Mat3X m1;
  std::array<SpMat, 9> S;
};

struct Assembly {
  SpMat K;  ///< elastic + Winkler + node springs (n × n)
  SpMat M;  ///< consistent mass with rotary and lumped inertia (n × n)
  MassIntegrals integrals;
};

/// Assembles K, M and (with_integrals) the mass integrals. The model must be valid (validate()).
/// M is assembled from element mass matrices; Σ_j S_jj (without row/column 0) is the same matrix
/// by another path (a unit test checks it).
Assembly assemble(const BeamModel& model, bool with_integrals = true);

/// Σ_e N_e ∫ (v'ᵀv' + w'ᵀw') dx, the geometric stiffness for element axial forces N (tension > 0,
/// one per element) [N/m] (n × n, body frame).
SpMat geometricStiffness(const BeamModel& model, const VecX& axial_force);

/// Axial force of each element (tension > 0) [N] for the displacements u (all DOFs).
VecX axialForces(const BeamModel& model, const VecX& u);

}  // namespace whirl::fem

#pragma once
/// \file
/// Characteristic multipliers of a linear periodic system whose monodromy matrix is a product of
/// factors, Φ(T) = Φ_{G−1} ⋯ Φ_1 Φ_0 (each the propagator over 1/G of the period), without forming the
/// product. A slowly turning rotor makes T long: its well-damped modes decay by e^{−σT} within one
/// revolution (10 % damping at 7 Hz over 12 s: e^{−53}), below the round-off of the product's largest
/// multiplier, so the eigenvalues of the formed Φ(T) lose them. The block-cyclic matrix
///     C = [0 … 0 Φ_{G−1}; Φ_0 0 … 0; 0 Φ_1 0 …; …; 0 … Φ_{G−2} 0]
/// (dim G·nx) has the eigenvalues λ with λ^G = μ and the eigenvectors [x_0; x_1; …] with
/// Φ_g x_g = λ x_{g+1}: the G-th root compresses the range of the multipliers, and each factor spans
/// a short enough time to keep it (the "lifted" or periodic eigenproblem; Bittanti & Colaneri,
/// *Periodic Systems*, 2009, on the cyclic reformulation). G = 1 is the eigenanalysis of Φ(T) itself.
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

struct LiftedMultipliers {
  int groups = 1;  ///< G
  /// Per multiplier: λ, the G-th root with arg λ ∈ (−π/G, π/G] (dim nx); 0 for a state that decays by
  /// more than 1e-12 within one factor (G > 1), whose multiplier is below round-off.
  Eigen::VectorXcd root;
  /// Per multiplier j: blocks[g].col(j) = x_g, the solution at the start of factor g divided by λ^g
  /// (x_0 is the eigenvector of Φ(T) for μ = λ^G); nx × nx each, G of them.
  std::vector<Eigen::MatrixXcd> blocks;
};

/// \param[in] factors Φ_0 … Φ_{G−1}, square, equal sizes (nx × nx), finite.
/// \throws ComputeError when the eigenproblem fails or the principal roots cannot be told apart.
LiftedMultipliers liftedMultipliers(const std::vector<MatX>& factors);

}  // namespace whirl

#pragma once
/// \file
/// An FE model (full or reduced) as a whirl body [Branlard2019, §3.4, eq. 19]: a Ritz body whose shape
/// "functions" are discrete vectors, the columns of a basis Φ over the free DOFs (identity for the
/// full model, Guyan or Craig–Bampton for a reduced one). With u = Φ p and c = [1; p]:
///   m1 = ∫ P dm · T,  S_jl = Tᵀ (∫ P_jᵀ P_l dm) T,  T = blockdiag(1, Φ)  (direction-wise, so the
///   rigid-body coupling terms of eq. 19 are exact), K_ee = Φᵀ K Φ, points at nodes with P = [X; Φ_node]
///   (translations) and θ = Φ_node (rotations), so a child attached at a node follows its
///   translation and rotation. The rest (eq. 19: Bᵀ M B, coupling with children) is the engine's.
#include <string>
#include <utility>
#include <vector>

#include "src/fem/boundary.hpp"
#include "src/model/body.hpp"

namespace whirl::fem {

struct RitzBody {
  BodyInertia inertia;
  ElasticProperties elastic;  ///< K = Φᵀ K Φ, D = 0 (see rayleighDamping)
  std::vector<BodyPoint> points;
};

/// \param assembly   assemble(model, true) (with the mass integrals)
/// \param basis      free DOFs × ne
/// \param stiffness  stiffness over the free DOFs to project (elastic, plus geometric if any)
/// \param points     name and node of each body point
RitzBody ritzBody(const BeamModel& model, const Assembly& assembly, const DofMap& map, const MatX& basis,
                  const SpMat& stiffness, const std::vector<std::pair<std::string, int>>& points);

/// Mass of the elastic coordinates, Σ_j S_jj over p (ne × ne): Φᵀ M Φ.
MatX elasticMass(const BodyInertia& inertia);

}  // namespace whirl::fem

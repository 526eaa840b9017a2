#pragma once
/// \file
/// The size of the mooring loads at a pose: the largest fairlead tension √(H² + V²) of the model's
/// quasi-static lines [N], 0 without lines. An equilibrium search measures its residual against the loads
/// in balance; moored at a symmetric start the residual is zero to round-off of these tensions, so they
/// set the scale there (linearize/operating_point.cpp).
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// \param ws kinematics at the pose (forwardKinematics or a residual evaluation filled it)
double largestMooringTension(const Model& model, const Workspace<double>& ws);

}  // namespace whirl

#pragma once
/// \file
/// A rigid transition piece: interface nodes tied rigidly to a reference point R, whose six DOFs (body
/// axes: translations u_R [m], small rotations θ_R [rad]) replace theirs. For a tied node j at x_j,
///   u_j = u_R + θ_R × (x_j − x_R),  θ_j = θ_R
/// (SubDyn's rigid link of its interface joints to ElastoDyn's platform reference point, the matrix T_I of
/// its Craig–Bampton reduction). A reduction basis over the interface DOFs then maps to R's DOFs by T.
#include <string>
#include <vector>

#include "src/fem/boundary.hpp"
#include "src/model/body.hpp"

namespace whirl::fem {

/// T (free DOFs × 6): the free DOFs of `nodes` as functions of R's six DOFs; the other rows are zero.
/// \throws ComputeError when a DOF of a tied node is fixed (it could not follow R).
MatX rigidTie(const BeamModel& model, const DofMap& map, const std::vector<int>& nodes, const Vec3& reference);

/// The point R on a body whose first six coordinates are R's DOFs (ne coordinates in all):
/// P = [x_R, I₃, 0 …], θ = [0, I₃, 0 …].
BodyPoint rigidInterfacePoint(const std::string& name, const Vec3& reference, int ne);

}  // namespace whirl::fem

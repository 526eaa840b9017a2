#pragma once
/// \file
/// Gravity on each body of a finalized model at its initial configuration (the DOF values, no
/// motion): what the static gravity preload of a flexible body needs — the gravity vector in the
/// body's frame and the mass each body carries (its own and that of every body below it in the tree).
#include <vector>

#include "src/model/model.hpp"

namespace whirl {

struct GravityAtRest {
  std::vector<Vec3> gravity_body;  ///< gravity in each body's frame [m/s²] (bodies in model order)
  std::vector<double> carried;     ///< mass of each body with everything attached below it [kg]
};

/// Forward kinematics at q = the DOF values, q̇ = q̈ = 0, then the bodies' gravity and carried masses.
GravityAtRest gravityAtRest(const Model& m);

}  // namespace whirl

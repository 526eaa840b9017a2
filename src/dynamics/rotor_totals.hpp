#pragma once
/// \file
/// The rotor's aerodynamic resultants that the load outputs read (src/dynamics/outputs.hpp), filled by
/// addAeroLoads and addUnsteadyAeroLoads in the same pass that forms the generalized forces.
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// Rotor thrust [N] and torque [N m] of the blade elements (about and along the rotor axis through
/// the apex); per blade (AeroModel::blades' order) the resultant force [N] of its elements and its
/// moment about the blade body's origin [N m], ground components. Kept in the Workspace so that the
/// output evaluations of an AD linearization reuse its storage.
template <class T>
struct RotorTotals {
  T thrust{0}, torque{0};
  std::vector<Vec3T<T>> blade_force, blade_moment;
};

}  // namespace whirl

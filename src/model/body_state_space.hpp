#pragma once
/// \file
/// Linear first-order states driven by the motion of a free joint's six coordinates:
///   ż = A z + B ẋ,   load on the six coordinates  f = C z,
/// x = (surge, sway, heave, roll, pitch, yaw) of the body's free joint. HydroDyn's wave-radiation
/// memory in state-space form (`RdtnMod = 2`: the fit of the radiation impulse response written by
/// SS_Fitting, Duarte, Sarmento & Alves 2013) is one: the convolution −∫K(t−τ) ẋ(τ) dτ becomes C z.
/// The loads act on the coordinates as BodyMatrices's do (model.hpp). At a static operating point
/// (ẋ = 0) the states rest at z = 0, so they do not enter the nonlinear residual: they are added to the
/// linear model only (linearize/linearize.hpp). States are named "<group> <k>" (1-based within the group).
#include <string>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

struct BodyStateSpace {
  int body = -1;  ///< body on a free joint
  MatX A;         ///< nz × nz [1/s]
  MatX B;         ///< nz × 6, per unit rate of (surge, sway, heave [m/s]; roll, pitch, yaw [rad/s])
  MatX C;         ///< 6 × nz, loads on the six coordinates [N; N m] per unit state
  /// Naming group of each state (dim nz), e.g. "HydroDyn radiation surge": a mode the states carry
  /// is named after the group with the largest share.
  std::vector<std::string> groups;
};

}  // namespace whirl

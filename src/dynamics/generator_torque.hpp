#pragma once
/// \file
/// ServoDyn's simple variable-speed generator torque law (ServoDyn `VSContrl = 1`, as in OpenFAST's
/// ServoDyn.f90 `CalculateTorque`), written for any scalar so its slope reaches the linear model.
#include <cmath>

#include "src/model/scalar.hpp"
#include "src/model/aero_model.hpp"

namespace whirl {

/// Generator torque [N m, high-speed shaft] at generator speed omega [rad/s]:
///   ω ≥ ω_rated: T_rated;  ω < ω_t: k ω²;  else (region 2½): slope (ω − ω_sync),
/// ω_sync = ω_rated / (1 + slip), slope = T_rated / (ω_rated − ω_sync), and ω_t where the line meets
/// the parabola (ServoDyn's VS_TrGnSp). No slip: region 2 up to rated speed. A speed within 1e-9
/// (relative) of rated counts as rated — region 3, constant torque, zero slope — so that a point
/// trimmed at rated speed (linearize/trim.hpp) linearizes with region 3's law whatever the round-off
/// of rotor speed × gear ratio.
template <class T>
T generatorTorque(const GeneratorTorqueLaw& g, const T& omega) {
  const double w = valueOf(omega);
  if (w >= g.rated_speed * (1 - 1e-9)) return T(g.rated_torque);
  const double sync = g.rated_speed / (1.0 + g.slip);
  double slope = 0, transition = g.rated_speed;
  if (g.slip >= 1.5e-4) {  // ServoDyn: sqrt(epsilon) of single precision
    slope = g.rated_torque / (g.rated_speed - sync);
    transition = std::abs(g.k2) < 1.2e-7 ? sync
                                         : (slope - std::sqrt(slope * (slope - 4.0 * g.k2 * sync))) / (2.0 * g.k2);
  }
  if (w < transition) return T(g.k2) * omega * omega;
  return T(slope) * (omega - T(sync));
}

}  // namespace whirl

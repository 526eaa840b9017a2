#pragma once
/// \file
/// ServoDyn's simple variable-speed generator torque law (ServoDyn `VSContrl = 1`, as in OpenFAST's
/// ServoDyn.f90 `CalculateTorque`), written for any scalar so its slope reaches the linear model.
#include <cmath>
#include <utility>

#include "src/base/scalar.hpp"
#include "src/model/aero_model.hpp"

namespace whirl {

/// Generator torque [N m, high-speed shaft] at generator speed omega [rad/s]:
///   ω ≥ ω_rated: T_rated;  ω < ω_t: k ω²;  else (region 2½): slope (ω − ω_sync),
/// ω_sync = ω_rated / (1 + slip), slope = T_rated / (ω_rated − ω_sync), and ω_t where the line meets
/// the parabola (ServoDyn's VS_TrGnSp). No slip: region 2 up to rated speed. A speed within 1e-9
/// (relative) of rated counts as rated — region 3, constant torque, zero slope — so that a point
/// trimmed at rated speed (linearize/trim.hpp) linearizes with region 3's law whatever the round-off
/// of rotor speed × gear ratio.
///
/// The simple induction generator (ServoDyn CalculateTorque, GenModel = 1): the line slope (ω − ω_sync)
/// through rated torque at rated speed, held at ± the pull-out torque beyond the pull-out slip
/// SIG_PORt (rated_speed − ω_sync). The Thevenin-equivalent induction generator (GenModel = 2): the
/// torque of its equivalent circuit, tec_a s / (tec_c0 + tec_c1 s + tec_c2 s²) at slip ratio s.
template <class T>
T generatorTorque(const GeneratorTorqueLaw& g, const T& omega) {
  const double w = valueOf(omega);
  using Kind = GeneratorTorqueLaw::Kind;
  if (g.kind == Kind::SimpleInduction) {
    const double rated_slip = g.rated_speed - g.sync_speed;
    const double slip = w - g.sync_speed;
    if (std::abs(slip) > g.pullout_ratio * rated_slip)
      return T(slip > 0 ? g.pullout_ratio * g.rated_torque : -g.pullout_ratio * g.rated_torque);
    return T(g.rated_torque / rated_slip) * (omega - T(g.sync_speed));
  }
  if (g.kind == Kind::Thevenin) {
    const T s = (omega - T(g.sync_speed)) / g.sync_speed;
    return T(g.tec_a) * s / (T(g.tec_c0) + T(g.tec_c1) * s + T(g.tec_c2) * s * s);
  }
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

/// The generator speeds [rad/s] between which an induction generator's torque rises with speed:
/// the motoring and generating pull-out speeds (where a fixed-speed rotor's steady state lies).
inline std::pair<double, double> pulloutSpeeds(const GeneratorTorqueLaw& g) {
  if (g.kind == GeneratorTorqueLaw::Kind::Thevenin) {
    const double s = std::sqrt(g.tec_c0 / g.tec_c2);  // dT/ds = 0 at s² = c0 / c2
    return {g.sync_speed * (1 - s), g.sync_speed * (1 + s)};
  }
  const double slip = g.pullout_ratio * (g.rated_speed - g.sync_speed);
  return {g.sync_speed - slip, g.sync_speed + slip};
}

}  // namespace whirl

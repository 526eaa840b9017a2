#pragma once
/// \file
/// An equilibrium on a jump of the loads. AeroDyn's blade-element loads are piecewise: an element whose
/// normal (or in-plane) velocity is below 1e-3 m/s skips BEM (no induction), an element without a valid
/// BEM root takes the geometric inflow, and two BEM roots can trade places. Where the equilibrium lies on
/// such a switch there is no root of e(q) = 0: Newton steps back and forth across the switch. The
/// equilibrium is then the one of Filippov (1988) for discontinuous right-hand sides — the point where
/// zero lies between the loads on the two sides — and whirl takes the side with the smaller residual.
#include <string>

#include "src/base/types.hpp"
#include "src/model/model.hpp"

namespace whirl {

struct AeroRecord;

/// Two Newton iterates a and b on either side of a switch of the loads (dim: the solved coordinates).
struct LoadJump {
  int dof = -1;               ///< the coordinate with the largest load jump (model index); −1: no jump
  double below = 0;           ///< its residual on one side [N, N m]
  double above = 0;           ///< and on the other [N, N m]
  double size = 0;            ///< ‖e_a − e_b‖ over the solved coordinates [N, N m]
  double span = 0;            ///< ‖q_a − q_b‖∞, how far apart the sides were [m, rad]
  int element = -1;           ///< the blade element whose loads changed most (AeroRecord order), −1: none
  double vx_a = 0, vx_b = 0;  ///< its normal velocity without induction on each side [m/s]
  double vy_a = 0, vy_b = 0;  ///< its in-plane velocity without induction on each side [m/s]
  bool bem_valid_a = true, bem_valid_b = true;
};

/// Largest relative load jump (‖e_a − e_b‖ / load scale) taken as an equilibrium [-]: a blade element
/// switching branches changes the loads by a fraction of its own load; more is not a switch of one element.
inline constexpr double kMaxLoadJump = 1e-2;

/// The jump between residuals `ea` and `eb` (solved coordinates `solved`), at two iterates that lie on
/// either side of a switch: set if zero lies between them — the combination λ e_a + (1 − λ) e_b
/// closest to zero is below 1 % of ‖e_a − e_b‖ — else dof −1. The element fields are those of
/// `rec_a` and `rec_b` (the two sides' records), when both are given.
LoadJump loadJump(const std::vector<int>& solved, const VecX& qa, const VecX& qb, const VecX& ea, const VecX& eb,
                  const AeroRecord* rec_a, const AeroRecord* rec_b);

/// One clause for messages and notes: where the loads jump and why, e.g. "the load on DOF 'teeter' jumps
/// from -3.509 to 3.51 N m across 1.49e-05 rad: blade 1 element 11 crosses AeroDyn's zero-velocity limit
/// of its normal velocity (|Vx| = 0.001 m/s, here -0.000999758 and -0.00100019 m/s), below which BEM is
/// not solved".
std::string describe(const Model& model, const LoadJump& jump);

}  // namespace whirl

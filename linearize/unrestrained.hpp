#pragma once
/// \file
/// Coordinates the static equilibrium cannot determine: a free yaw about a vertical axis, a free
/// platform yaw, … — no stiffness along them (K(i, i) = 0), so Newton cannot solve for them (K is
/// singular or, through couplings, indefinite) and a load along them has no static balance (a
/// turning rotor's mean yaw moment and its 3P ripple). They are held at their given value, as
/// OpenFAST linearizes such a deck about the point its time simulation reached; the load they carry
/// must stay small (kMaxHeldDrift). The linear model keeps them as states, and their modes come out
/// as rigid-body modes (f ≈ 0, modal/rotor_modes.cpp).
#include <string>
#include <vector>

#include "src/base/types.hpp"
#include "src/model/model.hpp"

namespace whirl {

/// The rule. A coordinate is *unrestrained* when all of
/// - it is an active, non-rotating joint coordinate (elastic coordinates carry their stiffness);
/// - no spring acts along it: no DofSpring with k ≠ 0 on it, no non-zero row or column of a
///   BodyMatrices stiffness (hydrostatics, mooring) through it;
/// - its stiffness K(i, i) = −∂e_i/∂q_i of the structural model at the reference configuration
///   (every elastic coordinate at 0, the joint coordinates at `q`, rates `qd`, inputs `u`,
///   aerodynamics left out) is zero to round-off: |K(i, i)| ≤ kUnrestrainedTolerance × max_j |K(j, j)|
///   over the non-rotating active coordinates j. A yaw axis tilted at the reference (a platform
///   pitch) has gravity stiffness and is solved for.
/// The couplings K(j, i) do not count: yawing an overhanging nacelle turns its weight moment from
/// fore-aft to side-to-side (K(tower SS, yaw) ≈ 3e4 N for the NREL 5MW), and with K(i, i) = 0 such a
/// coupling makes K indefinite — a "solution" that balances the yaw load by tilting the tower, a
/// saddle that Newton finds at absurd yaw angles or not at all.
/// Aerodynamic yaw stiffness does not count: it appears in the linear model (K of linearize) but
/// the periodic aerodynamic and inertial loads of a turning rotor have no static balance along it.
/// \param[in] q, qd, u  the starting point (dims model.ndof(), model.ndof(), model.ninput())
/// \returns the coordinate indices, ascending
std::vector<int> unrestrainedCoordinates(const Model& model, const VecX& q, const VecX& qd, const VecX& u);

/// Relative size of a "zero" stiffness (see unrestrainedCoordinates).
inline constexpr double kUnrestrainedTolerance = 1e-9;

/// Largest drift of a held coordinate [rad or m] that an operating point accepts, ½ |load| / M(i, i) · T²
/// over a time T: one revolution at rotor speed, with the mean of its load over the azimuths
/// (linearizePeriodic); kHeldDriftTime for a point where nothing turns. A free yaw turns under the
/// mean yaw moment of the rotor (ws03 at 6.972 rpm: 0.012 rad per revolution without aerodynamics,
/// 0.007 with; OpenFAST linearizes that deck with the yaw drifting at 7.5e-5 rad/s) or, parked, under
/// the weight moment about the yaw axis the deflected tower tilts (ws03 parked at 10° yaw: 19 N m,
/// 4e-5 rad in 10 s), so a small drift is part of the operating point; a load that moves it by more
/// has none (a body falling along a free prismatic joint: 490 m in 10 s).
inline constexpr double kMaxHeldDrift = 0.1;
/// The time over which a held coordinate's drift is measured where nothing turns [s]: a few periods
/// of a tower's first mode.
inline constexpr double kHeldDriftTime = 10.0;

/// How to hold coordinate `dof` (for messages): for the model's yaw and teeter coordinates the OpenFAST
/// keys ("--set YawDOF=False, or a yaw spring: ServoDyn YawSpr with CompServo = 1"; "--set
/// TeetDOF=False, or a teeter spring …"), otherwise generic.
std::string holdAdvice(const Model& model, int dof);

/// Unit of the generalized load along coordinate `dof`: "N m" (a rotation) or "N" (a translation,
/// an elastic coordinate's generalized force).
std::string loadUnit(const Model& model, int dof);

}  // namespace whirl

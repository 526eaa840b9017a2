#pragma once
/// \file
/// Is a solved operating point inside the range where the model is valid?
///
/// whirl's bodies are linear Ritz bodies with small elastic rotations (θ = Θ q_e) and, at most,
/// second-order axial shortening: a solution with deflections of a sizeable fraction of the body or
/// slopes of tens of degrees is a number the equations produce, not a turbine state. An absurd input
/// (`--set gravity=-1e6`, a rotor speed of 1e9 rpm) converges to such a point. The commands call
/// `checkPointValidity` after each operating-point solve and stop with an error (default) or, with
/// `--allow-invalid-point`, warn on stderr and record the problems in their metadata.
///
/// Checks, over every elastic body and every point of it (body frame, elastic part only):
/// - deflection |P_e q_e| ≤ `max_deflection_fraction` · L, L the largest distance of a body point from
///   the body origin (for a beam, its length; the shape coordinate of a beam is its tip deflection [m]);
/// - slope |Θ q_e|∞ ≤ `max_slope` rad (the small-angle assumption);
/// - the equilibrium residual over the solved coordinates ≤ `max_relative_residual` · the load scale, or
///   on a jump of the loads (OperatingPoint::load_jump) ≤ the jump;
/// - every joint rotation solved for equilibrium stays within half a turn of its start value (a
///   coordinate too weak for its loads swings round: a parked teeter under the rotor's weight);
/// - every active coordinate with a spring law linearized on one piece (DofSpring::q_min … q_max, a
///   teeter stop) lies on that piece.
#include <string>
#include <vector>

#include "linearize/operating_point.hpp"
#include "src/model/model.hpp"

namespace whirl {

/// Validity limits (documented in README.md, *Reliability*).
struct ValidityLimits {
  double max_deflection_fraction = 0.3;  ///< elastic deflection / body length [-]
  double max_slope = 0.5;                ///< elastic rotation [rad]
  double max_relative_residual = 1e-6;   ///< ‖e_solved‖ / load scale [-]
};

/// The problems found at one point, each one line naming the body or DOF ("blade 1: elastic deflection
/// 115 m is 1.8 × its length 63 m (limit 0.3)"); empty when the point is valid.
std::vector<std::string> checkPointValidity(const Model& model, const OperatingPoint& op,
                                            const ValidityLimits& limits = {});

}  // namespace whirl

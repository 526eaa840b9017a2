#pragma once
/// \file
/// The linear model checked against the nonlinear equations it came from: free decays from the
/// equilibrium perturbed by ε along chosen coordinates, integrated by simulate (IDA), against the
/// linear response x(t) = exp(A t) x0 of the model linearize exports there. The difference is of
/// order ε² (the first neglected terms of the Taylor expansion), so halving ε divides it by 4: an
/// observed order log2(err(ε)/err(ε/2)) ≥ 2 confirms that the exported A is the nonlinear system's
/// Jacobian (an order near 1 would mean a wrong entry). It is 3 when the quadratic terms vanish by
/// symmetry (the floating turbine's pitch, a pendulum: measured 2.94–2.99). The frequency and damping identified
/// from a decay of each coordinate perturbed alone by ε are set next to the eigenvalues: by the zero crossings and
/// extrema of that coordinate (identifyDecay), and by the eigensystem realization of every state's response
/// (identifyPoles), which separates the modes that share the coordinate.
///
/// Only for time-invariant linear models: no rotor, a rotor without blades (an axisymmetric rigid
/// rotor, turning freely at its rate), or a parked bladed rotor (no rotating coordinate moving); a turning
/// bladed rotor's model is periodic (linearizePeriodic).
/// With aerodynamics the linear model lets the induction follow (quasi-steady BEM), as the simulation does;
/// with NonlinearCheckOptions::aero_states and a model with unsteady-airfoil or dynamic-inflow states both hold
/// the equilibrium's frozen wake and carry the states (x = [δq; δq̇; δz]).
#include <optional>
#include <string>
#include <vector>

#include "linearize/simulate.hpp"
#include "modal/decay_identification.hpp"
#include "modal/era.hpp"
#include "modal/modes.hpp"

namespace whirl {

struct NonlinearCheckOptions {
  std::vector<int> dofs;    ///< coordinates perturbed (each by the amplitude); empty: every non-rotating active one
  double amplitude = 0.01;  ///< ε [m or rad]
  int levels = 3;           ///< ε, ε/2, ε/4, …
  double t_end = 10;        ///< [s]
  double dt_out = 0.01;     ///< [s]
  double rtol = 1e-10, atol = 1e-13;  ///< IDA, far below the ε² differences
  /// The model's blade-element aerodynamic states (unsteady airfoil, dynamic inflow: aeroStateCount) in both
  /// the linear model (on the frozen wake of the equilibrium) and the simulation (SimulationOptions::
  /// aero_states, the same induction held), the states starting at their steady values; false, or a model
  /// without them: the quasi-steady induction in both.
  bool aero_states = false;
};

struct NonlinearCheckLevel {
  double amplitude = 0;
  double max_difference = 0;  ///< max over time and coordinates of |q_nonlinear − q_linear| [m or rad]
  double max_response = 0;    ///< max |q − q_eq| of the linear response
};

struct NonlinearCheck {
  std::vector<NonlinearCheckLevel> levels;
  std::vector<Mode> modes;  ///< of the linear model at the equilibrium
  std::vector<std::string> identified_dofs;
  std::vector<IdentifiedDecay> identified;  ///< per perturbed coordinate, perturbed alone by the amplitude
  /// Per perturbed coordinate: the poles realized (identifyPoles) from that decay's every state.
  std::vector<std::vector<IdentifiedPole>> poles;
  int aero_states = 0;  ///< the aerodynamic states in both models (NonlinearCheckOptions::aero_states)
  /// Observed order of the difference between consecutive levels (≥ 2), one fewer than levels.
  std::vector<double> orders;
};

/// The poles of a simulated free response (identifyPoles): every integrated coordinate's deviation from
/// the equilibrium's motion q_eq + q̇_eq t, at the recorded instants k·dt_out (a last instant at t_end off
/// that grid is left out). Empty when there are too few instants for the Hankel matrix.
std::vector<IdentifiedPole> realizedPoles(const Simulation& sim, const OperatingPoint& equilibrium, double dt_out);

/// One perturbed coordinate of a check, set next to the eigenvalues: the mode it moves most (largest
/// participation of the coordinate; rigid-body and aerodynamic roots left out) and, of the poles realized from
/// its decay, the one nearest that mode's damped frequency.
struct IdentifiedComparison {
  std::string coordinate;
  IdentifiedDecay decay;               ///< by the coordinate's zero crossings and extrema
  std::optional<IdentifiedPole> pole;  ///< none without a mode or without realized poles
  int mode = -1;                       ///< index into NonlinearCheck::modes; −1: none
};

/// The comparisons of `check`'s perturbed coordinates, in its order (`whirl verify`'s table).
std::vector<IdentifiedComparison> compareWithModes(const Model& model, const NonlinearCheck& check);

/// The options' own checks, before any work: amplitude in (0, limits::kMaxVerifyAmplitude], levels in [2, 8],
/// t_end and dt_out positive and finite (their counts are simulate's to bound).
/// \throws InputError naming the option (`verify: amplitude: …`)
void requireCheckOptions(const NonlinearCheckOptions& options);

/// \param[in] equilibrium  a solved operating point (solveOperatingPoint)
/// \throws InputError for bad options (requireCheckOptions), a turning bladed rotor or an unknown / frozen coordinate;
/// ComputeError from simulate
NonlinearCheck checkAgainstLinear(const Model& model, const OperatingPoint& equilibrium,
                                  const NonlinearCheckOptions& options = {});

}  // namespace whirl

#pragma once
/// \file
/// State-space model for controller design: ẋ = A x + B u, y = C x + D u around an operating point,
/// with named states, inputs and outputs (units, operating-point values, rotating-frame blade).
///
/// States x = [q; q̇; z] of the active coordinates and any first-order states z (HydroDyn radiation; notation,
/// docs/dev/architecture.md), A and B from linearize(). Outputs
/// y = h(q, q̇, q̈) (Model::outputs) are differentiated by AD: with H_• = ∂h/∂• on the active
/// coordinates and q̈ taken from the equations of motion, q̈ = A_q̈ x + B_q̈ u (the rows of q̈ in A, B),
///   C = [H_q, H_q̇, H_z] + H_q̈ A_q̈,   D = H_u + H_q̈ B_q̈,
/// H_z = 0 but for the aerodynamic states (unsteady airfoil, dynamic inflow: linearize/unsteady_aero.hpp), with
/// which the load outputs (rotor thrust and torque, subtree moments) take the states' loads at their operating
/// values, as the equations of motion do (H_q, H_q̇, H_u then carry the unsteady loads' derivatives too).
/// Inputs that drive frozen coordinates (pitch) enter H_u and B through those coordinates (jacobian.hpp).
#include <optional>
#include <string>
#include <vector>

#include "linearize/linearize.hpp"
#include "linearize/periodic.hpp"

namespace whirl {

/// One entry of x, u or y.
struct StateSpaceVariable {
  std::string name;      ///< DOF name (states: its rate is "d(<name>)/dt"), input or output name
  std::string unit;      ///< SI, e.g. "m", "rad/s", "N m"
  double op = 0.0;       ///< operating-point value
  int blade = -1;        ///< rotor blade (0-based) in the rotating frame, −1 = fixed frame
  int rate_of = -1;      ///< states: index of the displacement state this one is the rate of, else −1
  bool azimuth = false;  ///< states: the displacement of a rotating coordinate (the rotor azimuth)
};

struct StateSpaceModel {
  std::vector<StateSpaceVariable> x, u, y;
  VecX xdot_op;                      ///< ẋ at the operating point: [q̇; M⁻¹ e(q, q̇, 0, u); 0]
  MatX A, B, C, D;                   ///< nx × nx, nx × nu, ny × nx, ny × nu
  double azimuth = 0.0;              ///< rad, value of the rotating coordinate (blade 1's azimuth), 0 if none
  double rotor_speed = 0.0;          ///< rad/s, its rate
  std::optional<double> wind_speed;  ///< m/s, when the operating point comes from a schedule
  bool multiblade = false;           ///< rotating entries are in multiblade coordinates (azimuth average)
};

/// Whether each state is a first-order state: neither a displacement with a rate among the states nor
/// a rate (dim x).
std::vector<bool> firstOrderStates(const std::vector<StateSpaceVariable>& x);

/// The state-space model at `op` from its linearization `lin` (all inputs and outputs of the model).
/// \throws ComputeError when an output is not finite at the operating point.
StateSpaceModel stateSpace(const Model& model, const OperatingPoint& op, const LinearModel& lin);

/// Keeps the named inputs and outputs, in the order given (an empty list keeps all).
/// \throws InputError "unknown input 'x' (inputs: …)" / "unknown output …".
StateSpaceModel selectInputsOutputs(const StateSpaceModel& s, const std::vector<std::string>& inputs,
                                    const std::vector<std::string>& outputs);

/// Removes the azimuth displacement state(s) (rows and columns), keeping the rotor-speed state, as
/// ROSCO's linear models do: the rigid azimuth is a pure integrator that controllers do not need.
StateSpaceModel dropAzimuth(const StateSpaceModel& s);

/// Multiblade (Coleman, MBC3) transform of each per-azimuth model (same variables; ≥ 3 blades)
/// and their average (linearize/mbc.hpp): A, B, C, D and the operating points (x_op = T⁻¹ x,
/// u_op, y_op = T1⁻¹ ·). Blade entries "blade k <s>" / "<s>k" become "<s> collective", "<s> cos",
/// "<s> sin"(, "<s> differential") with blade −1.
/// \param[out] per_azimuth the transformed model at each azimuth (may be null)
/// \throws InputError when fewer than 3 blades or the models differ in size.
StateSpaceModel multibladeAverage(const std::vector<StateSpaceModel>& models,
                                  std::vector<StateSpaceModel>* per_azimuth = nullptr);

/// Number of blades of the rotating entries (max blade + 1), 0 when none.
int bladeCount(const StateSpaceModel& s);

/// Unit of a coordinate from its joint: revolute → "rad", prismatic/elastic → "m" (free joints:
/// 3 translations [m], 3 rotations [rad]).
std::string dofUnit(const Model& model, int dof);

}  // namespace whirl

#pragma once
/// \file
/// The turbine with its controller along the wind: at each trimmed point the open-loop plant (the
/// multiblade average of a periodic linearization with the generator torque as a plain input, the
/// azimuth state dropped) is closed by the controller linearized there (linearize/closed_loop.hpp),
/// and the closed loop's modes are named by participation factors |v_i w_i| (right and left
/// eigenvectors, scale-free): the group of states with the largest share names the mode —
/// "rotor speed / pitch control" (pitch PI integral, or the rotor speed with the pitch loop active),
/// "flap 1 BW" (a blade pattern's cosine and sine coordinates counted together),
/// "rotor speed / torque control", "torque control", "speed filter", "speed notch k", "pitch actuator",
/// else the structural coordinate with the largest share (its name in multiblade coordinates).
#include <functional>
#include <string>
#include <vector>

#include "linearize/closed_loop.hpp"
#include "linearize/loop_margins.hpp"
#include "linearize/trim.hpp"

namespace whirl {

struct ClosedLoopMode {
  std::string name;
  double freq_hz = 0;  ///< natural frequency [Hz]
  double damped_freq_hz = 0;
  double damping_ratio = 0;  ///< [-]
  std::complex<double> eigenvalue;
  double controller_share = 0;  ///< participation of the controller's states [-]
  /// One of the roots the blade elements' unsteady-airfoil states add (modal/aero_roots.hpp), named
  /// "aero k"; the other modes are named from the structure's and the controller's states alone.
  bool aero = false;
  /// Right eigenvector on the model's states (ClosedLoopPoint::closed.x or plant.x), largest entry 1:
  /// what tracking along the wind compares (modal/closed_loop_campbell.hpp).
  Eigen::VectorXcd shape;
};

struct ClosedLoopPoint {
  SteadyState steady;
  StateSpaceModel plant;                                 ///< open loop (multiblade average, azimuth dropped)
  StateSpaceModel closed;                                ///< with the controller's states appended
  std::vector<ClosedLoopMode> open_modes, closed_modes;  ///< oscillating and real roots, by frequency
  LoopMargins pitch, torque;  ///< margins of each loop broken at its actuator input (NaN where the loop does not act)
  bool stable = true;         ///< every closed-loop eigenvalue with Re λ < 0 (the rigid azimuth dropped)
  double least_damping = 0;   ///< smallest damping ratio among the closed-loop modes [-]
};

struct ClosedLoopOptions {
  int azimuths = 36;  ///< per revolution, periodic linearization (multiblade average)
  bool frozen_wake = true;
  MarginOptions margins;
  ClosedLoopPorts ports;
  /// The plant's outputs kept (names, in the model's order); empty: all. Each output costs its
  /// Jacobian at every azimuth; the loop needs ports.speed_output only.
  std::vector<std::string> outputs;
};

/// One point: `controller` linearized at `steady` (gains scheduled at its pitch, region from it).
ClosedLoopPoint closedLoopPoint(const Model& model, const SteadyState& steady, const LinearController& controller,
                                const ClosedLoopOptions& opt = {});
/// The same on an open-loop plant already linearized there (ClosedLoopPoint::plant of a previous call):
/// only the closing, the modes and the margins.
ClosedLoopPoint closedLoopPoint(const StateSpaceModel& plant, const SteadyState& steady,
                                const LinearController& controller, const ClosedLoopOptions& opt = {});

/// The modes of a state matrix named as above; `has_pitch_loop` names the rotor-speed mode; a blade
/// pattern's cyclic modes are named backward or forward whirl (BW, FW) at `rotor_speed` [rad/s] (its
/// sign the rotor's sense), cos or sin when parked (|Ω| < 0.01 rad/s).
std::vector<ClosedLoopMode> namedModes(const StateSpaceModel& s, bool has_pitch_loop, double rotor_speed = 0);
struct EigenDecomposition;
/// As above from the decomposition of s.A with left eigenvectors (eigenStandard(s.A, true)).
std::vector<ClosedLoopMode> namedModes(const StateSpaceModel& s, const EigenDecomposition& e, bool has_pitch_loop,
                                       double rotor_speed);

}  // namespace whirl

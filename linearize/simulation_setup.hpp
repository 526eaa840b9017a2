#pragma once
/// \file
/// What a simulation's caller names by text, checked against the model with the messages the user
/// sees (`whirl simulate`'s --init, --input, --drive; the Python `Model.simulate`), and the check of
/// the recorded motion against the model's range of validity (linearize/point_validity.hpp).
#include <functional>
#include <optional>
#include <string>

#include "linearize/operating_point.hpp"
#include "linearize/simulate.hpp"
#include "linearize/trim.hpp"

namespace whirl {

/// Sets an initial value of `start`: `name` is a coordinate ("tower FA 1": the value [m or rad]),
/// "NAME+" (an offset added to the start value) or "NAME rate" (the rate [m/s or rad/s]).
/// \throws InputError "key: 'NAME': no such coordinate (active: …)" or "… a frozen coordinate …"
void applyInitialCondition(const Model& m, OperatingPoint& start, std::string name, double value,
                           const std::string& key);

/// Index of input `name`. \throws InputError "key: 'NAME': no such input (inputs: …)"
int simulationInput(const Model& m, const std::string& name, const std::string& key);

/// Index of the active coordinate `name` a signal drives. \throws InputError "key: 'NAME': no such active coordinate"
int drivenCoordinate(const Model& m, const std::string& name, const std::string& key);

/// Where a simulation at wind speed `wind` [m/s] starts: the steady state trimmed there (with
/// `controller` when given, ROSCO's), and the equilibrium at azimuth 0 under its condition and generator
/// torque (`whirl simulate --wind`, Model.simulate(wind=…)); the rotor is to be free.
struct WindStart {
  SteadyState steady;
  OperatingPoint start;
};
WindStart windStart(const Model& m, double wind, const RoscoController* controller);

/// The first recorded instant outside the model's range of validity (deflections, slopes; only the
/// geometry is checked), as "t = … s: the motion leaves the model's range of validity: <problem>";
/// empty when the whole motion is valid. A model that blows up (negative damping: a 325 km tower
/// deflection, issue 48, item 6) gives no result to keep silently (docs/user/limits.md, *Blow-ups*).
std::optional<std::string> invalidMotion(const Model& m, const Simulation& sim);

/// A SimulationOptions::stop that ends the integration at the first recorded instant outside the
/// model's range of validity (the instant invalidMotion then names): a model that blows up is not
/// integrated on to t_end (issue 48). `m` must outlive the function.
std::function<bool(double, const VecX&)> stopAtInvalidMotion(const Model& m);

}  // namespace whirl

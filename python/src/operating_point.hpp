#pragma once
/// \file
/// An operating point as Python holds it: the model it belongs to, the condition it was asked for
/// and the equilibrium solved there (the first azimuth's for a turning rotor).
#include <memory>
#include <optional>

#include "linearize/operating_point.hpp"
#include "src/model/operating_condition.hpp"

namespace whirl::python {

struct PyOperatingPoint {
  std::shared_ptr<const Model> model;
  OperatingCondition condition;
  double rpm = 0;                    ///< rotor speed [rpm]
  std::optional<double> wind_speed;  ///< [m/s], as given
  std::optional<double> pitch_deg;   ///< collective pitch [deg], as given
  OperatingPoint point;              ///< the solved equilibrium
};

/// The condition of `m` at rotor speed `rpm` [rpm] (the model's own when absent), hub-height wind
/// [m/s], collective pitch [deg] and azimuth [deg]; InputError with the CLI's --rpm messages.
OperatingCondition conditionOf(const Model& m, std::optional<double> rpm, std::optional<double> wind,
                               std::optional<double> pitch_deg, std::optional<double> azimuth_deg);

}  // namespace whirl::python

#include "src/model/operating_condition.hpp"

#include <numbers>

#include "src/model/model.hpp"

namespace whirl {

OperatingCondition modelCondition(const Model& m) {
  OperatingCondition c;
  for (const Dof& d : m.dofs)
    if (d.rotating) {
      c.rotor_speed = d.rate;
      break;
    }
  return c;
}

double rpmToRadPerSec(double rpm) { return rpm * 2 * std::numbers::pi / 60; }

SweepPoint sweepPoint(double rpm, std::optional<double> wind_speed, std::optional<double> pitch_deg) {
  SweepPoint p;
  p.rpm = rpm;
  p.wind_speed = wind_speed;
  p.pitch_deg = pitch_deg;
  p.condition.rotor_speed = rpmToRadPerSec(rpm);
  return p;
}

}  // namespace whirl

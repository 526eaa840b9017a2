#include "linearize/sweep.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <regex>

#include "src/base/limits.hpp"

namespace whirl {

std::vector<double> parseRange(const std::string& spec, const std::string& option) {
  static const std::regex re(R"(\s*([-+0-9.eE]+)\s*:\s*([-+0-9.eE]+)\s*:\s*([-+0-9.eE]+)\s*)");
  static const std::regex one(R"(\s*([-+0-9.eE]+)\s*)");
  std::smatch mt;
  if (std::regex_match(spec, mt, one)) return parseRange(mt.str(1) + ":1:" + mt.str(1), option);  // one value
  if (!std::regex_match(spec, mt, re))
    throw InputError(option + ": expected START:STEP:STOP (or one value), got '" + spec + "'");
  double a, s, b;
  try {
    a = std::stod(mt[1]);
    s = std::stod(mt[2]);
    b = std::stod(mt[3]);
  } catch (const std::exception&) {
    throw InputError(option + ": not a number in '" + spec + "'");
  }
  if (!(s > 0) || !(b >= a) || !std::isfinite(a) || !std::isfinite(b))
    throw InputError(option + ": need STEP > 0 and STOP >= START in '" + spec + "'");
  if (a < 0)
    throw InputError(option + (option == "--rpm" ? ": negative rotor speed in '" : ": negative value in '") + spec +
                     "' (rotors turn in the positive sense, as in a schedule)");
  // Count in double first: (b − a)/s can exceed the int range (0:1e-10:1).
  const double count = std::floor((b - a) / s + 1e-9) + 1;
  if (!(count <= limits::kMaxSweepPoints))
    throw InputError(option + ": more than " + std::to_string(limits::kMaxSweepPoints) + " points in '" + spec +
                     "' (src/base/limits.hpp)");
  const int n = static_cast<int>(count);
  std::vector<double> values(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) values[static_cast<size_t>(k)] = a + k * s;
  return values;
}

std::vector<SweepPoint> rpmRange(const std::string& spec) {
  std::vector<SweepPoint> pts;
  for (double rpm : parseRange(spec, "--rpm")) pts.push_back(sweepPoint(rpm));
  return pts;
}

OperatingCondition sweepCondition(const Model& m, const SweepPoint& point) {
  OperatingCondition c = point.condition;
  if (point.wind_speed && !c.wind_speed && m.roles.wind_speed_input >= 0) c.wind_speed = point.wind_speed;
  if (point.pitch_deg && !c.collective_pitch && !m.roles.blade_pitch.empty())
    c.collective_pitch = *point.pitch_deg * std::numbers::pi / 180;
  return c;
}

std::string sweepPointLabel(const Model& m, const SweepPoint& point) {
  // From the condition and the model's own values, not from initialPoint: the label goes into the
  // message of an error that the point's start may itself have raised.
  const OperatingCondition c = sweepCondition(m, point);
  constexpr double deg = 180 / std::numbers::pi;
  std::string s = fmt::format("{:.6g} rpm", c.rotor_speed * 30 / std::numbers::pi);
  if (m.roles.wind_speed_input >= 0)
    s += fmt::format(", wind {:.6g} m/s", c.wind_speed.value_or(m.inputs[m.roles.wind_speed_input].value));
  if (!m.roles.blade_pitch.empty())
    s += fmt::format(", pitch {:.6g} deg",
                     c.collective_pitch.value_or(m.dofs[m.roles.blade_pitch.front()].value) * deg);
  if (!m.roles.azimuth.empty()) s += fmt::format(", azimuth {:.6g} deg", m.dofs[m.roles.azimuth.front()].value * deg);
  return s;
}

}  // namespace whirl

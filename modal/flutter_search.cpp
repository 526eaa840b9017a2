#include "modal/flutter_search.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "modal/rotor_modes.hpp"
#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/model/operating_condition.hpp"

namespace whirl {
namespace {

void checkOptions(const Model& m, const FlutterSearchOptions& o) {
  if (findAzimuthDof(m) < 0) throw InputError("flutter: the model has no rotor (no rotating coordinate)");
  if (!(o.rpm_min > 0) || !(o.rpm_max > o.rpm_min) || !std::isfinite(o.rpm_max))
    throw InputError(fmt::format(
        "flutter: the rotor speeds {:g} to {:g} rpm are not an increasing range above 0 (--rpm-min, --rpm-max)",
        o.rpm_min, o.rpm_max));
  auto within = [](double x, double lo, double hi, const char* key, const char* unit) {
    if (!(x >= lo && x <= hi))
      throw InputError(fmt::format("flutter: {}: {:g} is outside [{:g}, {:g}] {}", key, x, lo, hi, unit));
  };
  within(o.wind, 0, limits::kMaxWindSpeed, "wind", "m/s");
  within(o.rpm_step, 1e-3, 1e3, "rpm_step", "rpm");
  // Each rotor speed is a periodic linearization, as a Campbell point: the same bound as a sweep's points.
  const double speeds = (o.rpm_max - o.rpm_min) / o.rpm_step;
  if (!(speeds <= limits::kMaxSweepPoints))
    throw InputError(fmt::format(
        "flutter: {:g} to {:g} rpm in steps of {:g} rpm are {:.3g} rotor speeds, more than {} (src/base/limits.hpp, "
        "kMaxSweepPoints): narrow the range or take larger steps (--rpm-max, --rpm-step)",
        o.rpm_min, o.rpm_max, o.rpm_step, speeds, limits::kMaxSweepPoints));
  within(o.tolerance, 1e-6, 1e3, "tolerance", "rpm");
  within(o.min_freq, 0, 1e3, "min_freq", "Hz");
  if (o.azimuths < 1) throw InputError("flutter: azimuths: must be at least 1");
}

FlutterPoint leastDamped(const Model& m, const FlutterSearchOptions& opt, const FlutterCallbacks& cb, double rpm) {
  OperatingCondition c = modelCondition(m);
  c.rotor_speed = rpmToRadPerSec(rpm);
  if (m.roles.wind_speed_input >= 0) c.wind_speed = opt.wind;
  PeriodicOptions p;
  p.azimuths = opt.azimuths;
  const PeriodicLinearization lin = linearizePeriodic(m, c, p);
  if (cb.check) cb.check(lin, rpm);
  const RotorModes r = rotorModes(m, lin);
  FlutterPoint out;
  out.rpm = rpm;
  out.damping = std::numeric_limits<double>::infinity();
  for (const Mode& mode : r.modes)
    if (!mode.rigid_body && !mode.first_order && mode.freq_hz >= opt.min_freq && mode.damping_ratio < out.damping) {
      out.damping = mode.damping_ratio;
      out.freq_hz = mode.damped_freq_hz;
      out.mode = mode.name;
    }
  if (out.mode.empty())
    throw ComputeError(fmt::format("flutter: no oscillating mode above {:g} Hz at {:g} rpm", opt.min_freq, rpm));
  if (cb.progress) cb.progress(out);
  return out;
}

}  // namespace

void setRotorSpeedRange(const Model& m, std::optional<double> rpm_min, std::optional<double> rpm_max,
                        FlutterSearchOptions& o) {
  o.rpm_min = rpm_min ? *rpm_min : modelCondition(m).rotor_speed * 30 / std::numbers::pi;
  o.rpm_max = rpm_max ? *rpm_max : 3 * o.rpm_min;
}

FlutterSearch flutterSearch(const Model& m, const FlutterSearchOptions& opt, const FlutterCallbacks& cb) {
  checkOptions(m, opt);
  FlutterSearch s;
  auto at = [&](double rpm) {
    s.points.push_back(leastDamped(m, opt, cb, rpm));
    return s.points.back();
  };
  FlutterPoint below = at(opt.rpm_min);
  if (below.damping < 0)
    throw ComputeError(fmt::format(
        "flutter: {} is already unstable at the first rotor speed {:g} rpm (damping {:.3g} %): start lower with "
        "--rpm-min",
        below.mode, opt.rpm_min, 100 * below.damping));
  std::optional<FlutterPoint> above;
  for (double rpm = opt.rpm_min + opt.rpm_step; rpm <= opt.rpm_max + 1e-9 && !above; rpm += opt.rpm_step) {
    const FlutterPoint l = at(rpm);
    if (l.damping < 0) above = l;
    else below = l;
  }
  if (!above) return s;
  // Bisection on the rotor speed: the least damping is continuous in it, negative above, positive below.
  while (above->rpm - below.rpm > opt.tolerance) {
    const FlutterPoint mid = at(0.5 * (below.rpm + above->rpm));
    if (mid.damping < 0) above = mid;
    else below = mid;
  }
  const double t = below.damping / (below.damping - above->damping);
  s.onset = FlutterOnset{below.rpm + t * (above->rpm - below.rpm), below.freq_hz + t * (above->freq_hz - below.freq_hz),
                         above->mode};
  return s;
}

}  // namespace whirl

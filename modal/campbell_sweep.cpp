#include "modal/campbell_sweep.hpp"

#include <cmath>
#include <numbers>
#include <regex>

#include "linearize/periodic.hpp"
#include "modal/campbell_serialize.hpp"
#include "modal/rotor_modes.hpp"
#include "src/parallel/parallel_map.hpp"
#include "src/model/error.hpp"
#include "src/model/limits.hpp"

namespace whirl {

std::vector<SweepPoint> rpmRange(const std::string& spec) {
  static const std::regex re(R"(\s*([-+0-9.eE]+)\s*:\s*([-+0-9.eE]+)\s*:\s*([-+0-9.eE]+)\s*)");
  std::smatch mt;
  if (!std::regex_match(spec, mt, re)) throw InputError("--rpm: expected START:STEP:STOP, got '" + spec + "'");
  double a, s, b;
  try {
    a = std::stod(mt[1]);
    s = std::stod(mt[2]);
    b = std::stod(mt[3]);
  } catch (const std::exception&) {
    throw InputError("--rpm: not a number in '" + spec + "'");
  }
  if (!(s > 0) || !(b >= a) || !std::isfinite(a) || !std::isfinite(b))
    throw InputError("--rpm: need STEP > 0 and STOP >= START in '" + spec + "'");
  if (a < 0) throw InputError("--rpm: negative rotor speed in '" + spec + "' (rotors turn in the positive sense, as in a schedule)");
  // Count in double first: (b − a)/s can exceed the int range (0:1e-10:1).
  const double count = std::floor((b - a) / s + 1e-9) + 1;
  if (!(count <= limits::kMaxSweepPoints))
    throw InputError("--rpm: more than " + std::to_string(limits::kMaxSweepPoints) + " points in '" + spec +
                     "' (src/model/limits.hpp)");
  const int n = static_cast<int>(count);
  std::vector<SweepPoint> pts(n);
  for (int k = 0; k < n; ++k) pts[k].rpm = a + k * s;
  return pts;
}

int setCollectivePitch(Model& m, double pitch_deg) {
  int count = 0;
  static const std::regex re(R"(blade \d+ pitch)");
  for (auto& d : m.dofs)
    if (std::regex_match(d.name, re)) {
      d.value = pitch_deg * std::numbers::pi / 180;
      ++count;
    }
  return count;
}

CampbellPoint campbellPoint(const Model& base, const SweepPoint& point, const SweepOptions& opt) {
  Model m = base;
  const double omega = point.rpm * 2 * std::numbers::pi / 60;
  for (auto& d : m.dofs)
    if (d.rotating) d.rate = omega;
  if (point.pitch_deg) setCollectivePitch(m, *point.pitch_deg);
  PeriodicOptions popt;
  popt.azimuths = opt.azimuths;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), popt);
  std::vector<std::string> problems;
  if (opt.check_point) problems = opt.check_point(m, p.points, point);
  RotorModes r = rotorModes(m, p);
  CampbellPoint cp;
  cp.validity_problems = std::move(problems);
  cp.rpm = point.rpm;
  cp.wind_speed = point.wind_speed;
  cp.pitch_deg = point.pitch_deg;
  cp.coordinates = std::move(r.coordinates);
  cp.modes = std::move(r.modes);
  return cp;
}

std::vector<CampbellPoint> campbellSweep(const Model& base, const std::vector<SweepPoint>& points,
                                         const SweepOptions& opt) {
  parallel::MapOptions map;
  map.progress = opt.progress;
  return parallel::parallelMap<CampbellPoint>(
      static_cast<int>(points.size()), [&](int k) { return campbellPoint(base, points[k], opt); },
      encodeCampbellPoint, decodeCampbellPoint, map);
}

}  // namespace whirl

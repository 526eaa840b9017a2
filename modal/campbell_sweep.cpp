#include "modal/campbell_sweep.hpp"

#include <cmath>
#include <numbers>
#include <regex>

#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "src/model/error.hpp"

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
  const int n = static_cast<int>(std::floor((b - a) / s + 1e-9)) + 1;
  if (n > 100000) throw InputError("--rpm: more than 100000 points in '" + spec + "'");
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

std::vector<CampbellPoint> campbellSweep(const Model& base, const std::vector<SweepPoint>& points,
                                         const SweepOptions& opt) {
  std::vector<CampbellPoint> out;
  out.reserve(points.size());
  PeriodicOptions popt;
  popt.azimuths = opt.azimuths;
  std::optional<OperatingPoint> warm;
  for (size_t k = 0; k < points.size(); ++k) {
    Model m = base;
    const double omega = points[k].rpm * 2 * std::numbers::pi / 60;
    for (auto& d : m.dofs)
      if (d.rotating) d.rate = omega;
    if (points[k].pitch_deg) setCollectivePitch(m, *points[k].pitch_deg);
    OperatingPoint start = initialPoint(m);
    if (warm) {  // previous point's equilibrium: a good guess for the next speed
      for (int i = 0; i < m.ndof(); ++i)
        if (!m.dofs[i].rotating && !m.dofs[i].frozen) start.q(i) = warm->q(i);
    }
    const PeriodicLinearization p = linearizePeriodic(m, start, popt);
    warm = p.points.front();
    RotorModes r = rotorModes(m, p);
    CampbellPoint cp;
    cp.rpm = points[k].rpm;
    cp.wind_speed = points[k].wind_speed;
    cp.pitch_deg = points[k].pitch_deg;
    cp.coordinates = std::move(r.coordinates);
    cp.modes = std::move(r.modes);
    out.push_back(std::move(cp));
    if (opt.progress) opt.progress(static_cast<int>(k + 1), static_cast<int>(points.size()));
  }
  return out;
}

}  // namespace whirl

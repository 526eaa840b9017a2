#include "modal/closed_loop_campbell.hpp"

#include <algorithm>
#include <map>
#include <numbers>

namespace whirl {
namespace {

/// A Campbell point of one loop's roots, shapes on the plant's states.
CampbellPoint campbellPointOf(const ClosedLoopPoint& p, bool closed) {
  const std::vector<StateSpaceVariable>& plant = p.plant.x;
  CampbellPoint cp;
  cp.rpm = p.steady.condition.rotor_speed * 30 / std::numbers::pi;
  cp.wind_speed = p.steady.condition.wind_speed;
  cp.pitch_deg = p.steady.condition.collective_pitch.value_or(0) * 180 / std::numbers::pi;
  for (const StateSpaceVariable& v : plant) cp.coordinates.push_back(v.name);
  for (const ClosedLoopMode& m : closed ? p.closed_modes : p.open_modes) {
    Mode md;
    md.freq_hz = m.freq_hz;
    md.damped_freq_hz = m.damped_freq_hz;
    md.damping_ratio = m.damping_ratio;
    md.name = m.name;
    md.first_order = m.aero;  // "aero k": listed apart, never tracked (modal/aero_roots.hpp)
    md.shape = m.shape.head(static_cast<Eigen::Index>(plant.size()));
    md.participation = md.shape.cwiseAbs2().real();
    md.participation /= std::max(md.participation.sum(), 1e-300);
    cp.modes.push_back(std::move(md));
  }
  return cp;
}

CampbellDiagram diagramOf(const std::vector<ClosedLoopPoint>& points, bool closed, const TrackingOptions& opt) {
  CampbellDiagram d;
  for (const ClosedLoopPoint& p : points) d.points.push_back(campbellPointOf(p, closed));
  d.lines = trackModes(d.points, opt);
  return d;
}

}  // namespace

ClosedLoopCampbell closedLoopCampbell(const Model& model, const RoscoController& controller,
                                      const std::vector<SteadyState>& schedule, const ClosedLoopCampbellOptions& opt) {
  ClosedLoopCampbell out;
  ClosedLoopOptions point = opt.point;
  if (point.outputs.empty()) point.outputs = {point.ports.speed_output};
  for (const SteadyState& s : schedule) {
    out.points.push_back(closedLoopPoint(model, s, linearRosco(controller, s, opt.controller), point));
    if (opt.progress) opt.progress(static_cast<int>(out.points.size()), static_cast<int>(schedule.size()));
  }
  out.open = diagramOf(out.points, false, opt.tracking);
  out.closed = diagramOf(out.points, true, opt.tracking);
  return out;
}

}  // namespace whirl

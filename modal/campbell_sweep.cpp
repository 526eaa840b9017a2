#include "modal/campbell_sweep.hpp"

#include "linearize/periodic.hpp"
#include "modal/aero_roots.hpp"
#include "modal/campbell_serialize.hpp"
#include "modal/mode_shapes.hpp"
#include "modal/rotor_modes.hpp"

namespace whirl {

CampbellPoint campbellPoint(const Model& m, const SweepPoint& point, const OperatingPoint& start,
                            const SweepOptions& opt) {
  PeriodicOptions popt;
  popt.azimuths = opt.azimuths;
  popt.linearize.inputs = false;  // modes only
  popt.linearize.unsteady_aero = opt.unsteady_aero;
  if (point.deflections.size() > 0) popt.deflections = &point.deflections;
  const PeriodicLinearization p = linearizePeriodic(m, start, popt);
  std::vector<std::string> problems;
  if (opt.check_point) problems = opt.check_point(m, p.points, point);
  RotorModes r = rotorModes(m, p);
  // The node motions of the structural modes; an aerodynamic root (modal/aero_roots.hpp) moves the
  // structure little, and the motions of its hundreds of roots (180 UA states on the NREL 5MW) made
  // campbell_modes.json 160 MB and the sweep 10× slower.
  std::vector<Mode> structural;
  std::vector<std::size_t> at;
  for (std::size_t k = 0; k < r.modes.size(); ++k)
    if (!isAeroRoot(r.modes[k])) structural.push_back(std::move(r.modes[k])), at.push_back(k);
  addModeMotions(m, p, r.num_blades, r.coordinates, structural);
  for (std::size_t k = 0; k < at.size(); ++k) r.modes[at[k]] = std::move(structural[k]);
  CampbellPoint cp;
  cp.validity_problems = std::move(problems);
  cp.rpm = point.rpm;
  cp.wind_speed = point.wind_speed;
  cp.pitch_deg = point.pitch_deg;
  cp.coordinates = std::move(r.coordinates);
  cp.modes = std::move(r.modes);
  return cp;
}

CampbellPoint campbellPoint(const Model& m, const SweepPoint& point, const SweepOptions& opt) {
  return campbellPoint(m, point, initialPoint(m, sweepCondition(m, point)), opt);
}

std::vector<CampbellPoint> campbellSweep(int sets, const std::function<const Model&(int)>& model_of,
                                         const std::vector<SweepPoint>& points, const SweepOptions& opt) {
  return sweepOperatingPoints<CampbellPoint>(
      sets, model_of, points,
      [&](const Model& m, const SweepPoint& point, const OperatingPoint& start) {
        return campbellPoint(m, point, start, opt);
      },
      encodeCampbellPoint, decodeCampbellPoint, opt);
}

std::vector<CampbellPoint> campbellSweep(const Model& m, const std::vector<SweepPoint>& points,
                                         const SweepOptions& opt) {
  return campbellSweep(
      1, [&](int) -> const Model& { return m; }, points, opt);
}

}  // namespace whirl

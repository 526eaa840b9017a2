#include "linearize/controller_tuning_whirl.hpp"

#include <algorithm>
#include <iterator>
#include <optional>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {
namespace {

int stateIndex(const LinearModel& lin, int dof) {
  const auto it = std::find(lin.dofs.begin(), lin.dofs.end(), dof);
  if (it == lin.dofs.end()) throw InputError(where("", 0, "azimuth", "the rotating coordinate is not a state"));
  return static_cast<int>(std::distance(lin.dofs.begin(), it));
}

}  // namespace

std::vector<TuningPoint> whirlTuningSchedule(const Model& model, const std::vector<SteadyState>& trimmed,
                                             const WhirlTuningOptions& opt) {
  const int pitch_in = model.roles.collective_pitch_input;
  if (pitch_in < 0) throw InputError(where("", 0, "collective pitch", "the model has no collective pitch input"));
  const int az = findAzimuthDof(model);
  if (az < 0) throw InputError(where("", 0, "azimuth", "the model has no rotating coordinate"));
  const int wind_in = model.roles.wind_speed_input;
  // The plant without the torque law: the generator torque is the controller's input.
  Model plant = model;
  plant.generator.speed_output = -1;
  std::vector<TuningPoint> s;
  for (const SteadyState& t : trimmed) {
    PeriodicOptions po;
    po.azimuths = std::max(1, opt.trim.azimuths);
    po.azimuth_dof = az;
    po.linearize.frozen_wake = opt.frozen_wake;
    if (!t.azimuth_q.empty()) po.deflections = &t.azimuth_q.front();
    OperatingCondition c = t.condition;
    // A full revolution is what linearizePeriodic steps; one blade passage of `azimuths` points is what
    // the trim averaged: the same azimuths k·2π/(B n) when the revolution has B·n points.
    const int blades = std::max<int>(1, static_cast<int>(model.roles.blade_pitch.size()));
    po.azimuths *= blades;
    if (model.generator.active()) c.generator_torque = t.generator_torque;
    const PeriodicLinearization p = linearizePeriodic(plant, c, po);
    TuningPoint tp;
    tp.wind_speed = c.wind_speed.value_or(0);
    tp.rotor_speed = c.rotor_speed;
    tp.pitch = c.collective_pitch.value_or(0);
    tp.above_rated = t.above_rated;
    for (const LinearModel& lin : p.models) {
      const int i = stateIndex(lin, az);
      tp.dq_dpitch += lin.Q(i, pitch_in) / static_cast<double>(p.models.size());
      tp.dq_domega -= lin.C(i, i) / static_cast<double>(p.models.size());
      if (wind_in >= 0) tp.dq_dwind += lin.Q(i, wind_in) / static_cast<double>(p.models.size());
    }
    const double R = model.aero.rotor_radius;
    tp.tsr = tp.wind_speed > 0 ? tp.rotor_speed * R / tp.wind_speed : 0;
    s.push_back(tp);
  }
  return s;
}

double rotorInertia(const Model& model) {
  const int az = findAzimuthDof(model);
  if (az < 0) throw InputError(where("", 0, "azimuth", "the model has no rotating coordinate"));
  // The mass matrix alone: a linearization at the initial point would need its induction (frozen wake).
  const OperatingPoint p = initialPoint(model);
  Workspace<double> ws(model);
  MatX M;
  massMatrix(model, ws, p.q, M);
  return M(az, az);
}

double gearboxRatio(const Model& model) {
  const int az = findAzimuthDof(model);
  std::optional<int> out = model.findOutput("GenSpeed");
  if (!out && model.generator.active()) out = model.generator.speed_output;
  double g = 0;
  if (out && az >= 0)
    for (const auto& [d, k] : model.outputs[static_cast<size_t>(*out)].terms)
      if (d == az) g += k;
  if (!(g > 0)) throw InputError(where("", 0, "GenSpeed", "no generator-speed output following the rotor azimuth"));
  return g;
}

}  // namespace whirl

#include "modal/closed_loop_step.hpp"

#include <algorithm>
#include <cmath>

#include "linearize/operating_point.hpp"
#include "linearize/rosco_linear.hpp"
#include "linearize/rosco_step.hpp"
#include "linearize/simulate.hpp"
#include "modal/closed_loop_modes.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

int indexOf(const std::vector<StateSpaceVariable>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  throw InputError(where("", 0, name, "not an output of the closed loop"));
}

void checkOptions(const ClosedLoopStepOptions& o) {
  auto positive = [](double x, const char* key) {
    if (!(x > 0) || !std::isfinite(x)) throw InputError(where("", 0, key, "must be a positive number"));
  };
  positive(o.t_end, "t_end");
  positive(o.dt_out, "dt_out");
  positive(o.controller_dt, "controller_dt");
  if (!std::isfinite(o.wind_step) || o.wind_step == 0) throw InputError(where("", 0, "wind_step", "must be non-zero"));
  if (!(o.step_time >= 0 && o.step_time < o.t_end))
    throw InputError(where("", 0, "step_time", "must lie in [0, t_end)"));
  if (o.azimuths < 1) throw InputError(where("", 0, "azimuths", "must be at least 1"));
}

/// The linear response to the same step by RK4, h = 1 ms (the fastest closed-loop roots of the NREL 5MW
/// are near 40 rad/s), sampled at `time`: the rows `rows` of C x (D u for the wind is kept too).
std::vector<VecX> linearResponse(const StateSpaceModel& cl, int wind, const std::vector<int>& rows,
                                 const std::vector<double>& time, double t0, double step) {
  VecX x = VecX::Zero(cl.A.rows());
  const double h = 1e-3;
  double t = 0;
  std::vector<VecX> out;
  for (double tk : time) {
    for (; t < tk - 1e-12; t += h) {
      const double u = t >= t0 ? step : 0;
      auto f = [&](const VecX& z) -> VecX { return cl.A * z + cl.B.col(wind) * u; };
      const VecX k1 = f(x), k2 = f(x + h / 2 * k1), k3 = f(x + h / 2 * k2), k4 = f(x + h * k3);
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    const double u = tk >= t0 ? step : 0;
    VecX y(rows.size());
    for (size_t i = 0; i < rows.size(); ++i)
      y(static_cast<Eigen::Index>(i)) = cl.C.row(rows[i]).dot(x) + cl.D(rows[i], wind) * u;
    out.push_back(y);
  }
  return out;
}

}  // namespace

ClosedLoopStep closedLoopStep(const Model& m, const RoscoController& c, const SteadyState& st,
                              const ClosedLoopStepOptions& opt) {
  checkOptions(opt);
  if (m.roles.wind_speed_input < 0) throw InputError(where("", 0, "wind speed", "the model has no wind input"));
  std::vector<int> model_outputs;
  for (const std::string& name : opt.outputs) {
    const auto i = m.findOutput(name);
    if (!i) throw InputError(where("", 0, name, "the model has no output of this name"));
    model_outputs.push_back(*i);
  }
  OperatingCondition cond = st.condition;
  cond.generator_torque = st.generator_torque;
  const OperatingPoint start = solveOperatingPoint(m, initialPoint(m, cond));

  SimulationOptions so;
  so.t_end = opt.t_end;
  so.dt_out = opt.dt_out;
  TimeSignal wind;
  wind.kind = TimeSignal::Kind::Step;
  wind.parameters = {opt.step_time, opt.wind_step};
  so.inputs.push_back({m.roles.wind_speed_input, wind});
  so.controller = roscoInTheLoop(m, c, st, opt.controller_dt, start);
  const int pitch_in = so.controller.inputs[1];
  const Simulation sim = simulate(m, start, so);

  ClosedLoopOptions lo;
  lo.azimuths = opt.azimuths;
  lo.frozen_wake = false;
  lo.outputs = opt.outputs;
  if (std::find(lo.outputs.begin(), lo.outputs.end(), lo.ports.speed_output) == lo.outputs.end())
    lo.outputs.push_back(lo.ports.speed_output);  // the loop reads it
  const StateSpaceModel cl = closedLoopPoint(m, st, linearRosco(c, st), lo).closed;
  std::vector<int> rows;
  for (const std::string& name : opt.outputs) rows.push_back(indexOf(cl.y, name));
  rows.push_back(indexOf(cl.y, "controller: collective pitch"));
  const std::vector<VecX> lin = linearResponse(cl, indexOf(cl.u, "wind speed"), rows, sim.time, opt.step_time,
                                               opt.wind_step);

  ClosedLoopStep r;
  r.time = sim.time;
  for (size_t j = 0; j < rows.size(); ++j) {
    ClosedLoopStepSignal s;
    const bool pitch = j == opt.outputs.size();
    s.name = pitch ? "collective pitch" : opt.outputs[j];
    s.unit = pitch ? "rad" : m.outputs[static_cast<size_t>(model_outputs[j])].unit;
    for (size_t k = 0; k < sim.time.size(); ++k) {
      const auto K = static_cast<Eigen::Index>(k);
      const double nl = pitch ? sim.u(K, pitch_in) - sim.u(0, pitch_in)
                              : sim.y(K, model_outputs[j]) - sim.y(0, model_outputs[j]);
      const double li = lin[k](static_cast<Eigen::Index>(j));
      s.nonlinear.push_back(nl);
      s.linear.push_back(li);
      s.peak = std::max(s.peak, std::abs(li));
      s.max_difference = std::max(s.max_difference, std::abs(nl - li));
      if (sim.time[k] <= opt.step_time + opt.early_window)
        s.early_difference = std::max(s.early_difference, std::abs(nl - li));
    }
    r.signals.push_back(std::move(s));
  }
  return r;
}

}  // namespace whirl

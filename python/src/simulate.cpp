// Model.simulate: the computation of `whirl simulate` (src/cli/cmd_simulate.cpp, the same library
// calls in the same order): the start point, initial values, input histories and driven coordinates,
// SUNDIALS IDA, the validity check of the motion; the time series as the columns of timeseries.csv,
// and the files when asked.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>

#include "linearize/point_validity.hpp"
#include "linearize/rosco_step.hpp"
#include "linearize/simulate.hpp"
#include "linearize/simulation_setup.hpp"
#include "python/src/bindings.hpp"
#include "python/src/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/io/text/time_signal_reader.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/timeseries_output.hpp"

namespace whirl::python {
namespace {

// The recorded series in the column order of timeseries.csv (time_s, each coordinate and its rate,
// inputs, outputs): rows are instants.
MatX seriesTable(const Model& m, const Simulation& sim) {
  MatX t(static_cast<Eigen::Index>(sim.time.size()), 1 + 2 * m.ndof() + m.ninput() + m.noutput());
  for (std::size_t r = 0; r < sim.time.size(); ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    Eigen::Index c = 0;
    t(i, c++) = sim.time[r];
    for (int d = 0; d < m.ndof(); ++d) {
      t(i, c++) = sim.q(i, d);
      t(i, c++) = sim.qd(i, d);
    }
    for (int u = 0; u < m.ninput(); ++u) t(i, c++) = sim.u(i, u);
    for (int y = 0; y < m.noutput(); ++y) t(i, c++) = sim.y(i, y);
  }
  return t;
}

// (column names, values, statistics, warning or None)
py::tuple simulateModel(const PyModel& p, double tmax, std::optional<double> rpm, double dt_out,
                        const std::vector<std::pair<std::string, double>>& init,
                        const std::vector<std::pair<std::string, std::string>>& inputs,
                        const std::vector<std::pair<std::string, std::string>>& drives, bool free_rotor,
                        bool equilibrium, double rtol, double atol, bool allow_invalid_point,
                        const std::optional<std::string>& out, const std::vector<std::string>& plot_channels, bool plot,
                        const py::object& progress, std::optional<double> wind, bool closed_loop,
                        double controller_dt) {
  const Model& m = *p.model;
  if (!(tmax > 0)) throw InputError("tmax: simulated time must be positive [s]");
  requireActiveDof(m, m.name);
  OperatingPoint start = rpm ? initialPoint(m, conditionOf(m, rpm, std::nullopt, std::nullopt, std::nullopt))
                             : initialPoint(m);
  SimulationOptions so;
  so.t_end = tmax;
  so.dt_out = dt_out;
  so.rtol = rtol;
  so.atol = atol;
  // The model's unsteady-airfoil and dynamic-inflow states integrated as `whirl simulate` does (the load's
  // unsteady_aero= choice, applied to the model, decides whether there are any).
  so.aero_states = true;
  if (!free_rotor && !wind) so.prescribed = m.roles.azimuth;
  if (!allow_invalid_point) so.stop = stopAtInvalidMotion(m);  // a diverging model stops at its first invalid instant
  // wind=: the trimmed start of `whirl simulate --wind` (with the deck's ROSCO controller), closed_loop=:
  // that controller in the loop (linearize/rosco_step.hpp).
  if (closed_loop && !wind) throw InputError("closed_loop: needs wind= (it starts where ROSCO settles)");
  if (wind) {
    if (rpm || equilibrium) throw InputError("wind: starts at the trimmed state: not with rpm= or equilibrium=");
    const std::optional<RoscoController> controller = deckController(p);
    if (closed_loop && !controller)
      throw InputError(p.source +
                       ": closed_loop needs ROSCO's controller: ServoDyn with VSContrl = 5 and DLL_InFile "
                       "naming its DISCON.IN (docs/user/controller.md)");
    if (!(controller_dt > 0)) throw InputError("controller_dt: must be > 0 [s]");
    const WindStart w = windStart(m, *wind, controller ? &*controller : nullptr);
    start = w.start;
    checkValidity(p, m, {start}, "", allow_invalid_point);
    if (closed_loop) so.controller = roscoInTheLoop(m, *controller, w.steady, controller_dt, start);
  }
  for (const auto& [name, signal] : inputs)
    so.inputs.push_back({simulationInput(m, name, "inputs"), parseTimeSignal(signal, "inputs " + name)});
  for (const auto& [name, signal] : drives) {
    const int i = drivenCoordinate(m, name, "drives");
    so.driven.push_back({i, parseTimeSignal(signal, "drives " + name)});
    so.prescribed.erase(std::remove(so.prescribed.begin(), so.prescribed.end(), i), so.prescribed.end());
  }
  TimeseriesPlotOptions po;
  po.channels = plot_channels;
  po.render = plot;
  po.title = m.name + ": simulation";
  // The progress callback (t, t_end) and Ctrl-C, after each recorded instant; a Python error stops the
  // integration there and is raised again.
  SweepGuard guard(progress);
  so.progress = [&](double t, double t_end) { guard.notify(t, t_end); };
  Simulation sim;
  guard.runSweep(p, [&] {
    if (equilibrium) {
      start = solveOperatingPoint(m, start);
      checkValidity(p, m, {start}, "", allow_invalid_point);
    }
    for (const auto& [name, value] : init) applyInitialCondition(m, start, name, value, "init");
    sim = simulate(m, start, so);
  });
  std::optional<std::string> warning = invalidMotion(m, sim);
  if (warning && !allow_invalid_point)
    throw ComputeError(p.source + ": " + *warning +
                       " (a diverging model; nothing written: allow_invalid_point=True keeps it anyway)");
  if (out) {  // only now the output folder: a failed simulation writes nothing
    prepareOutputFolder(*out);
    writeTimeseries(m, sim, *out, po);
  }
  py::dict stats;
  stats["steps"] = sim.steps;
  stats["residual_evaluations"] = sim.residual_evaluations;
  stats["jacobian_evaluations"] = sim.jacobian_evaluations;
  stats["nonlinear_iterations"] = sim.nonlinear_iterations;
  stats["convergence_failures"] = sim.convergence_failures;
  stats["error_test_failures"] = sim.error_test_failures;
  std::vector<std::string> states;
  for (int s : sim.states) states.push_back(m.dofs[static_cast<std::size_t>(s)].name);
  stats["states"] = states;
  stats["aero_states"] = static_cast<int>(sim.z.cols());
  return py::make_tuple(timeseriesColumns(m), seriesTable(m, sim), stats, warning);
}

}  // namespace

void bindSimulate(py::module_& m) {
  m.def("simulate", &simulateModel, py::arg("model"), py::arg("tmax"), py::arg("rpm") = py::none(),
        py::arg("dt_out") = 0.01, py::arg("init") = std::vector<std::pair<std::string, double>>{},
        py::arg("inputs") = std::vector<std::pair<std::string, std::string>>{},
        py::arg("drives") = std::vector<std::pair<std::string, std::string>>{}, py::arg("free_rotor") = false,
        py::arg("equilibrium") = false, py::arg("rtol") = 1e-6, py::arg("atol") = 1e-8,
        py::arg("allow_invalid_point") = false, py::arg("out") = py::none(),
        py::arg("plot_channels") = std::vector<std::string>{}, py::arg("plot") = true, py::arg("progress") = py::none(),
        py::arg("wind") = py::none(), py::arg("closed_loop") = false, py::arg("controller_dt") = 0.01);
}

}  // namespace whirl::python

// Model.closed_loop: the computation of `whirl campbell --wind … --closed-loop` (the same library calls),
// its tables as the CLI writes them (closed_loop_modes.csv, margins.csv, campbell.csv of the closed and
// of the open loop), which the package reads into DataFrames: the same numbers to the last digit.
#include <pybind11/stl.h>

#include "linearize/trim.hpp"
#include "modal/closed_loop_campbell.hpp"
#include "modal/closed_loop_step.hpp"
#include "python/src/bindings.hpp"
#include "src/base/error.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/closed_loop_step_table.hpp"
#include "src/writers/closed_loop_tables.hpp"

namespace whirl::python {
namespace {

py::dict closedLoop(const PyModel& p, const std::vector<double>& winds, int azimuths, bool without_speed_filter,
                    const py::object& progress) {
  const Model& m = *p.model;
  if (azimuths < 1 || azimuths > 3600) throw InputError("azimuths: must be in 1 … 3600");
  const std::optional<RoscoController> controller = deckController(p);
  if (!controller)
    throw InputError(p.source +
                     ": closed_loop needs ROSCO's controller: ServoDyn with VSContrl = 5 and DLL_InFile "
                     "naming its DISCON.IN (docs/user/controller.md)");
  SweepGuard guard(progress);
  ClosedLoopCampbell c;
  guard.runSweep(p, [&] {
    TrimOptions trim;
    trim.controller = &*controller;
    trim.progress = guard.phase(0);
    const std::vector<SteadyState> schedule = trimSchedule(m, winds, trim);
    ClosedLoopCampbellOptions o;
    o.point.azimuths = azimuths;
    o.controller.without_speed_filter = without_speed_filter;
    o.progress = guard.phase(1);
    c = closedLoopCampbell(m, *controller, schedule, o);
  });
  py::dict out;
  out["modes"] = closedLoopModesCsv(c.points);
  out["margins"] = closedLoopMarginsCsv(c.points);
  out["campbell"] = campbellCsv(c.closed);
  out["open_loop_campbell"] = campbellCsv(c.open);
  return out;
}

/// Model.closed_loop_step: `whirl verify --closed-loop`'s computation, closed_loop_step.csv's text.
std::string closedLoopStepTable(const PyModel& p, double wind, const ClosedLoopStepOptions& so) {
  const Model& m = *p.model;
  const std::optional<RoscoController> controller = deckController(p);
  if (!controller)
    throw InputError(p.source +
                     ": closed_loop_step needs ROSCO's controller: ServoDyn with VSContrl = 5 and "
                     "DLL_InFile naming its DISCON.IN (docs/user/controller.md)");
  std::string csv;
  {
    py::gil_scoped_release release;
    TrimOptions trim;
    trim.controller = &*controller;
    trim.azimuths = so.azimuths;
    const SteadyState st = trimAtWindSpeed(m, wind, trim);
    csv = closedLoopStepCsv(closedLoopStep(m, *controller, st, so), wind, so);
  }
  return csv;
}

}  // namespace

void bindClosedLoop(py::module_& m) {
  m.def(
      "closed_loop_step",
      [](const PyModel& p, double wind, double wind_step, double step_time, double tmax, double dt_out,
         double controller_dt, int azimuths, const std::vector<std::string>& outputs) {
        ClosedLoopStepOptions so;
        so.wind_step = wind_step;
        so.step_time = step_time;
        so.t_end = tmax;
        so.dt_out = dt_out;
        so.controller_dt = controller_dt;
        so.azimuths = azimuths;
        so.outputs = outputs;
        return closedLoopStepTable(p, wind, so);
      },
      py::arg("model"), py::arg("wind"), py::arg("wind_step"), py::arg("step_time"), py::arg("tmax"), py::arg("dt_out"),
      py::arg("controller_dt"), py::arg("azimuths"), py::arg("outputs"));
  m.def("closed_loop", &closedLoop, py::arg("model"), py::arg("wind"), py::arg("azimuths") = 36,
        py::arg("without_speed_filter") = false, py::arg("progress") = py::none());
}

}  // namespace whirl::python

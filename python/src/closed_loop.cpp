// Model.closed_loop: the computation of `whirl campbell --wind … --closed-loop` (the same library calls),
// its tables as the CLI writes them (closed_loop_modes.csv, margins.csv, campbell.csv of the closed and
// of the open loop), which the package reads into DataFrames: the same numbers to the last digit.
#include <pybind11/stl.h>

#include "linearize/trim.hpp"
#include "modal/closed_loop_campbell.hpp"
#include "python/src/bindings.hpp"
#include "src/model/error.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/closed_loop_tables.hpp"

namespace whirl::python {
namespace {

py::dict closedLoop(const PyModel& p, const std::vector<double>& winds, int azimuths, bool without_speed_filter,
                    const py::object& progress) {
  const Model& m = *p.model;
  if (azimuths < 1 || azimuths > 3600) throw InputError("azimuths: must be in 1 … 3600");
  const std::optional<RoscoController> controller = deckController(p);
  if (!controller)
    throw InputError(p.source + ": closed_loop needs ROSCO's controller: ServoDyn with VSContrl = 5 and DLL_InFile "
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

}  // namespace

void bindClosedLoop(py::module_& m) {
  m.def("closed_loop", &closedLoop, py::arg("model"), py::arg("wind"), py::arg("azimuths") = 36,
        py::arg("without_speed_filter") = false, py::arg("progress") = py::none());
}

}  // namespace whirl::python

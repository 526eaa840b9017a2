// whirl._whirl.StateSpace and Model.linearize: the state-space model `whirl export` writes for one
// operating point (the same exportSweep call, so the matrices equal the .mat file's to the last
// bit), and the second-order matrices M, C, K, Q of `whirl linearize` at its equilibrium.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "linearize/export_sweep.hpp"
#include "linearize/linearize.hpp"
#include "linearize/trim.hpp"
#include "python/src/bindings.hpp"
#include "python/src/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/state_space_files.hpp"

namespace whirl::python {
namespace {

/// A linearization: the state-space model (multiblade average for a rotor of 3+ blades), the
/// per-azimuth models in the rotating frame, and the second-order model at the equilibrium.
struct PyLinear {
  ExportPoint point;
  LinearModel second_order;  ///< empty for the points of Model.export (has_second_order false)
  bool has_second_order = false;
  double seconds = 0;  ///< wall time of the library's computation (GIL released) [s]
};

py::list variables(const std::vector<StateSpaceVariable>& v) {
  py::list rows;
  for (const StateSpaceVariable& s : v)
    rows.append(
        py::dict(py::arg("name") = s.name, py::arg("unit") = s.unit, py::arg("op") = s.op, py::arg("blade") = s.blade));
  return rows;
}

// Matrices as read-only numpy views of the C++ object's storage (Eigen's column-major layout: an
// F-ordered array), kept alive by the Python object that owns them.
template <class T, class Get>
void matrixProperty(py::class_<T>& c, const char* name, Get get, const char* doc) {
  c.def_property_readonly(name, get, py::return_value_policy::reference_internal, doc);
}

// Built on the heap and handed to Python as is: no move of the per-azimuth models into a new object.
std::unique_ptr<PyLinear> linearizeAt(const PyModel& p, const py::object& op, int azimuths,
                                      const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                                      bool drop_azimuth) {
  SweepPoint sp;
  if (op.is_none()) {
    sp.condition = modelCondition(*p.model);
  } else {
    const auto& o = op.cast<const PyOperatingPoint&>();
    if (o.model != p.model) throw InputError("linearize: the operating point belongs to another model");
    sp.condition = o.condition;
    sp.wind_speed = o.wind_speed;
    sp.pitch_deg = o.pitch_deg;
  }
  sp.rpm = sp.condition.rotor_speed * 30 / std::numbers::pi;
  if (azimuths < 1 || azimuths > 3600)
    throw InputError("azimuths: must be in 1 … 3600 (is " + std::to_string(azimuths) + ")");
  ExportOptions eo;
  eo.azimuths = azimuths;
  eo.inputs = inputs;
  eo.outputs = outputs;
  eo.drop_azimuth = drop_azimuth;
  SweepOptions sweep;
  sweep.azimuths = azimuths;
  auto out = std::make_unique<PyLinear>();
  runReleased(p, [&] {
    const auto start = std::chrono::steady_clock::now();
    out->point = std::move(exportSweep(*p.model, {sp}, eo, sweep).front());
    out->second_order = linearize(*p.model, out->point.equilibrium);
    out->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  out->has_second_order = true;
  return out;
}

// `whirl export` (src/cli/cmd_export.cpp): the points of --rpm, --schedule or --wind (trimmed, with
// the deck's ROSCO controller when it has one), exportSweep over them with the commands' validity
// check, and the files of --format into `out` when asked (one OutputSet: all files or none).
std::vector<PyLinear> exportPoints(const PyModel& p, const std::optional<std::vector<double>>& rpm,
                                   const std::optional<std::vector<double>>& wind, const py::object& schedule,
                                   int azimuths, const std::vector<std::string>& inputs,
                                   const std::vector<std::string>& outputs, bool drop_azimuth,
                                   const py::object& progress, bool allow_invalid_point,
                                   const std::optional<std::string>& format, const std::optional<std::string>& out) {
  const Model& m = *p.model;
  if (bool(rpm) + bool(wind) + !schedule.is_none() > 1)
    throw InputError("export: give at most one of rpm=, wind= and schedule=");
  if (azimuths < 1 || azimuths > 3600)
    throw InputError("azimuths: must be in 1 … 3600 (is " + std::to_string(azimuths) + ")");
  if (format && *format != "mat" && *format != "lin" && *format != "json")
    throw InputError("format: must be mat, lin or json (is '" + *format + "')");
  if (bool(format) != bool(out)) throw InputError("export: give format= and out= together to write files");
  std::vector<SweepPoint> points;
  if (rpm) {
    for (double r : *rpm) {
      SweepPoint sp;
      sp.condition = conditionOf(m, r, std::nullopt, std::nullopt, std::nullopt);
      sp.rpm = sp.condition.rotor_speed * 30 / std::numbers::pi;
      points.push_back(sp);
    }
  } else if (!schedule.is_none()) {
    points = schedulePoints(schedule);
    if (m.roles.azimuth.empty())
      throw InputError("rpm: the model has no rotating DOF (mark the azimuth with `rotating: true`)");
  } else if (!wind) {
    SweepPoint sp;  // the model's own condition
    sp.condition = modelCondition(m);
    sp.rpm = sp.condition.rotor_speed * 30 / std::numbers::pi;
    points.push_back(sp);
  }
  const std::optional<RoscoController> controller = wind ? deckController(p) : std::nullopt;
  if (out) prepareOutputFolder(*out);
  ExportOptions eo;
  eo.azimuths = azimuths;
  eo.inputs = inputs;
  eo.outputs = outputs;
  eo.drop_azimuth = drop_azimuth;
  SweepGuard guard(progress);
  SweepOptions sweep;
  sweep.azimuths = azimuths;
  sweep.progress = wind ? guard.phase(1) : guard.progress();
  const bool labelled = !schedule.is_none() || wind || (rpm && rpm->size() > 1);
  sweep.check_point = [&](const Model& pm, const std::vector<OperatingPoint>& ops, const SweepPoint& sp) {
    return checkValidity(p, pm, ops, labelled ? fmt::format("{:g} rpm", sp.rpm) : "", allow_invalid_point);
  };
  StateSpaceExport e;
  e.source = p.source;
  e.model_name = m.name;
  guard.runSweep(p, [&] {
    if (wind) {
      TrimOptions trim;
      if (controller) trim.controller = &*controller;
      trim.progress = guard.phase(0);
      for (const SteadyState& s : trimSchedule(m, *wind, trim)) points.push_back(sweepPointOf(s));
    }
    e.points = exportSweep(m, points, eo, sweep);
  });
  if (out) {
    OutputSet files(*out);                                                // every file at once, or none
    std::string title = e.model_name.substr(0, e.model_name.find(". "));  // as `whirl export`
    if (title.empty()) title = e.source;
    writeStateSpaceFiles(e, *format, title, files);
    files.commit();
  }
  std::vector<PyLinear> result;
  for (ExportPoint& pt : e.points) result.push_back(PyLinear{std::move(pt), {}, false});
  return result;
}

}  // namespace

void bindLinear(py::module_& m) {
  py::class_<StateSpaceModel> ss(m, "StateSpace", "ẋ = A x + B u, y = C x + D u about an operating point.");
  matrixProperty(
      ss, "A", [](const StateSpaceModel& s) -> const MatX& { return s.A; }, "state matrix (nx × nx)");
  matrixProperty(
      ss, "B", [](const StateSpaceModel& s) -> const MatX& { return s.B; }, "input matrix (nx × nu)");
  matrixProperty(
      ss, "C", [](const StateSpaceModel& s) -> const MatX& { return s.C; }, "output matrix (ny × nx)");
  matrixProperty(
      ss, "D", [](const StateSpaceModel& s) -> const MatX& { return s.D; }, "feedthrough (ny × nu)");
  matrixProperty(
      ss, "xdot_op", [](const StateSpaceModel& s) -> const VecX& { return s.xdot_op; }, "ẋ at the point");
  ss.def("states", [](const StateSpaceModel& s) { return variables(s.x); })
      .def("inputs", [](const StateSpaceModel& s) { return variables(s.u); })
      .def("outputs", [](const StateSpaceModel& s) { return variables(s.y); })
      .def_readonly("azimuth", &StateSpaceModel::azimuth)
      .def_readonly("rotor_speed", &StateSpaceModel::rotor_speed)
      .def_readonly("multiblade", &StateSpaceModel::multiblade);

  py::class_<PyLinear> lin(m, "Linearization", "The linear models at one operating point.");
  lin.def_property_readonly(
         "state_space", [](const PyLinear& l) -> const StateSpaceModel& { return l.point.model; },
         py::return_value_policy::reference_internal)
      .def_property_readonly(
          "per_azimuth", [](const PyLinear& l) -> const std::vector<StateSpaceModel>& { return l.point.azimuths; },
          py::return_value_policy::reference_internal)
      .def_property_readonly("rpm", [](const PyLinear& l) { return l.point.rpm; })
      .def_property_readonly("wind_speed", [](const PyLinear& l) { return l.point.wind_speed; })
      .def_property_readonly("pitch_deg", [](const PyLinear& l) { return l.point.pitch_deg; })
      .def_readonly("has_second_order", &PyLinear::has_second_order)
      .def_readonly("seconds", &PyLinear::seconds,
                    "wall time of the library's computation [s], without the Python call around it")
      .def_property_readonly("dof_names", [](const PyLinear& l) { return l.second_order.dof_names; })
      .def_property_readonly("second_order_inputs", [](const PyLinear& l) { return l.second_order.input_names; });
  matrixProperty(
      lin, "M", [](const PyLinear& l) -> const MatX& { return l.second_order.M; }, "mass matrix");
  matrixProperty(
      lin, "damping", [](const PyLinear& l) -> const MatX& { return l.second_order.C; }, "damping matrix");
  matrixProperty(
      lin, "K", [](const PyLinear& l) -> const MatX& { return l.second_order.K; }, "stiffness matrix");
  matrixProperty(
      lin, "Q", [](const PyLinear& l) -> const MatX& { return l.second_order.Q; }, "input matrix");

  m.def("linearize", &linearizeAt, py::arg("model"), py::arg("op") = py::none(), py::arg("azimuths") = 36,
        py::arg("inputs") = std::vector<std::string>{}, py::arg("outputs") = std::vector<std::string>{},
        py::arg("drop_azimuth") = false);
  m.def("export", &exportPoints, py::arg("model"), py::arg("rpm") = py::none(), py::arg("wind") = py::none(),
        py::arg("schedule") = py::none(), py::arg("azimuths") = 36, py::arg("inputs") = std::vector<std::string>{},
        py::arg("outputs") = std::vector<std::string>{}, py::arg("drop_azimuth") = false,
        py::arg("progress") = py::none(), py::arg("allow_invalid_point") = false, py::arg("format") = py::none(),
        py::arg("out") = py::none());
}

}  // namespace whirl::python

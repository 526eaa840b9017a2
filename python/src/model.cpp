// whirl._whirl.Model: loading (a case path with --set overrides, or a case's YAML text), the model's
// coordinates, inputs and outputs with units, and its operating points.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "linearize/operating_point.hpp"
#include "linearize/state_space.hpp"
#include "python/src/bindings.hpp"
#include "python/src/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/turbine/load_model.hpp"

namespace whirl::python {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// The Python module builds linear models from every model: None → as the deck asks, True → required,
// False → quasi-steady (the command line's --unsteady-aero / --quasi-steady-aero).
UnsteadyAeroChoice unsteadyAeroChoice(std::optional<bool> unsteady_aero) {
  if (!unsteady_aero) return UnsteadyAeroChoice::as_deck;
  return *unsteady_aero ? UnsteadyAeroChoice::required : UnsteadyAeroChoice::off;
}

PyModel load(const std::string& path, const std::vector<std::string>& sets, bool allow_outside_files,
             std::optional<bool> unsteady_aero) {
  PyModel m;
  m.source = path;
  m.sets = sets;
  py::gil_scoped_release released;
  Model model = loadCaseModel(path, sets, allow_outside_files, &m.notes);
  applyUnsteadyAeroChoice(model, unsteadyAeroChoice(unsteady_aero), path, &m.notes, true);
  m.model = std::make_shared<const Model>(std::move(model));
  return m;
}

// A case's YAML text (the package writes a dict as JSON, which is YAML): no file, the same reader.
PyModel loadText(const std::string& text, const std::string& folder, const std::vector<std::string>& sets,
                 bool allow_outside_files, std::optional<bool> unsteady_aero) {
  PyModel m;
  m.source = "<dict>";
  m.sets = sets;
  py::gil_scoped_release released;
  std::vector<CaseOverride> overrides;
  for (const auto& s : sets) overrides.push_back(parseOverride(s));
  Model model = readCaseText(text, m.source, folder, overrides, allow_outside_files);
  requireActiveDof(model, m.source);
  applyUnsteadyAeroChoice(model, unsteadyAeroChoice(unsteady_aero), m.source, &m.notes, true);
  m.model = std::make_shared<const Model>(std::move(model));
  return m;
}

py::list dofTable(const Model& m) {
  py::list rows;
  for (int i = 0; i < m.ndof(); ++i) {
    const Dof& d = m.dofs[static_cast<std::size_t>(i)];
    rows.append(py::dict(py::arg("name") = d.name, py::arg("unit") = dofUnit(m, i),
                         py::arg("body") = m.bodies[static_cast<std::size_t>(d.body)].name,
                         py::arg("kind") = d.kind == DofKind::Joint ? "joint" : "elastic", py::arg("frozen") = d.frozen,
                         py::arg("rotating") = d.rotating, py::arg("blade") = d.blade, py::arg("value") = d.value,
                         py::arg("rate") = d.rate));
  }
  return rows;
}

py::list inputTable(const Model& m) {
  py::list rows;
  for (const Input& in : m.inputs)
    rows.append(py::dict(py::arg("name") = in.name, py::arg("unit") = in.unit, py::arg("value") = in.value,
                         py::arg("blade") = in.blade));
  return rows;
}

py::list outputTable(const Model& m) {
  py::list rows;
  for (const Output& out : m.outputs)
    rows.append(py::dict(py::arg("name") = out.name, py::arg("unit") = out.unit, py::arg("blade") = out.blade));
  return rows;
}

py::list bodyTable(const Model& m) {
  py::list rows;
  for (const Body& b : m.bodies)
    rows.append(py::dict(py::arg("name") = b.name,
                         py::arg("parent") = b.parent < 0 ? std::string("ground")
                                                          : m.bodies[static_cast<std::size_t>(b.parent)].name));
  return rows;
}

}  // namespace

std::optional<RoscoController> deckController(const PyModel& p) { return p.model->deck_controller; }

OperatingCondition conditionOf(const Model& m, std::optional<double> rpm, std::optional<double> wind,
                               std::optional<double> pitch_deg, std::optional<double> azimuth_deg) {
  OperatingCondition c = modelCondition(m);
  if (rpm) {
    // The CLI's --rpm rules and messages (src/cli/common.cpp, operatingCondition).
    if (!std::isfinite(*rpm) || *rpm < 0)
      throw InputError("rpm: rotor speed must be finite and not negative (is " + fmt::format("{:g}", *rpm) +
                       "); whirl's rotors turn in the positive sense of their azimuth, as a schedule requires");
    if (m.roles.azimuth.empty())
      throw InputError("rpm: the model has no rotating DOF (mark the azimuth with `rotating: true`)");
    c.rotor_speed = rpmToRadPerSec(*rpm);
  }
  if (wind) c.wind_speed = *wind;
  if (pitch_deg) c.collective_pitch = *pitch_deg * kDeg;
  if (azimuth_deg) c.azimuth = *azimuth_deg * kDeg;
  return c;
}

void bindModel(py::module_& m) {
  py::class_<PyModel>(m, "Model", "A finalized model (read-only); see whirl.Model for the documented API.")
      .def_readonly("source", &PyModel::source)
      .def_readonly("notes", &PyModel::notes)
      .def_property_readonly("name", [](const PyModel& p) { return p.model->name; })
      .def_property_readonly("has_aero", [](const PyModel& p) { return p.model->aero.active(); })
      .def("dofs", [](const PyModel& p) { return dofTable(*p.model); })
      .def("inputs", [](const PyModel& p) { return inputTable(*p.model); })
      .def("outputs", [](const PyModel& p) { return outputTable(*p.model); })
      .def("bodies", [](const PyModel& p) { return bodyTable(*p.model); })
      .def(
          "operating_point",
          [](const PyModel& p, std::optional<double> rpm, std::optional<double> wind, std::optional<double> pitch,
             std::optional<double> azimuth) {
            PyOperatingPoint op;
            op.model = p.model;
            op.condition = conditionOf(*p.model, rpm, wind, pitch, azimuth);
            op.rpm = op.condition.rotor_speed * 30 / std::numbers::pi;
            op.wind_speed = wind;
            op.pitch_deg = pitch;
            runReleased(p, [&] { op.point = solveOperatingPoint(*p.model, initialPoint(*p.model, op.condition)); });
            return op;
          },
          py::arg("rpm") = py::none(), py::arg("wind") = py::none(), py::arg("pitch") = py::none(),
          py::arg("azimuth") = py::none());

  py::class_<PyOperatingPoint>(m, "OperatingPoint", "A solved equilibrium at an operating condition.")
      .def_readonly("rpm", &PyOperatingPoint::rpm, "rotor speed [rpm]")
      .def_readonly("wind_speed", &PyOperatingPoint::wind_speed, "hub-height wind speed [m/s] as given, or None")
      .def_readonly("pitch_deg", &PyOperatingPoint::pitch_deg, "collective pitch [deg] as given, or None")
      .def_property_readonly(
          "q", [](const PyOperatingPoint& o) -> const VecX& { return o.point.q; },
          py::return_value_policy::reference_internal,
          "coordinates at the equilibrium, all DOFs in model order [m or rad] (read-only view)")
      .def_property_readonly(
          "qd", [](const PyOperatingPoint& o) -> const VecX& { return o.point.qd; },
          py::return_value_policy::reference_internal,
          "their rates [m/s or rad/s]: the rotor speed on rotating DOFs (read-only view)")
      .def_property_readonly(
          "u", [](const PyOperatingPoint& o) -> const VecX& { return o.point.u; },
          py::return_value_policy::reference_internal,
          "inputs at the point, in the units of Model.inputs (read-only view)")
      .def_property_readonly(
          "iterations", [](const PyOperatingPoint& o) { return o.point.iterations; },
          "Newton iterations of the equilibrium")
      .def_property_readonly(
          "residual_norm", [](const PyOperatingPoint& o) { return o.point.residual_norm; },
          "norm of the residual at the equilibrium [N, N m]");

  m.def("load", &load, py::arg("path"), py::arg("sets") = std::vector<std::string>{},
        py::arg("allow_outside_files") = false, py::arg("unsteady_aero") = std::nullopt);
  m.def("load_text", &loadText, py::arg("text"), py::arg("folder") = ".", py::arg("sets") = std::vector<std::string>{},
        py::arg("allow_outside_files") = false, py::arg("unsteady_aero") = std::nullopt);
}

}  // namespace whirl::python

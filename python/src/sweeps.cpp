// Model.steady, Model.campbell and Model.modes: the computations of `whirl steady`, `whirl campbell`
// and `whirl modes` (the same library calls in the same order), their results as columns for the
// package's DataFrames.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <numbers>

#include "linearize/periodic.hpp"
#include "linearize/point_validity.hpp"
#include "linearize/trim.hpp"
#include "modal/campbell_diagram.hpp"
#include "modal/lin_modes.hpp"
#include "modal/rotor_modes.hpp"
#include "modal/tracking.hpp"
#include "python/src/bindings.hpp"
#include "python/src/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/io/text/schedule.hpp"
#include "src/writers/steady_table.hpp"

namespace whirl::python {
namespace {

py::dict steady(const PyModel& p, const std::vector<double>& winds, int azimuths, const py::object& progress) {
  const Model& m = *p.model;
  if (!m.aero.active())
    throw InputError(p.source + ": the model has no aerodynamics (an OpenFAST deck with CompAero = 2)");
  if (azimuths < 1 || azimuths > 360) throw InputError("azimuths: must be in 1 … 360");
  TrimOptions trim;
  trim.azimuths = azimuths;
  // The deck's ROSCO controller, when it names one, as `whirl steady` (docs/user/controller.md).
  const std::optional<RoscoController> controller = deckController(p);
  if (controller) trim.controller = &*controller;
  SweepGuard guard(progress);
  trim.progress = guard.progress();
  std::vector<SteadyState> states;
  guard.runSweep(p, [&] { states = trimSchedule(m, winds, trim); });
  const std::vector<std::string>& names = steadyColumns();
  std::vector<std::vector<double>> columns(names.size() - 1);
  std::vector<std::string> region;
  for (const SteadyState& s : states) {
    const SteadyRow r = steadyRow(m, s);
    for (std::size_t c = 0; c < r.values.size(); ++c) columns[c].push_back(r.values[c]);
    region.push_back(r.region);
  }
  py::dict out;
  for (std::size_t c = 0; c + 1 < names.size(); ++c) out[py::str(names[c])] = columns[c];
  out[py::str(names.back())] = region;
  return out;
}

// One row per point and line with a mode there, in campbell.csv's order (points in sweep order,
// lines in line order), with what campbell_modes.json adds per mode.
py::dict campbellColumns(const CampbellDiagram& d, bool participations) {
  std::vector<int> point;
  std::vector<double> rpm, wind, pitch, freq, damped, zeta;
  std::vector<std::string> name;
  std::vector<bool> rigid, first_order, stable;
  std::vector<std::string> coords;  // union of the points' coordinates, first seen first
  for (const CampbellPoint& pt : d.points)
    for (const std::string& c : pt.coordinates)
      if (std::find(coords.begin(), coords.end(), c) == coords.end()) coords.push_back(c);
  std::vector<std::vector<double>> part(participations ? coords.size() : 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < d.points.size(); ++k) {
    const CampbellPoint& pt = d.points[k];
    for (const CampbellLine& line : d.lines) {
      if (line.mode[k] < 0) continue;
      const Mode& md = pt.modes[static_cast<std::size_t>(line.mode[k])];
      point.push_back(static_cast<int>(k));
      rpm.push_back(pt.rpm);
      wind.push_back(pt.wind_speed.value_or(nan));
      pitch.push_back(pt.pitch_deg.value_or(nan));
      name.push_back(line.name);
      freq.push_back(md.freq_hz);
      damped.push_back(md.damped_freq_hz);
      zeta.push_back(md.damping_ratio);
      rigid.push_back(md.rigid_body);
      first_order.push_back(md.first_order);
      stable.push_back(md.rigid_body || !(md.damping_ratio < 0));
      for (std::size_t c = 0; c < part.size(); ++c) {
        const auto at = std::find(pt.coordinates.begin(), pt.coordinates.end(), coords[c]);
        part[c].push_back(at == pt.coordinates.end() ? nan : md.participation(at - pt.coordinates.begin()));
      }
    }
  }
  py::dict out;
  out["point"] = point;
  out["rpm"] = rpm;
  out["wind_speed"] = wind;
  out["pitch_deg"] = pitch;
  out["mode"] = name;
  out["freq_hz"] = freq;
  out["damped_freq_hz"] = damped;
  out["damping_ratio"] = zeta;
  out["stable"] = stable;
  out["rigid_body"] = rigid;
  out["first_order"] = first_order;
  for (std::size_t c = 0; c < part.size(); ++c) out[py::str("participation: " + coords[c])] = part[c];
  return out;
}

py::dict campbell(const PyModel& p, const std::optional<std::vector<double>>& rpm,
                  const std::optional<std::vector<double>>& wind, const py::object& schedule, int azimuths,
                  const py::object& progress, bool participations, bool allow_invalid_point) {
  const Model& m = *p.model;
  if (!rpm + !wind + schedule.is_none() != 2)
    throw InputError("campbell: give exactly one of rpm=, wind= and schedule=");
  if (azimuths < 1 || azimuths > 3600) throw InputError("azimuths: must be in 1 … 3600");
  std::vector<SweepPoint> points;
  if (rpm)
    for (double r : *rpm) points.push_back(sweepPoint(r));
  else if (!schedule.is_none()) points = schedulePoints(schedule);
  const std::optional<RoscoController> controller = wind ? deckController(p) : std::nullopt;
  SweepGuard guard(progress);
  SweepOptions sweep;
  sweep.azimuths = azimuths;
  sweep.progress = wind ? guard.phase(1) : guard.progress();
  sweep.check_point = [&](const Model& pm, const std::vector<OperatingPoint>& ops, const SweepPoint& sp) {
    return checkValidity(p, pm, ops, fmt::format("{:g} rpm", sp.rpm), allow_invalid_point);
  };
  CampbellDiagram d;
  guard.runSweep(p, [&] {
    if (wind) {  // each wind speed trimmed, as `whirl campbell --wind` (trimmedPoints, the deck's controller)
      TrimOptions trim;
      if (controller) trim.controller = &*controller;
      trim.progress = guard.phase(0);
      for (const SteadyState& s : trimSchedule(m, *wind, trim)) points.push_back(sweepPointOf(s));
    }
    CampbellDiagramOptions cd;
    cd.sweep = sweep;
    d = campbellDiagram(m, points, cd);
  });
  return campbellColumns(d, participations);
}

int bladeCount(const Model& m) {
  int nb = 0;
  for (int i : m.activeDofs()) nb = std::max(nb, m.dofs[static_cast<std::size_t>(i)].blade + 1);
  return nb;
}

py::dict modeColumns(const std::vector<Mode>& modes, const std::vector<std::string>& coords) {
  std::vector<int> index;
  std::vector<std::string> name;
  std::vector<double> freq, damped, zeta;
  std::vector<bool> rigid, first_order;
  std::vector<std::vector<double>> part(coords.size());
  for (std::size_t k = 0; k < modes.size(); ++k) {
    index.push_back(static_cast<int>(k) + 1);
    name.push_back(modes[k].name);
    freq.push_back(modes[k].freq_hz);
    damped.push_back(modes[k].damped_freq_hz);
    zeta.push_back(modes[k].damping_ratio);
    rigid.push_back(modes[k].rigid_body);
    first_order.push_back(modes[k].first_order);
    for (std::size_t c = 0; c < coords.size(); ++c)
      part[c].push_back(static_cast<Eigen::Index>(c) < modes[k].participation.size()
                            ? modes[k].participation(static_cast<Eigen::Index>(c))
                            : 0.0);
  }
  py::dict out;
  out["index"] = index;
  out["name"] = name;
  out["freq_hz"] = freq;
  out["damped_freq_hz"] = damped;
  out["damping_ratio"] = zeta;
  out["rigid_body"] = rigid;
  out["first_order"] = first_order;
  for (std::size_t c = 0; c < coords.size(); ++c) out[py::str("participation: " + coords[c])] = part[c];
  return out;
}

// `whirl modes` (src/cli/cmd_modes.cpp) with the dense solver: a rotor over the revolution
// (multiblade coordinates, or Floquet for fewer blades), otherwise the eigen of M, C, K.
py::dict modes(const PyModel& p, const py::object& op, int azimuths, bool allow_invalid_point) {
  const Model& m = *p.model;
  if (azimuths < 1 || azimuths > 3600) throw InputError("azimuths: must be in 1 … 3600");
  OperatingCondition condition = modelCondition(m);
  if (!op.is_none()) condition = op.cast<const PyOperatingPoint&>().condition;
  std::vector<Mode> result;
  std::vector<std::string> coords;
  runReleased(p, [&] {
    const OperatingPoint start = initialPoint(m, condition);
    const int teeter = m.roles.teeter_dof;
    if (findAzimuthDof(m) >= 0 &&
        (bladeCount(m) > 0 || (teeter >= 0 && !m.dofs[static_cast<std::size_t>(teeter)].frozen))) {
      PeriodicOptions po;
      po.azimuths = azimuths;
      const PeriodicLinearization lin = linearizePeriodic(m, start, po);
      checkValidity(p, m, lin.points, "", allow_invalid_point);
      RotorModes r = rotorModes(m, lin);
      result = std::move(r.modes);
      coords = std::move(r.coordinates);
      return;
    }
    const OperatingPoint eq = solveOperatingPoint(m, start);
    checkValidity(p, m, {eq}, "", allow_invalid_point);
    const LinearModel lin = linearize(m, eq);
    if (!lin.first_order_names.empty()) {
      RotorModes r = linearModelModes(m, lin, eq.held);
      result = std::move(r.modes);
      coords = std::move(r.coordinates);
      return;
    }
    result = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
    coords = lin.dof_names;
  });
  return modeColumns(result, coords);
}

// `whirl lin` (src/cli/cmd_lin.cpp): the files grouped by operating point, each group's modes in
// multiblade coordinates, tracked over the points; the notes of the transform returned beside.
py::tuple linCampbell(const std::vector<std::string>& files, bool participations) {
  CampbellDiagram d;
  std::vector<std::string> notes;
  {
    py::gil_scoped_release released;
    std::vector<OpenFastLin> lins;
    for (const auto& f : files) lins.push_back(readOpenFastLin(f));
    for (const auto& group : groupLinByOperatingPoint(std::move(lins)))
      d.points.push_back(linCampbellPoint(group, &notes));
    d.lines = trackModes(d.points);
  }
  return py::make_tuple(campbellColumns(d, participations), notes);
}

}  // namespace

std::vector<std::string> checkValidity(const PyModel& p, const Model& m, const std::vector<OperatingPoint>& ops,
                                       const std::string& where, bool allow_invalid_point) {
  std::vector<std::string> problems;
  for (const OperatingPoint& op : ops)
    for (const std::string& s : checkPointValidity(m, op))
      if (std::find(problems.begin(), problems.end(), s) == problems.end()) problems.push_back(s);
  if (!problems.empty() && !allow_invalid_point)
    throw ComputeError(p.source + ": " + (where.empty() ? "" : where + ": ") +
                       "operating point outside the model's range of validity: " + problems.front() +
                       " (check the inputs; allow_invalid_point=True to go on anyway)");
  return problems;
}

std::vector<SweepPoint> schedulePoints(const py::object& schedule) {
  if (py::isinstance<py::str>(schedule)) return readSchedule(schedule.cast<std::string>());
  std::vector<SweepPoint> points;  // rows (rpm, wind speed or None, pitch [deg] or None)
  for (const auto& row : schedule.cast<std::vector<std::tuple<double, std::optional<double>, std::optional<double>>>>())
    points.push_back(sweepPoint(std::get<0>(row), std::get<1>(row), std::get<2>(row)));
  return points;
}

void bindSweeps(py::module_& m) {
  m.def("steady", &steady, py::arg("model"), py::arg("wind"), py::arg("azimuths") = 3,
        py::arg("progress") = py::none());
  m.def("campbell", &campbell, py::arg("model"), py::arg("rpm") = py::none(), py::arg("wind") = py::none(),
        py::arg("schedule") = py::none(), py::arg("azimuths") = 36, py::arg("progress") = py::none(),
        py::arg("participations") = false, py::arg("allow_invalid_point") = false);
  m.def("lin_campbell", &linCampbell, py::arg("files"), py::arg("participations") = false);
  m.def("modes", &modes, py::arg("model"), py::arg("op") = py::none(), py::arg("azimuths") = 36,
        py::arg("allow_invalid_point") = false);
}

}  // namespace whirl::python

// Model.verify: the check of `whirl verify` (modal/nonlinear_check.hpp) — free decays from the equilibrium
// against the linear model there, with the deck's aerodynamic states in both as the command has them — as
// tables: the amplitudes with their differences and observed orders, and the identified frequencies and
// damping next to the eigenvalues (compareWithModes, the command's table).
#include <pybind11/stl.h>

#include <cmath>
#include <optional>

#include "linearize/point_validity.hpp"
#include "modal/nonlinear_check.hpp"
#include "python/src/bindings.hpp"
#include "python/src/operating_point.hpp"
#include "src/base/error.hpp"

namespace whirl::python {
namespace {

// (levels as a dict of columns, identified as a dict of columns, aerodynamic states)
py::tuple verify(const PyModel& p, std::optional<double> rpm, const std::vector<std::string>& dofs, double amplitude,
                 int levels, double tmax, double dt_out, bool allow_invalid_point) {
  const Model& m = *p.model;
  requireActiveDof(m, m.name);
  NonlinearCheckOptions co;
  co.amplitude = amplitude;
  co.levels = levels;
  co.t_end = tmax;
  co.dt_out = dt_out;
  co.aero_states = true;    // the model's states, as whirl.load(..., unsteady_aero=) chose
  requireCheckOptions(co);  // before the operating point is solved
  for (const std::string& name : dofs) {
    const auto i = m.findDof(name);
    if (!i) throw InputError("dofs: '" + name + "': no such coordinate");
    co.dofs.push_back(*i);
  }
  const OperatingCondition c = conditionOf(m, rpm, std::nullopt, std::nullopt, std::nullopt);
  NonlinearCheck check;
  runReleased(p, [&] {
    const OperatingPoint eq = solveOperatingPoint(m, initialPoint(m, c));
    checkValidity(p, m, {eq}, "", allow_invalid_point);
    check = checkAgainstLinear(m, eq, co);
  });
  std::vector<double> amp, diff, resp, order;
  for (size_t k = 0; k < check.levels.size(); ++k) {
    amp.push_back(check.levels[k].amplitude);
    diff.push_back(check.levels[k].max_difference);
    resp.push_back(check.levels[k].max_response);
    order.push_back(k == 0 ? NAN : check.orders[k - 1]);
  }
  py::dict lv;
  lv["amplitude"] = amp;
  lv["max_difference"] = diff;
  lv["max_response"] = resp;
  lv["order"] = order;
  std::vector<std::string> coordinate, mode;
  std::vector<double> f, z, fr, zr, fm, zm;
  for (const IdentifiedComparison& r : compareWithModes(m, check)) {
    const Mode* best = r.mode >= 0 ? &check.modes[static_cast<size_t>(r.mode)] : nullptr;
    coordinate.push_back(r.coordinate);
    f.push_back(r.decay.damped_freq_hz);
    z.push_back(r.decay.damping_ratio);
    fr.push_back(r.pole ? r.pole->damped_freq_hz : NAN);
    zr.push_back(r.pole ? r.pole->damping_ratio : NAN);
    mode.push_back(best ? best->name : "");
    fm.push_back(best ? best->damped_freq_hz : NAN);
    zm.push_back(best ? best->damping_ratio : NAN);
  }
  py::dict id;
  id["coordinate"] = coordinate;
  id["damped_freq_hz"] = f;
  id["damping_ratio"] = z;
  id["realized_freq_hz"] = fr;
  id["realized_damping_ratio"] = zr;
  id["mode"] = mode;
  id["mode_damped_freq_hz"] = fm;
  id["mode_damping_ratio"] = zm;
  return py::make_tuple(lv, id, check.aero_states);
}

}  // namespace

void bindVerify(py::module_& m) {
  m.def("verify", &verify, py::arg("model"), py::arg("rpm") = py::none(), py::arg("dofs") = std::vector<std::string>{},
        py::arg("amplitude") = 0.01, py::arg("levels") = 3, py::arg("tmax") = 10.0, py::arg("dt_out") = 0.01,
        py::arg("allow_invalid_point") = false);
}

}  // namespace whirl::python

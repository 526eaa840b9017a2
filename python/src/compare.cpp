// whirl.compare: modes matched with a reference table and checked (`whirl compare`,
// modal/mode_compare.hpp): from CSV files as the command reads them, or from the package's tables.
#include <pybind11/stl.h>

#include <cmath>

#include "modal/mode_compare.hpp"
#include "python/src/bindings.hpp"
#include "src/base/error.hpp"

namespace whirl::python {
namespace {

std::vector<NamedFrequency> resultModes(const py::object& result, std::optional<double> rpm) {
  if (py::isinstance<py::str>(result)) return readResultModes(result.cast<std::string>(), rpm);
  std::vector<NamedFrequency> modes;  // rows (name, frequency [Hz]) of a table, already at one point
  for (const auto& [name, f] : result.cast<std::vector<std::pair<std::string, double>>>()) modes.push_back({name, f});
  if (modes.empty()) throw InputError("result: no modes" + std::string(rpm ? " at that rpm" : ""));
  return modes;
}

std::vector<ReferenceMode> referenceModes(const py::object& reference) {
  if (py::isinstance<py::str>(reference)) return readReferenceModes(reference.cast<std::string>());
  std::vector<ReferenceMode> rows;  // rows (mode, frequency [Hz], whirl mode)
  for (const auto& [mode, f, whirl_mode] : reference.cast<std::vector<std::tuple<std::string, double, std::string>>>())
    rows.push_back({mode, f, whirl_mode});
  return rows;
}

py::dict compare(const py::object& result, const py::object& reference, double tol_rel, std::optional<double> rpm) {
  if (!std::isfinite(tol_rel) || tol_rel < 0)
    throw InputError("tol_rel: must be a finite number >= 0 (is " + std::to_string(tol_rel) + ")");
  if (rpm && !std::isfinite(*rpm)) throw InputError("rpm: must be a finite number");
  const std::vector<ModeComparison> rows = compareModes(resultModes(result, rpm), referenceModes(reference), tol_rel);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> mode, whirl_mode, status;
  std::vector<double> ref_f, f, err;
  for (const ModeComparison& c : rows) {
    mode.push_back(c.reference.mode);
    ref_f.push_back(c.reference.freq_hz);
    whirl_mode.push_back(c.match ? c.match->name : "");
    f.push_back(c.match ? c.match->freq_hz : nan);
    err.push_back(c.match ? c.rel_error : nan);
    status.push_back(!c.match ? "MISSING" : c.ok ? "ok" : "FAIL");
  }
  py::dict out;
  out["reference_mode"] = mode;
  out["reference_freq_hz"] = ref_f;
  out["whirl_mode"] = whirl_mode;
  out["freq_hz"] = f;
  out["rel_error"] = err;
  out["status"] = status;
  return out;
}

}  // namespace

void bindCompare(py::module_& m) {
  m.def("compare", &compare, py::arg("result"), py::arg("reference"), py::arg("tol_rel") = 0.01,
        py::arg("rpm") = py::none());
}

}  // namespace whirl::python

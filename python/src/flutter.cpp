// Model.flutter: the search of `whirl flutter` (modal/flutter_search.hpp, the library call the command makes),
// with the validity check of every rotor speed's points as the command does it.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>

#include "modal/flutter_search.hpp"
#include "python/src/bindings.hpp"

namespace whirl::python {
namespace {

// (points as a dict of columns, onset dict or None)
py::tuple flutter(const PyModel& p, double wind, std::optional<double> rpm_min, std::optional<double> rpm_max,
                  double rpm_step, double tolerance, double min_freq, int azimuths, bool allow_invalid_point,
                  const py::object& progress) {
  const Model& m = *p.model;
  FlutterSearchOptions so;
  so.wind = wind;
  setRotorSpeedRange(m, rpm_min, rpm_max, so);
  so.rpm_step = rpm_step;
  so.tolerance = tolerance;
  so.min_freq = min_freq;
  so.azimuths = azimuths;
  FlutterCallbacks cb;
  cb.check = [&](const PeriodicLinearization& lin, double rpm) {
    checkValidity(p, m, lin.points, fmt::format("{:g} rpm", rpm), allow_invalid_point);
  };
  // progress(rpm, damping_ratio) after each rotor speed; a Python error there, or Ctrl-C, stops the search.
  SweepGuard guard(progress);
  cb.progress = [&](const FlutterPoint& l) { guard.notify(l.rpm, l.damping); };
  FlutterSearch s;
  guard.runSweep(p, [&] { s = flutterSearch(m, so, cb); });
  py::dict table;
  std::vector<double> rpm, freq, damping;
  std::vector<std::string> mode;
  for (const FlutterPoint& l : s.points) {
    rpm.push_back(l.rpm);
    mode.push_back(l.mode);
    freq.push_back(l.freq_hz);
    damping.push_back(l.damping);
  }
  table["rpm"] = rpm;
  table["least_damped_mode"] = mode;
  table["frequency_hz"] = freq;
  table["damping_ratio"] = damping;
  py::object onset = py::none();
  if (s.onset) {
    py::dict o;
    o["rpm"] = s.onset->rpm;
    o["mode"] = s.onset->mode;
    o["frequency_hz"] = s.onset->freq_hz;
    onset = o;
  }
  return py::make_tuple(table, onset);
}

}  // namespace

void bindFlutter(py::module_& m) {
  m.def("flutter", &flutter, py::arg("model"), py::arg("wind") = 0.0, py::arg("rpm_min") = py::none(),
        py::arg("rpm_max") = py::none(), py::arg("rpm_step") = 1.0, py::arg("tolerance") = 0.01,
        py::arg("min_freq") = 0.1, py::arg("azimuths") = 36, py::arg("allow_invalid_point") = false,
        py::arg("progress") = py::none());
}

}  // namespace whirl::python

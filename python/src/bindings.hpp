#pragma once
/// \file
/// What the binding files of the Python module share: the model as Python sees it (the library's
/// Model with where it came from), the sweep guard (progress callback, Ctrl-C) and the one place
/// errors of a model's computation get the case in front of their message, as the CLI does
/// (src/cli/common.cpp, runWithCaseSource).
#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "linearize/operating_point.hpp"
#include "linearize/sweep.hpp"
#include "src/model/model.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl::python {

namespace py = pybind11;

/// A loaded model: immutable once built, shared by every result that needs it.
struct PyModel {
  std::shared_ptr<const Model> model;
  std::string source;              ///< the case path, or "<dict>" for a case built from a Python dict
  std::vector<std::string> notes;  ///< the readers' informational lines (the CLI's `whirl: note:`)
  std::vector<std::string> sets;   ///< the `--set KEY=VALUE` overrides it was loaded with
};

/// Runs `f` with the GIL released; a ComputeError comes back with the model's source in front of its
/// message ("CASE: operating point did not converge …"), as the command line says it.
void runReleased(const PyModel& m, const std::function<void()>& f);

/// Progress and interruption of a sweep. progress() gives the library's callback: it takes the GIL,
/// calls the Python callback (done, total) when there is one and checks for a pending signal
/// (Ctrl-C). A Python exception there (KeyboardInterrupt included) stops the sweep at the end of the
/// current operating point and is raised again by runSweep.
class SweepGuard {
 public:
  explicit SweepGuard(py::object callback) : callback_(std::move(callback)) {}
  std::function<void(int, int)> progress();
  /// The callback of a sweep in two phases (trimming the wind speeds, then the sweep): phase 0 reports
  /// (done, 2 n), phase 1 (n + done, 2 n), so one bar covers both.
  std::function<void(int, int)> phase(int index);
  /// Runs the sweep `f` with the GIL released (runReleased) and re-raises a Python error of the callback.
  void runSweep(const PyModel& m, const std::function<void()>& f);
  /// From inside runSweep: calls the Python callback with `args` (the GIL taken) when there is one and checks
  /// for Ctrl-C; a Python error there stops the computation at this call (runSweep raises it again).
  template <class... A>
  void notify(const A&... args) {
    guarded([&] {
      if (!callback_.is_none()) callback_(args...);
    });
  }

 private:
  void guarded(const std::function<void()>& call);
  py::object callback_;
  bool stopped_ = false;
};

/// The validity check of the commands (src/cli/common.cpp, checkSolvedPoints): the problems of the
/// solved points, the first one a ComputeError naming the model (and `where`) unless allowed.
std::vector<std::string> checkValidity(const PyModel& p, const Model& m, const std::vector<OperatingPoint>& ops,
                                       const std::string& where, bool allow_invalid_point);

/// The ROSCO controller of the model's deck, as the commands read it along the wind
/// (Model::deck_controller, read with the deck and its overrides); none for a YAML case or a dict.
std::optional<RoscoController> deckController(const PyModel& p);

/// The sweep points of a schedule: a CSV path (readSchedule), or rows (rpm, wind speed or None,
/// pitch [deg] or None) from a DataFrame.
std::vector<SweepPoint> schedulePoints(const py::object& schedule);

void bindErrors(py::module_& m);
void bindModel(py::module_& m);
void bindLinear(py::module_& m);
void bindSweeps(py::module_& m);
void bindBode(py::module_& m);
void bindSimulate(py::module_& m);
void bindCompare(py::module_& m);
void bindClosedLoop(py::module_& m);
void bindFlutter(py::module_& m);
void bindVerify(py::module_& m);

}  // namespace whirl::python

// Errors: InputError and ComputeError become Python exceptions with the library's message, which is
// the CLI's `whirl: error: <message>` without the prefix; the sweep guard and the GIL release.
#include <Python.h>

#include "python/src/bindings.hpp"
#include "src/base/error.hpp"

namespace whirl::python {

void runReleased(const PyModel& m, const std::function<void()>& f) {
  try {
    py::gil_scoped_release released;
    f();
  } catch (const ComputeError& e) {
    const std::string what = e.what();
    if (what.rfind(m.source + ":", 0) == 0) throw;  // already named
    throw ComputeError(m.source + ": " + what);
  }
}

void SweepGuard::guarded(const std::function<void()>& call) {
  py::gil_scoped_acquire acquired;
  try {
    call();
  } catch (py::error_already_set& e) {
    e.restore();  // raised again by runSweep, after the library has unwound
    stopped_ = true;
    throw std::runtime_error("stopped by the progress callback");
  }
  if (PyErr_CheckSignals() != 0) {  // Ctrl-C: the KeyboardInterrupt is now the pending error
    stopped_ = true;
    throw std::runtime_error("interrupted");
  }
}

std::function<void(int, int)> SweepGuard::progress() {
  return [this](int done, int total) { notify(done, total); };
}

std::function<void(int, int)> SweepGuard::phase(int index) {
  std::function<void(int, int)> f = progress();
  return [f, index](int done, int total) { f(index * total + done, 2 * total); };
}

void SweepGuard::runSweep(const PyModel& m, const std::function<void()>& f) {
  try {
    runReleased(m, f);
  } catch (...) {
    if (stopped_) throw py::error_already_set();  // the callback's error, pending since restore()
    throw;
  }
}

void bindErrors(py::module_& m) {
  // ValueError and RuntimeError as bases: code that catches those keeps working.
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<ComputeError>(m, "ComputeError", PyExc_RuntimeError);
}

}  // namespace whirl::python

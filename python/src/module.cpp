// The extension module whirl._whirl: the library's models and analyses for the Python package
// python/whirl/, which builds the tables and plots on top of it.
#include <pybind11/pybind11.h>

#include "python/src/bindings.hpp"

PYBIND11_MODULE(_whirl, m) {
  m.doc() =
      "whirl's C++ library: models, operating points, linearization, modes and Campbell sweeps. "
      "Use the package `whirl`, which wraps this module.";
#ifdef WHIRL_VERSION
  m.attr("__version__") = WHIRL_VERSION;
#endif
  whirl::python::bindErrors(m);
  whirl::python::bindModel(m);
  whirl::python::bindLinear(m);
  whirl::python::bindSweeps(m);
  whirl::python::bindBode(m);
  whirl::python::bindSimulate(m);
  whirl::python::bindCompare(m);
  whirl::python::bindClosedLoop(m);
  whirl::python::bindFlutter(m);
  whirl::python::bindVerify(m);
}

// Model.bode: the computation of `whirl bode` (src/cli/cmd_bode.cpp, the same library calls in the
// same order), its table as columns for the package's DataFrame, bode.csv and bode.gp when asked.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <numbers>

#include "linearize/export_point.hpp"
#include "linearize/frequency_response.hpp"
#include "linearize/trim.hpp"
#include "python/src/bindings.hpp"
#include "python/src/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/writers/bode_table.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::python {
namespace {

// (frequencies [Hz], column names, values (frequency × column), static gains, title)
py::tuple bode(const PyModel& p, const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
               std::optional<double> rpm, std::optional<double> wind, double f0, double f1, int points, int azimuths,
               bool allow_invalid_point, const std::optional<std::string>& out, bool plot) {
  const Model& m = *p.model;
  if (inputs.empty() || outputs.empty()) throw InputError("bode: give inputs= and outputs=");
  if (points < 2 || points > 100000) throw InputError("points: must be in 2 … 100000");
  const std::vector<double> f = logFrequencies(f0, f1, points);
  if (azimuths < 1 || azimuths > 3600) throw InputError("azimuths: must be in 1 … 3600");
  if (wind && rpm) throw InputError("bode: give wind= (trimmed) or rpm=, not both");
  ExportOptions eo;
  eo.azimuths = azimuths;
  eo.inputs = inputs;
  eo.outputs = outputs;
  eo.drop_azimuth = true;  // the rigid azimuth is a pure integrator of the rotor speed
  OperatingCondition c = conditionOf(m, rpm, std::nullopt, std::nullopt, std::nullopt);
  std::vector<Eigen::MatrixXcd> G;
  Eigen::MatrixXcd G0;
  StateSpaceModel model;
  runReleased(p, [&] {
    if (wind) c = trimAtWindSpeed(m, *wind).condition;
    ExportPoint pt = exportOperatingPoint(m, initialPoint(m, c), eo);
    checkValidity(p, m, {pt.equilibrium}, "", allow_invalid_point);
    G = frequencyResponse(pt.model, f);
    G0 = frequencyResponse(pt.model, {1e-9}).front();  // the static gain, as the CLI prints it
    model = std::move(pt.model);
  });
  std::string title = "Frequency response";
  if (wind)
    title += fmt::format(": {:g} m/s, {:.3f} rpm, pitch {:.2f} deg", *wind, c.rotor_speed * 30 / std::numbers::pi,
                         c.collective_pitch.value_or(0) * 180 / std::numbers::pi);
  if (out) {
    prepareOutputFolder(*out);
    OutputSet files(*out);  // table, script and images together
    files.write("bode.csv", bodeCsv(model, f, G));
    files.write("bode.gp", bodeGnuplotScript(title, static_cast<int>(model.y.size() * model.u.size())));
    if (plot) renderGnuplot(files.stagingFolder(), "gnuplot", "bode", *out);
    files.commit();
  }
  py::dict gain;
  for (Eigen::Index i = 0; i < G0.rows(); ++i)
    for (Eigen::Index j = 0; j < G0.cols(); ++j)
      gain[py::str(model.y[static_cast<std::size_t>(i)].name + " / " + model.u[static_cast<std::size_t>(j)].name)] =
          G0(i, j).real();
  return py::make_tuple(f, bodeColumns(model), bodeValues(G), gain, title);
}

}  // namespace

void bindBode(py::module_& m) {
  m.def("bode", &bode, py::arg("model"), py::arg("inputs"), py::arg("outputs"), py::arg("rpm") = py::none(),
        py::arg("wind") = py::none(), py::arg("f_from") = 0.01, py::arg("f_to") = 10.0, py::arg("points") = 400,
        py::arg("azimuths") = 36, py::arg("allow_invalid_point") = false, py::arg("out") = py::none(),
        py::arg("plot") = true);
}

}  // namespace whirl::python

// `whirl bode`: the frequency response of the linear model at one operating point — for a controller
// designer, how the chosen outputs (generator speed, tower-top acceleration, …) answer the inputs
// (wind speed, collective pitch, generator torque, …).
#include <CLI/CLI.hpp>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "linearize/export_point.hpp"
#include "linearize/frequency_response.hpp"
#include "linearize/rosco_linear.hpp"
#include "linearize/trim.hpp"
#include "modal/closed_loop_modes.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/writers/bode_table.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct BodeOptions {
  ModelOptions model;
  std::optional<double> wind;
  std::string inputs, outputs, out;
  double f0 = 0.01, f1 = 10;
  int points = 400, azimuths = 36;
  bool no_plot = false;
  bool closed_loop = false, without_speed_filter = false;
};

void run(const BodeOptions& opt) {
  const Model m = loadModel(opt.model, true);
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  ExportOptions eo;
  eo.azimuths = opt.azimuths;
  eo.inputs = splitList(opt.inputs);
  eo.outputs = splitList(opt.outputs);
  eo.drop_azimuth = true;  // the rigid azimuth is a pure integrator of the rotor speed
  if (eo.inputs.empty() || eo.outputs.empty()) throw InputError("bode: give --inputs and --outputs");
  OperatingCondition c = operatingCondition(m, opt.model);
  std::string where;
  // Trimmed with the deck's ROSCO controller when it has one (docs/user/controller.md).
  if (opt.closed_loop && !opt.wind) throw InputError("bode: --closed-loop needs --wind");
  const std::optional<RoscoController> controller = opt.closed_loop ? closedLoopController(m, opt.model)
                                                                    : m.deck_controller;
  if (opt.without_speed_filter && !opt.closed_loop)
    throw InputError("bode: --without-speed-filter goes with --closed-loop");
  std::optional<SteadyState> steady;
  if (opt.wind) {
    if (opt.model.rpm) throw InputError("bode: give --wind (trimmed) or --rpm, not both");
    TrimOptions trim;
    if (controller) trim.controller = &*controller;
    steady = trimAtWindSpeed(m, *opt.wind, trim);
    c = steady->condition;
    char text[96];
    std::snprintf(text, sizeof text, "%g m/s, %.3f rpm, pitch %.2f deg", *opt.wind,
                  c.rotor_speed * 30 / std::numbers::pi, c.collective_pitch.value_or(0) * 180 / std::numbers::pi);
    where = text;
  }
  ExportPoint p;
  if (opt.closed_loop) {
    // The closed loop's channels by name: the plant's and the controller's commands.
    RoscoLinearOptions ro;
    ro.without_speed_filter = opt.without_speed_filter;
    ClosedLoopOptions clo;
    clo.azimuths = opt.azimuths;
    p.model = selectInputsOutputs(closedLoopPoint(m, *steady, linearRosco(*controller, *steady, ro), clo).closed,
                                  eo.inputs, eo.outputs);
    where += ", closed loop";
  } else {
    p = exportOperatingPoint(m, initialPoint(m, c), eo);
    checkSolvedPoints(opt.model, m, {p.equilibrium});
  }
  const std::vector<double> f = logFrequencies(opt.f0, opt.f1, opt.points);
  const std::vector<Eigen::MatrixXcd> G = frequencyResponse(p.model, f);
  const int pairs = static_cast<int>(p.model.y.size() * p.model.u.size());
  OutputSet files(dir);  // table, script and images together
  files.write("bode.csv", bodeCsv(p.model, f, G));
  files.write("bode.gp",
              bodeGnuplotScript("Frequency response" + (where.empty() ? std::string() : ": " + where), pairs));
  if (!opt.no_plot) renderGnuplot(files.stagingFolder(), "gnuplot", "bode", dir);
  files.commit();
  const std::vector<std::string> written = files.paths();
  // The static gain, signed: G(0) = D − C A⁻¹ B (at 0 Hz, whether or not the plot starts there).
  const Eigen::MatrixXcd G0 = frequencyResponse(p.model, {1e-9}).front();
  std::printf("static gain (SI units):\n");
  for (Eigen::Index i = 0; i < G0.rows(); ++i)
    for (Eigen::Index j = 0; j < G0.cols(); ++j)
      std::printf("  %s / %s: %.6g\n", p.model.y[static_cast<std::size_t>(i)].name.c_str(),
                  p.model.u[static_cast<std::size_t>(j)].name.c_str(), G0(i, j).real());
  std::printf("wrote");
  for (const auto& w : written) std::printf(" %s", w.c_str());
  std::printf("\n");
}

}  // namespace

void addBodeCommand(CLI::App& app) {
  auto opt = std::make_shared<BodeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bode",
      "Frequency response (Bode diagram) of the linear model at one operating point, azimuth-averaged in multiblade "
      "coordinates without the azimuth integrator: writes bode.csv, bode.gp and PNG/SVG");
  addModelOptions(*cmd, opt->model, true);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--wind", opt->wind, "trimmed operating point at this wind speed [m/s] (aerodynamic models)");
  cmd->add_option("--inputs", opt->inputs, "inputs, comma-separated (e.g. 'wind speed,collective pitch')")->required();
  cmd->add_option("--outputs", opt->outputs, "outputs, comma-separated (e.g. GenSpeed)")->required();
  cmd->add_option("--from", opt->f0, "lowest frequency [Hz]")->check(CLI::PositiveNumber);
  cmd->add_option("--to", opt->f1, "highest frequency [Hz]")->check(CLI::PositiveNumber);
  cmd->add_option("--points", opt->points, "number of frequencies")->check(CLI::Range(2, 100000));
  addMultibladeAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->add_flag("--closed-loop", opt->closed_loop,
                "with --wind on a deck with ROSCO's controller: the closed loop's response (outputs also "
                "'controller: generator torque', 'controller: collective pitch')");
  cmd->add_flag("--without-speed-filter", opt->without_speed_filter,
                "with --closed-loop: leave the controller's generator-speed low pass out");
  cmd->add_flag("--no-plot", opt->no_plot, "write the table and the Gnuplot script, do not run Gnuplot");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli

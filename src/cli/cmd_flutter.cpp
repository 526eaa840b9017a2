// `whirl flutter CASE`: the rotor speed at which a mode's damping first crosses zero (classical
// flutter of the blades: torsion coalescing with flap), searched beyond rated in still air or at a
// given wind speed with the pitch held (modal/flutter_search.hpp); prints each point and the onset,
// writes flutter.csv.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <optional>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "modal/flutter_search.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/writers/atomic_file.hpp"

namespace whirl::cli {
namespace {

struct FlutterOptions {
  ModelOptions model;
  double wind = 0;                ///< hub-height wind speed [m/s]
  std::optional<double> rpm_min;  ///< first rotor speed [rpm]; none: the deck's initial rotor speed
  std::optional<double> rpm_max;  ///< last rotor speed [rpm]; none: 3 × the first
  double rpm_step = 1;            ///< step of the search before bisection [rpm]
  double tolerance = 0.01;        ///< width of the final bracket [rpm]
  double min_freq = 0.1;          ///< modes below this frequency are not flutter candidates [Hz]
  int azimuths = 36;
  std::string out;
};

void printPoint(const FlutterPoint& l) {
  std::fprintf(stderr, "flutter: %8.4f rpm  least damped %-28s %8.4f Hz  damping %+.4f %%\n", l.rpm, l.mode.c_str(),
               l.freq_hz, 100 * l.damping);
}

void run(const FlutterOptions& opt) {
  const Model m = loadModel(opt.model, true);
  FlutterSearchOptions so;
  so.wind = opt.wind;
  setRotorSpeedRange(m, opt.rpm_min, opt.rpm_max, so);
  so.rpm_step = opt.rpm_step;
  so.tolerance = opt.tolerance;
  so.min_freq = opt.min_freq;
  so.azimuths = opt.azimuths;
  const auto start = std::chrono::steady_clock::now();
  FlutterCallbacks cb;
  cb.check = [&](const PeriodicLinearization& lin, double rpm) {
    checkSolvedPoints(opt.model, m, lin.points, fmt::format("{:g} rpm", rpm));
  };
  cb.progress = printPoint;
  const FlutterSearch s = flutterSearch(m, so, cb);
  std::string table = "rpm,least_damped_mode,frequency_hz,damping_ratio\n";
  for (const FlutterPoint& l : s.points)
    table += fmt::format("{:.6g},{},{:.6g},{:.6g}\n", l.rpm, l.mode, l.freq_hz, l.damping);
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  ensureWritableFolder(dir);
  if (!s.onset) {
    const FlutterPoint& last = s.points.back();
    writeFileAtomic(dir + "/flutter.csv", table);
    std::printf("no flutter up to %g rpm (least damping %.4g %% at %g rpm, %s); wrote %s/flutter.csv\n", so.rpm_max,
                100 * last.damping, last.rpm, last.mode.c_str(), dir.c_str());
    return;
  }
  table += fmt::format("# onset,{},{:.6g},{:.6g}\n", s.onset->mode, s.onset->freq_hz, s.onset->rpm);
  writeFileAtomic(dir + "/flutter.csv", table);
  std::printf(
      "flutter onset %.3f rpm: %s at %.4f Hz (%.2f x the first rotor speed %g rpm); wrote %s/flutter.csv, "
      "%.1f s\n",
      s.onset->rpm, s.onset->mode.c_str(), s.onset->freq_hz, s.onset->rpm / so.rpm_min, so.rpm_min, dir.c_str(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

void addFlutterCommand(CLI::App& app) {
  auto opt = std::make_shared<FlutterOptions>();
  CLI::App* cmd = app.add_subcommand(
      "flutter",
      "flutter search: the rotor speed raised beyond rated (still air, or --wind with the pitch held) until a "
      "mode's damping crosses zero, then bisected; prints the onset speed, frequency and mode, writes flutter.csv");
  addModelOptions(*cmd, opt->model, false);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--wind", opt->wind, "hub-height wind speed [m/s] (default 0: still air)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--rpm-min", opt->rpm_min, "first rotor speed [rpm] (default: the deck's RotSpeed)");
  cmd->add_option("--rpm-max", opt->rpm_max, "last rotor speed searched [rpm] (default: 3 x the first)");
  cmd->add_option("--rpm-step", opt->rpm_step, "rotor-speed step before the bisection [rpm]")
      ->check(CLI::Range(1e-3, 1e3));
  cmd->add_option("--tolerance", opt->tolerance, "width of the final bracket [rpm]")->check(CLI::Range(1e-6, 1e3));
  cmd->add_option("--min-freq", opt->min_freq, "modes below this frequency are not candidates [Hz]")
      ->check(CLI::Range(0.0, 1e3));
  addMultibladeAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli

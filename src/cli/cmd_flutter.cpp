// `whirl flutter CASE`: the rotor speed at which a mode's damping first crosses zero (classical
// flutter of the blades: torsion coalescing with flap), searched beyond rated in still air or at a
// given wind speed with the pitch held. Each rotor speed is a periodic linearization averaged in
// multiblade coordinates (the path of `whirl modes`); the search steps the rotor speed up until the
// least-damped mode is unstable, then bisects on the rotor speed (the flutter limit as the rotor speed
// of zero damping, as in Hansen 2007, "Aeroelastic instability problems for wind turbines").
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/model/operating_condition.hpp"
#include "src/writers/atomic_file.hpp"

namespace whirl::cli {
namespace {

struct FlutterOptions {
  ModelOptions model;
  double wind = 0;          ///< hub-height wind speed [m/s]
  double rpm_min = -1;      ///< first rotor speed [rpm]; < 0: the deck's initial rotor speed
  double rpm_max = -1;      ///< last rotor speed [rpm]; < 0: 3 × the first
  double rpm_step = 1;      ///< step of the search before bisection [rpm]
  double tolerance = 0.01;  ///< width of the final bracket [rpm]
  double min_freq = 0.1;    ///< modes below this frequency are not flutter candidates [Hz]
  int azimuths = 36;
  std::string out;
};

/// The least-damped oscillating mode at one rotor speed.
struct Least {
  double rpm = 0;
  double damping = std::numeric_limits<double>::infinity();  ///< damping ratio [-]
  double freq_hz = 0;
  std::string name;
};

Least leastDamped(const Model& m, const FlutterOptions& opt, double rpm) {
  OperatingCondition c = modelCondition(m);
  c.rotor_speed = rpmToRadPerSec(rpm);
  if (m.roles.wind_speed_input >= 0) c.wind_speed = opt.wind;
  PeriodicOptions p;
  p.azimuths = opt.azimuths;
  const PeriodicLinearization lin = linearizePeriodic(m, c, p);
  checkSolvedPoints(opt.model, m, lin.points, fmt::format("{:g} rpm", rpm));
  const RotorModes r = rotorModes(m, lin);
  Least out;
  out.rpm = rpm;
  // Rigid-body roots (the free rotor) and first-order roots are no flutter candidates, nor are the slow
  // drivetrain and controller roots below min_freq (their damping is the torque law's, not the blades').
  for (const Mode& mode : r.modes)
    if (!mode.rigid_body && !mode.first_order && mode.freq_hz >= opt.min_freq && mode.damping_ratio < out.damping) {
      out.damping = mode.damping_ratio;
      out.freq_hz = mode.damped_freq_hz;
      out.name = mode.name;
    }
  if (out.name.empty())
    throw ComputeError(fmt::format("flutter: no oscillating mode above {:g} Hz at {:g} rpm", opt.min_freq, rpm));
  return out;
}

void printPoint(const Least& l) {
  std::fprintf(stderr, "flutter: %8.4f rpm  least damped %-28s %8.4f Hz  damping %+.4f %%\n", l.rpm, l.name.c_str(),
               l.freq_hz, 100 * l.damping);
}

void run(const FlutterOptions& opt) {
  const Model m = loadModel(opt.model, true);
  if (findAzimuthDof(m) < 0) throw InputError("flutter: the model has no rotor (no rotating coordinate)");
  const double first = opt.rpm_min >= 0 ? opt.rpm_min : modelCondition(m).rotor_speed * 30 / std::numbers::pi;
  const double last = opt.rpm_max > 0 ? opt.rpm_max : 3 * first;
  if (!(first > 0) || !(last > first))
    throw InputError(
        fmt::format("flutter: the rotor speeds {:g} to {:g} rpm are not an increasing range above 0 "
                    "(--rpm-min, --rpm-max)",
                    first, last));
  const auto start = std::chrono::steady_clock::now();
  std::string table = "rpm,least_damped_mode,frequency_hz,damping_ratio\n";
  auto add = [&](const Least& l) {
    printPoint(l);
    table += fmt::format("{:.6g},{},{:.6g},{:.6g}\n", l.rpm, l.name, l.freq_hz, l.damping);
  };
  Least below = leastDamped(m, opt, first);
  add(below);
  if (below.damping < 0)
    throw ComputeError(
        fmt::format("flutter: {} is already unstable at the first rotor speed {:g} rpm "
                    "(damping {:.3g} %): start lower with --rpm-min",
                    below.name, first, 100 * below.damping));
  std::optional<Least> above;
  for (double rpm = first + opt.rpm_step; rpm <= last + 1e-9 && !above; rpm += opt.rpm_step) {
    const Least l = leastDamped(m, opt, rpm);
    add(l);
    if (l.damping < 0) above = l;
    else below = l;
  }
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  ensureWritableFolder(dir);
  if (!above) {
    writeFileAtomic(dir + "/flutter.csv", table);
    std::printf("no flutter up to %g rpm (least damping %.4g %% at %g rpm, %s); wrote %s/flutter.csv\n", last,
                100 * below.damping, below.rpm, below.name.c_str(), dir.c_str());
    return;
  }
  // Bisection on the rotor speed: the least damping is continuous in it, negative above, positive below.
  while (above->rpm - below.rpm > opt.tolerance) {
    const Least mid = leastDamped(m, opt, 0.5 * (below.rpm + above->rpm));
    add(mid);
    if (mid.damping < 0) above = mid;
    else below = mid;
  }
  // The onset: zero damping interpolated linearly in the final bracket.
  const double t = below.damping / (below.damping - above->damping);
  const double onset = below.rpm + t * (above->rpm - below.rpm);
  const double freq = below.freq_hz + t * (above->freq_hz - below.freq_hz);
  table += fmt::format("# onset,{},{:.6g},{:.6g}\n", above->name, freq, onset);
  writeFileAtomic(dir + "/flutter.csv", table);
  std::printf(
      "flutter onset %.3f rpm: %s at %.4f Hz (%.2f x the first rotor speed %g rpm); wrote %s/flutter.csv, "
      "%.1f s\n",
      onset, above->name.c_str(), freq, onset / first, first, dir.c_str(),
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

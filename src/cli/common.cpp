#include "src/cli/common.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "linearize/load_jump.hpp"
#include "linearize/point_validity.hpp"
#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/parallel/session.hpp"
#include "src/turbine/load_model.hpp"

namespace whirl::cli {

void addModelOptions(CLI::App& cmd, ModelOptions& opt, bool with_rpm) {
  cmd.add_option("CASE", opt.case_path, "case: YAML case file, OpenFAST .fst or ElastoDyn .dat")->required();
  cmd.add_option("--set", opt.sets,
                 "override KEY=VALUE (repeatable): a dotted path of the YAML case, or an OpenFAST key; "
                 "gravity=G for both");
  if (with_rpm) cmd.add_option("--rpm", opt.rpm, "rotor speed [rpm]: the rate of every DOF marked rotating");
  cmd.add_flag("--allow-invalid-point", opt.allow_invalid_point,
               "go on (with a warning) when the solved operating point, or a simulated motion, leaves the model's "
               "range of validity (deflection > 0.3 body length, elastic slope > 0.5 rad, residual not small)");
  cmd.add_flag("--allow-outside-files", opt.allow_outside_files,
               "let a YAML case's `file:` entries name files outside the case folder");
}

void addAeroStateOptions(CLI::App& cmd, ModelOptions& opt) {
  CLI::Option* qs = cmd.add_flag("--quasi-steady-aero", opt.quasi_steady_aero,
                                 "leave the deck's unsteady-airfoil states (AeroDyn UA_Mod 4 or 6) and dynamic-inflow "
                                 "states (DBEMT_Mod 3) out of the linear models: the static polar on the frozen wake, "
                                 "as with UA_Mod 0 and DBEMT_Mod -1");
  cmd.add_flag("--unsteady-aero", opt.unsteady_aero,
               "insist on the deck's unsteady-airfoil states (UA_Mod 4 or 6; in the linear models by default): "
               "refuse a deck without them")
      ->excludes(qs);
}

CLI::Option* addMultibladeAzimuths(CLI::App& cmd, int& azimuths) {
  return cmd.add_option("--azimuths", azimuths, "azimuths per revolution: periodic linearization, multiblade average")
      ->check(CLI::Range(1, 3600));
}

CLI::Option* addTrimAzimuths(CLI::App& cmd, int& azimuths) {
  return cmd.add_option("--azimuths", azimuths, "equilibria per point, over one blade passage")
      ->check(CLI::Range(1, 360));
}

OperatingCondition operatingCondition(const Model& m, const ModelOptions& opt) {
  OperatingCondition c = modelCondition(m);
  if (opt.rpm) {
    if (!std::isfinite(*opt.rpm) || *opt.rpm < 0)
      throw InputError("--rpm: rotor speed must be finite and not negative (is " + fmt::format("{:g}", *opt.rpm) +
                       "); whirl's rotors turn in the positive sense of their azimuth, as a schedule requires");
    if (m.roles.azimuth.empty())
      throw InputError("--rpm: the model has no rotating DOF (mark the azimuth with `rotating: true`)");
    c.rotor_speed = rpmToRadPerSec(*opt.rpm);
  }
  return c;
}

OperatingPoint startPoint(const Model& m, const ModelOptions& opt) {
  return opt.rpm ? initialPoint(m, operatingCondition(m, opt)) : initialPoint(m);
}

bool isYamlCase(const std::string& path) { return isYamlCasePath(path); }

Model loadModel(const ModelOptions& opt, bool linear_model) {
  std::vector<std::string> notes;
  Model m = loadCaseModel(opt.case_path, opt.sets, opt.allow_outside_files, &notes);
  const UnsteadyAeroChoice choice = opt.unsteady_aero       ? UnsteadyAeroChoice::required
                                    : opt.quasi_steady_aero ? UnsteadyAeroChoice::off
                                                            : UnsteadyAeroChoice::as_deck;
  applyUnsteadyAeroChoice(m, choice, opt.case_path, &notes, linear_model);
  if (parallel::rank() == 0)
    for (const std::string& n : notes) std::fprintf(stderr, "whirl: note: %s\n", escapeControlCharacters(n).c_str());
  return m;
}

std::vector<std::string> checkSolvedPoints(const ModelOptions& opt, const Model& model,
                                           const std::vector<OperatingPoint>& points, const std::string& where) {
  std::vector<std::string> problems;
  std::size_t geometric = 0, elements = 0, points_with = 0, on_jump = 0;
  const OperatingPoint* largest_jump = nullptr;
  for (const OperatingPoint& op : points) {
    if (op.load_jump.dof >= 0) {
      ++on_jump;
      if (!largest_jump || op.load_jump.size / op.load_scale > largest_jump->load_jump.size / largest_jump->load_scale)
        largest_jump = &op;
    }
    for (const std::string& p : checkPointValidity(model, op))
      if (std::find(problems.begin(), problems.end(), p) == problems.end()) problems.push_back(p);
    const auto n = static_cast<std::size_t>(std::count_if(op.aero.elements.begin(), op.aero.elements.end(),
                                                          [](const AeroElementState& e) { return !e.bem_valid; }));
    geometric += n;
    elements += op.aero.elements.size();
    points_with += n > 0;
  }
  // AeroDyn's informational message, once per call (a sweep calls per operating condition): the
  // elements are not an error there either.
  if (geometric > 0 && parallel::rank() == 0)
    std::fprintf(stderr,
                 "whirl: note: %s: %s%zu of %zu blade elements at %zu of %zu operating points have no valid BEM "
                 "inflow angle (in-plane wind against the rotation, e.g. at the root in yaw); they take the geometric "
                 "inflow angle without induction, as AeroDyn does\n",
                 escapeControlCharacters(opt.case_path).c_str(),
                 where.empty() ? "" : (escapeControlCharacters(where) + ": ").c_str(), geometric, elements, points_with,
                 points.size());
  if (largest_jump && parallel::rank() == 0)
    std::fprintf(stderr,
                 "whirl: note: %s: %sat %zu of %zu operating points the equilibrium lies on a jump of the loads, "
                 "taken on the side with the smaller residual (a Filippov equilibrium); the largest: %s\n",
                 escapeControlCharacters(opt.case_path).c_str(),
                 where.empty() ? "" : (escapeControlCharacters(where) + ": ").c_str(), on_jump, points.size(),
                 escapeControlCharacters(describe(model, largest_jump->load_jump)).c_str());
  if (problems.empty()) return problems;
  const std::string prefix = opt.case_path + ": " + (where.empty() ? "" : where + ": ");
  if (!opt.allow_invalid_point)
    throw ComputeError(prefix + "operating point outside the model's range of validity: " + problems.front() +
                       " (check the inputs; --allow-invalid-point to go on anyway)");
  if (parallel::rank() == 0)
    for (const std::string& p : problems)
      std::fprintf(stderr, "whirl: warning: %s%s\n", prefix.c_str(), escapeControlCharacters(p).c_str());
  return problems;
}

void runWithCaseSource(const std::string& case_path, const std::function<void()>& run) {
  try {
    run();
  } catch (const ComputeError& e) {
    const std::string what = e.what();
    if (what.rfind(case_path + ":", 0) == 0) throw;  // already named
    throw ComputeError(case_path + ": " + what);
  }
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    const auto b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
    if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
  }
  return out;
}

std::function<void(int, int)> sweepProgress(const std::string& command) {
  const auto start = std::chrono::steady_clock::now();
  auto printed = std::make_shared<bool>(false);
  // Only on a terminal: the "\r" line is for a person watching, and in a log or a pipe (scripts,
  // the CLI tests) it would appear or not depending on how long the sweep took.
  static const bool terminal = isatty(STDERR_FILENO) == 1;
  return [=](int done, int total) {
    if (!terminal) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (s < 1.0 && !*printed) return;
    if (parallel::size() > 1)
      std::fprintf(stderr, "\r%s: %d/%d operating points on rank 0 of %d (%.1f s)", command.c_str(), done, total,
                   parallel::size(), s);
    else std::fprintf(stderr, "\r%s: %d/%d operating points (%.1f s)", command.c_str(), done, total, s);
    *printed = true;
    if (done == total) std::fprintf(stderr, "\n");
  };
}

std::string defaultOutputFolder(const std::string& case_path) {
  return (std::filesystem::path("reports") / std::filesystem::path(case_path).stem()).string();
}

void noteHiddenFirstOrderLines(const CampbellDiagram& d, const CampbellPlotOptions& plot) {
  CampbellPlotOptions all = plot;
  all.max_freq_hz = 0;  // count only what the first-order rule hides
  std::size_t hidden = 0;
  std::string example;
  for (const CampbellLine& line : d.lines)
    if (!campbellLineShown(d, line, all)) {
      ++hidden;
      if (example.empty()) example = line.name;
    }
  if (hidden > 0)
    std::fprintf(stderr,
                 "whirl: note: %zu lines carried by first-order states (e.g. '%s': roots of HydroDyn's radiation "
                 "fit) are in the tables, not drawn; --first-order-lines draws them\n",
                 hidden, withoutControlCharacters(example).c_str());
}

RoscoController closedLoopController(const Model& m, const ModelOptions& opt) {
  std::optional<RoscoController> c = m.deck_controller;
  if (!c)
    throw InputError(opt.case_path +
                     ": --closed-loop needs ROSCO's controller: ServoDyn with VSContrl = 5 and DLL_InFile naming its "
                     "DISCON.IN (docs/user/controller.md)");
  return std::move(*c);
}

}  // namespace whirl::cli

// whirl study: parameter sets (a CSV of --set columns) × operating points, one table.
#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <map>

#include "modal/campbell_sweep.hpp"
#include "modal/tracking.hpp"
#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/text/csv.hpp"
#include "src/io/text/schedule.hpp"
#include "src/parallel/session.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/study_table.hpp"

namespace whirl::cli {
namespace {

struct StudyOptions {
  ModelOptions model;
  std::string params, rpm_range, schedule, out, tracking;
  int azimuths = 36;
};

/// The model of parameter set s: the case's own --set first, then the row's values.
Model loadSet(const StudyOptions& opt, const TextTable& sets, size_t s) {
  ModelOptions mo = opt.model;
  for (size_t c = 0; c < sets.names.size(); ++c) mo.sets.push_back(sets.names[c] + "=" + sets.rows[s][c]);
  try {
    return loadModel(mo, true);
  } catch (const InputError& e) {
    throw InputError(where(sets.file, sets.lines[s], "parameter set " + std::to_string(s + 1), e.what()));
  }
}

void run(const StudyOptions& opt) {
  if (opt.rpm_range.empty() == opt.schedule.empty())
    throw InputError("study: give exactly one of --rpm START:STEP:STOP and --schedule FILE");
  const std::vector<SweepPoint> points = opt.schedule.empty() ? rpmRange(opt.rpm_range) : readSchedule(opt.schedule);
  const TextTable sets = readTextCsv(opt.params);
  if (sets.rows.size() > static_cast<std::size_t>(limits::kMaxStudySets))
    throw InputError(
        where(opt.params, sets.lines[limits::kMaxStudySets], "",
              "more than " + std::to_string(limits::kMaxStudySets) +
                  " parameter sets (src/base/limits.hpp, kMaxStudySets): split the study into several runs"));
  if (sets.names.empty() || sets.rows.empty())
    throw InputError(where(opt.params, 1, "", "needs a header of --set keys and at least one row of values"));
  for (const auto& n : sets.names)
    if (n.empty() || n.find('=') != std::string::npos) throw InputError(where(opt.params, 1, n, "not a --set key"));
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);

  if (parallel::launchedByMpi()) parallel::requirePetsc("mpirun");  // start-up outside the timing
  const auto start = std::chrono::steady_clock::now();
  const size_t S = sets.rows.size(), P = points.size();
  SweepOptions sweep;
  sweep.azimuths = opt.azimuths;
  sweep.check_point = [&opt](const Model& pm, const std::vector<OperatingPoint>& ops, const SweepPoint& sp) {
    return checkSolvedPoints(opt.model, pm, ops, fmt::format("{:g} rpm", sp.rpm));
  };
  std::map<int, Model> models;  // this rank's models, built when its first point of a set comes
  const std::vector<CampbellPoint> all = campbellSweep(
      static_cast<int>(S),
      [&](int s) -> const Model& {
        auto it = models.find(s);
        if (it == models.end()) it = models.emplace(s, loadSet(opt, sets, static_cast<size_t>(s))).first;
        return it->second;
      },
      points, sweep);
  if (parallel::rank() != 0) return;

  TrackingOptions track;
  track.overrides_file = opt.tracking;
  const std::string csv = studyCsv(sets.names, sets.rows, all, track);
  OutputSet files(dir);
  files.write("study.csv", csv);
  files.commit();
  const std::string path = files.paths().front();
  std::printf("wrote %s\n%zu parameter sets x %zu operating points, %.2f s", path.c_str(), S, P,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (parallel::size() > 1) std::printf(" on %d MPI ranks", parallel::size());
  std::printf("\n");
}

}  // namespace

void addStudyCommand(CLI::App& app) {
  auto opt = std::make_shared<StudyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "study",
      "parameter study: every parameter set of --params (a CSV whose columns are --set keys, one row per set) "
      "at every operating point; writes study.csv (set, its values, then the campbell.csv columns)");
  addModelOptions(*cmd, opt->model, false);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--params", opt->params, "CSV of parameter sets: header of --set keys, one row per set")->required();
  cmd->add_option("--rpm", opt->rpm_range, "rotor speeds START:STEP:STOP [rpm]");
  cmd->add_option("--schedule", opt->schedule, "operating schedule CSV (wind speed, RotSpeed, BldPitch columns)");
  addMultibladeAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->add_option("--tracking", opt->tracking, "mode-tracking overrides file, applied to every set");
  cmd->callback([opt]() { runWithCaseSource(opt->model.case_path, [&] { run(*opt); }); });
}

}  // namespace whirl::cli

// `whirl report RESULT_DIR`: the interactive Campbell report (src/writers/campbell_html.hpp) of a folder that
// `whirl campbell` wrote, from its campbell_modes.json; written as RESULT_DIR/campbell.html.
// `whirl report DIR... --side-by-side --out OUT`: the Campbell diagrams of several such folders in one figure,
// one column each, and their first modes tabulated side by side (src/writers/campbell_side_by_side.hpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/writers/campbell_csv_input.hpp"
#include "src/writers/campbell_html.hpp"
#include "src/writers/campbell_side_by_side.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct ReportOptions {
  std::vector<std::string> dirs;
  std::string versus = "auto";
  double max_freq = 0;
  bool side_by_side = false;
  std::vector<std::string> labels;
  std::string out;
  double max_damping = 0;
  bool no_plot = false;
};

void runHtml(const ReportOptions& opt) {
  const std::string dir = opt.dirs.front();
  const std::string path = (std::filesystem::path(dir) / "campbell_modes.json").string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where(path, 0, "", "not found: give a folder written by whirl campbell"));
  std::ostringstream text;
  text << in.rdbuf();
  CampbellReportOptions r;
  r.max_freq_hz = opt.max_freq;
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  std::size_t points = 0, lines = 0;
  bool all_wind = true;
  if (j.is_object() && j.contains("points") && j["points"].is_array()) {
    points = j["points"].size();
    for (const auto& p : j["points"])
      all_wind = all_wind && p.is_object() && p.contains("wind_speed") && p["wind_speed"].is_number();
  }
  if (j.is_object() && j.contains("lines") && j["lines"].is_array()) lines = j["lines"].size();
  r.versus_wind_speed = opt.versus == "wind" || (opt.versus == "auto" && all_wind && points > 0);
  r.summary = {{"result folder", dir}, {"operating points", std::to_string(points)}, {"lines", std::to_string(lines)}};
  r.steady_csv = steadyCsvIn(dir);
  const std::string page = campbellHtml(text.str(), r, path);
  prepareOutputFolder(dir);
  OutputSet files(dir);
  files.write("campbell.html", page);
  files.commit();
  std::printf("wrote %s\n", (std::filesystem::path(dir) / "campbell.html").string().c_str());
}

/// The columns of the side-by-side figure: every folder's campbell.csv, read before anything is written,
/// titled with its --label (the folder's name without labels).
std::vector<SideBySideColumn> sideBySideColumns(const ReportOptions& opt) {
  if (!opt.labels.empty() && opt.labels.size() != opt.dirs.size())
    throw InputError(where("", 0, "--label",
                           std::to_string(opt.labels.size()) + " labels for " + std::to_string(opt.dirs.size()) +
                               " result folders: give one per folder, in the same order"));
  std::vector<SideBySideColumn> columns;
  for (std::size_t k = 0; k < opt.dirs.size(); ++k) {
    const std::filesystem::path dir(opt.dirs[k]);
    const std::string csv = (dir / "campbell.csv").string();
    if (!std::filesystem::is_regular_file(csv))
      throw InputError(where(csv, 0, "", "not found: give a folder written by whirl campbell"));
    const std::string name = dir.filename().empty() ? dir.parent_path().filename().string() : dir.filename().string();
    columns.push_back({opt.labels.empty() ? name : opt.labels[k], readCampbellCsv(csv)});
  }
  return columns;
}

void runSideBySide(const ReportOptions& opt) {
  if (opt.out.empty())
    throw InputError(where("", 0, "--out", "missing: --side-by-side writes its figure into a folder of its own"));
  SideBySideOptions s;
  const std::vector<SideBySideColumn> columns = sideBySideColumns(opt);
  bool all_wind = true;
  for (const SideBySideColumn& c : columns)
    for (const CampbellCsvPoint& p : c.result.points) all_wind = all_wind && p.wind_speed.has_value();
  s.versus_wind_speed = opt.versus == "wind" || (opt.versus == "auto" && all_wind);
  s.max_freq_hz = opt.max_freq;
  s.max_damping_percent = opt.max_damping;
  s.render = !opt.no_plot;
  for (const std::string& path : writeCampbellSideBySide(columns, opt.out, s)) std::printf("wrote %s\n", path.c_str());
}

void run(const ReportOptions& opt) {
  if (opt.side_by_side) return runSideBySide(opt);
  if (opt.dirs.size() != 1)
    throw InputError(
        where("", 0, "RESULT_DIR", std::to_string(opt.dirs.size()) + " folders: one without --side-by-side"));
  const bool side_options[] = {!opt.labels.empty(), !opt.out.empty(), opt.max_damping > 0, opt.no_plot};
  const char* const side_names[] = {"--label", "--out", "--max-damping", "--no-plot"};
  for (int i = 0; i < 4; ++i)
    if (side_options[i]) throw InputError(where("", 0, side_names[i], "only with --side-by-side"));
  runHtml(opt);
}

}  // namespace

void addReportCommand(CLI::App& app) {
  auto opt = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "interactive Campbell report of a whirl campbell result folder: writes RESULT_DIR/campbell.html "
      "(diagram, mode shapes, tables; one file, opens without a network); with --side-by-side, several result "
      "folders' Campbell diagrams in one figure, one column each, and their first modes tabulated (aero_models.csv)");
  cmd->add_option("RESULT_DIR", opt->dirs,
                  "folder with the campbell_modes.json of whirl campbell (with --side-by-side: folders with its "
                  "campbell.csv, one column each)")
      ->required();
  cmd->add_option("--versus", opt->versus, "x axis: rpm, wind or auto (wind when every point has a wind speed)")
      ->check(CLI::IsMember({"rpm", "wind", "auto"}));
  cmd->add_option("--max-freq", opt->max_freq, "top of the frequency axis [Hz] (default: automatic)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--side-by-side", opt->side_by_side,
                "draw the RESULT_DIRs' Campbell diagrams side by side (same axes) into --out: "
                "campbell_side_by_side.gp/.png/.svg and aero_models.csv");
  cmd->add_option("--label", opt->labels,
                  "title of a RESULT_DIR's column, once per folder in the same order (default: the folder's name)")
      ->allow_extra_args(false);  // one value per --label: a folder after it stays a RESULT_DIR
  cmd->add_option("--out", opt->out, "output folder of --side-by-side");
  cmd->add_option("--max-damping", opt->max_damping,
                  "top of the damping axis of --side-by-side [%] (default: automatic)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-plot", opt->no_plot, "with --side-by-side: write the script and data, do not run Gnuplot");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli

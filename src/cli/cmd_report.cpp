// `whirl report RESULT_DIR`: the interactive Campbell report (src/writers/campbell_html.hpp) of a folder that
// `whirl campbell` wrote, from its campbell_modes.json; written as RESULT_DIR/campbell.html.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/writers/campbell_html.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct ReportOptions {
  std::string dir;
  std::string versus = "auto";
  double max_freq = 0;
};

void run(const ReportOptions& opt) {
  const std::string path = (std::filesystem::path(opt.dir) / "campbell_modes.json").string();
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
  r.summary = {{"result folder", opt.dir},
               {"operating points", std::to_string(points)},
               {"lines", std::to_string(lines)}};
  r.steady_csv = steadyCsvIn(opt.dir);
  const std::string page = campbellHtml(text.str(), r, path);
  prepareOutputFolder(opt.dir);
  OutputSet files(opt.dir);
  files.write("campbell.html", page);
  files.commit();
  std::printf("wrote %s\n", (std::filesystem::path(opt.dir) / "campbell.html").string().c_str());
}

}  // namespace

void addReportCommand(CLI::App& app) {
  auto opt = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "interactive Campbell report of a whirl campbell result folder: writes RESULT_DIR/campbell.html "
      "(diagram, mode shapes, tables; one file, opens without a network)");
  cmd->add_option("RESULT_DIR", opt->dir, "folder with the campbell_modes.json of whirl campbell")->required();
  cmd->add_option("--versus", opt->versus, "x axis: rpm, wind or auto (wind when every point has a wind speed)")
      ->check(CLI::IsMember({"rpm", "wind", "auto"}));
  cmd->add_option("--max-freq", opt->max_freq, "top of the frequency axis [Hz] (default: automatic)")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli

#include <CLI/CLI.hpp>
#include <cstdio>
#include <utility>

#include "modal/lin_modes.hpp"
#include "modal/tracking.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/cli/mode_output.hpp"
#include "src/io/openfast_lin.hpp"
#include "src/model/error.hpp"
#include "src/model/text.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct LinOptions {
  std::vector<std::string> files;
  std::string format = "table", out = "reports/lin";
  bool no_plot = false;
  bool first_order_lines = false;
};

void run(const LinOptions& opt) {
  std::vector<OpenFastLin> lins;
  for (const auto& f : opt.files) lins.push_back(readOpenFastLin(f));
  const std::vector<std::vector<OpenFastLin>> groups = groupLinByOperatingPoint(std::move(lins));
  CampbellDiagram d;
  d.title = "Campbell diagram: OpenFAST linearization";
  std::vector<std::string> notes;
  for (const auto& group : groups) d.points.push_back(linCampbellPoint(group, &notes));
  for (const auto& n : notes) std::fprintf(stderr, "whirl: note: %s\n", escapeControlCharacters(n).c_str());
  if (d.points.size() == 1) {
    nlohmann::json header;
    header["files"] = opt.files;
    header["rotor_speed_rpm"] = d.points[0].rpm;
    if (d.points[0].wind_speed) header["wind_speed"] = *d.points[0].wind_speed;
    header["azimuths"] = groups.front().size();
    printModes(d.points[0].modes, d.points[0].coordinates, opt.format, header);
    return;
  }
  prepareOutputFolder(opt.out);
  d.lines = trackModes(d.points);
  CampbellPlotOptions plot;
  plot.render = !opt.no_plot;
  plot.first_order_lines = opt.first_order_lines;
  noteHiddenFirstOrderLines(d, plot);
  const auto files = writeCampbell(d, opt.out, plot);
  std::printf("%zu operating points from %zu files; wrote", d.points.size(), opt.files.size());
  for (const auto& f : files) std::printf(" %s", f.c_str());
  std::printf("\n");
}

}  // namespace

void addLinCommand(CLI::App& app) {
  auto opt = std::make_shared<LinOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lin", "modes from OpenFAST .lin files: grouped by operating point, multiblade transform over each group's "
             "azimuths, named; one operating point prints like `modes`, several write a Campbell diagram");
  // No CLI::ExistingFile: a missing file is the reader's "FILE: cannot open file" (exit 1), as elsewhere.
  cmd->add_option("FILE", opt->files, "OpenFAST .lin files")->required();
  cmd->add_option("--format", opt->format, "one operating point: table, csv or json")
      ->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->add_option("--out", opt->out, "several operating points: output folder (default reports/lin)");
  cmd->add_flag("--no-plot", opt->no_plot, "do not run Gnuplot");
  cmd->add_flag(
      "--first-order-lines", opt->first_order_lines,
      "also draw the lines carried by first-order states (HydroDyn radiation …), which are in the tables anyway");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli

#include <CLI/CLI.hpp>
#include <cstdio>
#include <utility>

#include "modal/lin_modes.hpp"
#include "modal/tracking.hpp"
#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/cli/mode_output.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

struct LinOptions {
  std::vector<std::string> files;
  std::string format = "table", out;
  double tolerance = 1e-3;
  bool no_plot = false;
  bool first_order_lines = false;
};

// One operating point: the modes printed like `whirl modes`, and written to <out>/modes.<format>
// (modes.txt for the table) when --out is given.
void writeOnePoint(const LinOptions& opt, const CampbellPoint& p, std::size_t azimuths) {
  nlohmann::json header;
  header["files"] = opt.files;
  header["rotor_speed_rpm"] = p.rpm;
  if (p.wind_speed) header["wind_speed"] = *p.wind_speed;
  header["azimuths"] = azimuths;
  if (opt.out.empty()) {
    printModes(p.modes, p.coordinates, opt.format, header);
    return;
  }
  prepareOutputFolder(opt.out);
  const std::string name = "modes." + std::string(opt.format == "table" ? "txt" : opt.format);
  OutputSet files(opt.out);
  const std::string text = modesText(p.modes, p.coordinates, opt.format, header);
  files.write(name, text);
  files.commit();
  std::fputs(text.c_str(), stdout);
  std::printf("wrote %s\n", files.paths().front().c_str());
}

void run(const LinOptions& opt) {
  if (!(opt.tolerance >= 0 && opt.tolerance < 1))
    throw InputError("--rpm-tolerance: must be in [0, 1), got " + std::to_string(opt.tolerance));
  std::vector<OpenFastLin> lins;
  for (const auto& f : opt.files) lins.push_back(readOpenFastLin(f));
  const std::vector<std::vector<OpenFastLin>> groups = groupLinByOperatingPoint(std::move(lins), opt.tolerance);
  CampbellDiagram d;
  d.title = "Campbell diagram: OpenFAST linearization";
  std::vector<std::string> notes;
  for (const auto& group : groups) {
    if (const std::string w = fewAzimuthsWarning(group); !w.empty())
      std::fprintf(stderr, "whirl: warning: %s\n", escapeControlCharacters(w).c_str());
    d.points.push_back(linCampbellPoint(group, &notes));
  }
  for (const auto& n : notes) std::fprintf(stderr, "whirl: note: %s\n", escapeControlCharacters(n).c_str());
  if (d.points.size() == 1) return writeOnePoint(opt, d.points[0], groups.front().size());
  // Several points: the Campbell files in --out (default reports/<root name of the first file>), and
  // the table on stdout in --format (table: the summary line; csv, json: the Campbell table itself).
  const std::string root = linRootName(opt.files.front());
  const std::string dir = !opt.out.empty() ? opt.out : defaultOutputFolder(root.empty() ? opt.files.front() : root);
  prepareOutputFolder(dir);
  d.lines = trackModes(d.points);
  CampbellPlotOptions plot;
  plot.render = !opt.no_plot;
  plot.first_order_lines = opt.first_order_lines;
  noteHiddenFirstOrderLines(d, plot);
  const auto files = writeCampbell(d, dir, plot);
  if (opt.format == "csv") std::fputs(campbellCsv(d).c_str(), stdout);
  if (opt.format == "json") std::fputs(campbellModesJson(d).c_str(), stdout);
  std::fprintf(opt.format == "table" ? stdout : stderr, "%zu operating points from %zu files; wrote", d.points.size(),
               opt.files.size());
  for (const auto& f : files) std::fprintf(opt.format == "table" ? stdout : stderr, " %s", f.c_str());
  std::fprintf(opt.format == "table" ? stdout : stderr, "\n");
}

}  // namespace

void addLinCommand(CLI::App& app) {
  auto opt = std::make_shared<LinOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lin",
      "modes from OpenFAST .lin files: grouped by operating point, multiblade transform over each group's "
      "azimuths, named; one operating point prints like `modes`, several write a Campbell diagram");
  // No CLI::ExistingFile: a missing file is the reader's "FILE: cannot open file" (exit 1), as elsewhere.
  cmd->add_option("FILE", opt->files, "OpenFAST .lin files")->required();
  cmd->add_option("--format", opt->format,
                  "table, csv or json: one operating point prints its modes so (and writes them to --out when "
                  "given); several print the Campbell table so (table: a summary line)")
      ->check(CLI::IsMember({"table", "csv", "json"}));
  cmd->add_option("--out", opt->out,
                  "output folder (several operating points: default reports/<root name of the first file>)");
  cmd->add_option("--rpm-tolerance", opt->tolerance,
                  "files of one root name <root>.<k>.lin are one operating point when their rotor and wind speeds "
                  "agree within this fraction (default 1e-3)");
  cmd->add_flag("--no-plot", opt->no_plot, "do not run Gnuplot");
  cmd->add_flag(
      "--first-order-lines", opt->first_order_lines,
      "also draw the lines carried by first-order states (HydroDyn radiation …), which are in the tables anyway");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli

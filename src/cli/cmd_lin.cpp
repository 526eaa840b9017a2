#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <map>

#include "src/writers/campbell_output.hpp"
#include "modal/mbc_lin.hpp"
#include "modal/rotor_modes.hpp"
#include "modal/tracking.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/mode_output.hpp"
#include "src/writers/output_set.hpp"
#include "src/io/openfast_lin.hpp"
#include "src/io/openfast_lin_names.hpp"
#include "src/model/error.hpp"

namespace whirl::cli {
namespace {

struct LinOptions {
  std::vector<std::string> files;
  std::string format = "table", out = "reports/lin";
  bool no_plot = false;
};

// The displacement coordinates of a .lin file: the states whose rate is another state; they must
// come first (OpenFAST writes the ElastoDyn displacements first).
RotorCoordinates coordinatesOf(const OpenFastLin& lin, const MbcLayout& layout) {
  std::vector<bool> displacement(lin.x.size(), false);
  for (int v : layout.velocity_of)
    if (v >= 0) displacement[v] = true;
  int n = 0;
  while (n < static_cast<int>(displacement.size()) && displacement[n]) ++n;
  for (size_t i = n; i < displacement.size(); ++i)
    if (displacement[i])
      throw InputError(where(lin.path, lin.x[i].line, "", "displacement states must come first in the state vector"));
  if (n == 0) throw InputError(where(lin.path, 0, "", "no second-order (displacement, rate) states to analyse"));
  RotorCoordinates c;
  for (int i = 0; i < n; ++i) {
    c.names.push_back(dofNameFromLinDescription(lin.x[i].description));
    c.blade.push_back(layout.state_blade[i]);
    c.azimuth.push_back(isAzimuthLinDescription(lin.x[i].description));
  }
  c.weights = MatX::Identity(n, n);  // a .lin file has no mass matrix
  return c;
}

CampbellPoint analyse(const std::vector<OpenFastLin>& group) {
  const MbcLayout layout = mbcLayoutFromLin(group.front());
  std::vector<MbcSample> samples;
  for (const auto& lin : group) {
    if (lin.A.rows() != group.front().A.rows())
      throw InputError(lin.path + ": its states differ from " + group.front().path + " (same operating point)");
    samples.push_back(mbcSampleFromLin(lin));
  }
  const RotorModes r = multibladeModes(coordinatesOf(group.front(), layout), layout, samples);
  CampbellPoint p;
  p.rpm = group.front().rotor_speed * 30 / M_PI;
  p.wind_speed = group.front().wind_speed;
  p.coordinates = r.coordinates;
  p.modes = r.modes;
  return p;
}

void run(const LinOptions& opt) {
  // Group the files by operating point (rotor speed, wind speed), in order of rotor speed.
  std::map<std::pair<long long, long long>, std::vector<OpenFastLin>> groups;
  for (const auto& f : opt.files) {
    OpenFastLin lin = readOpenFastLin(f);
    if (lin.A.size() == 0) throw InputError(f + ": no A matrix (no continuous states)");
    const long long w = std::llround(1e6 * lin.rotor_speed), v = std::llround(1e4 * lin.wind_speed.value_or(-1));
    // The same azimuth twice (a file given twice) would weigh it double in the multiblade average.
    for (const OpenFastLin& other : groups[{w, v}])
      if (std::abs(std::remainder(lin.azimuth - other.azimuth, 2 * M_PI)) < 1e-6)
        throw InputError(f + ": same operating point and azimuth as " + other.path +
                         " (a repeated azimuth would bias the multiblade average; give each file once)");
    groups[{w, v}].push_back(std::move(lin));
  }
  CampbellDiagram d;
  d.title = "Campbell diagram: OpenFAST linearization";
  for (const auto& [key, group] : groups) d.points.push_back(analyse(group));
  if (d.points.size() == 1) {
    nlohmann::json header;
    header["files"] = opt.files;
    header["rotor_speed_rpm"] = d.points[0].rpm;
    if (d.points[0].wind_speed) header["wind_speed"] = *d.points[0].wind_speed;
    header["azimuths"] = groups.begin()->second.size();
    printModes(d.points[0].modes, d.points[0].coordinates, opt.format, header);
    return;
  }
  prepareOutputFolder(opt.out);
  d.lines = trackModes(d.points);
  CampbellPlotOptions plot;
  plot.render = !opt.no_plot;
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
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli

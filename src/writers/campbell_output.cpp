// writeCampbell: all Campbell files of one diagram and their Gnuplot images, committed as one set.
#include "src/writers/campbell_output.hpp"

#include <algorithm>

#include "src/base/error.hpp"
#include "src/writers/campbell_aero.hpp"
#include "src/writers/campbell_html.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/hawcstab2_files.hpp"
#include "src/writers/mode_shape_tables.hpp"
#include "src/writers/mode_shape_vtk.hpp"
#include "src/writers/openfast_campbell_files.hpp"
#include "src/writers/output_set.hpp"

namespace whirl {

namespace {

// One animation per shown line and point where the line has a mode with a motion:
// mode_<line>_p<point>.pvd and its frames (src/writers/mode_shape_vtk.hpp).
void writeCampbellVtk(const CampbellDiagram& d, const CampbellPlotOptions& opt, OutputSet& files) {
  for (const CampbellLine& line : d.lines) {
    if (!campbellLineShown(d, line, opt)) continue;
    for (std::size_t p = 0; p < d.points.size(); ++p) {
      if (line.mode[p] < 0) continue;
      const Mode& m = d.points[p].modes[static_cast<std::size_t>(line.mode[p])];
      const std::string stem = "mode_" + vtkFileStem(line.name) + "_p" + std::to_string(p);
      for (const auto& [name, text] : modeShapeVtk(m.motion, stem, m.freq_hz, m.damped_freq_hz))
        files.write(name, text);
    }
  }
}

}  // namespace

std::vector<std::string> writeCampbell(const CampbellDiagram& d, const std::string& dir,
                                       const CampbellPlotOptions& opt) {
  checkCampbell(d, opt);
  const std::string folder = dir.empty() ? "." : dir;
  prepareOutputFolder(folder);
  OutputSet files(folder);
  files.write("campbell.csv", campbellCsv(d));
  if (hasAeroRoots(d)) files.write("campbell_aero.csv", campbellAeroCsv(d));
  const std::string modes_json = campbellModesJson(d);
  files.write("campbell_modes.json", modes_json);
  if (opt.html) {
    CampbellReportOptions r;
    r.harmonics = opt.harmonics;
    r.versus_wind_speed = opt.versus_wind_speed;
    r.max_freq_hz = opt.max_freq_hz;
    r.first_order_lines = opt.first_order_lines;
    r.summary = opt.summary;
    r.steady_csv = steadyCsvIn(folder);
    files.write("campbell.html", campbellHtml(modes_json, r));
  }
  files.write("campbell.dat", campbellGnuplotData(d));
  files.write("campbell.gp", campbellGnuplotScript(d, opt));
  if (std::find(opt.formats.begin(), opt.formats.end(), "hawcstab2") != opt.formats.end()) {
    files.write("campbell.cmb", hawcstab2Cmb(d));
    files.write("campbell.amp", hawcstab2Amp(d));
    files.write("campbell.opt", hawcstab2Opt(d));
  }
  if (std::find(opt.formats.begin(), opt.formats.end(), "openfast") != opt.formats.end()) {
    files.write("Campbell_OP.csv", openfastCampbellOp(d));
    files.write("Campbell_ModesID.csv", openfastCampbellModesId(d));
    for (std::size_t p = 0; p < d.points.size(); ++p)
      files.write(openfastCampbellPointName(p), openfastCampbellPoint(d, p));
    files.write("Campbell_Summary.txt", openfastCampbellSummary(d));
  }
  if (std::find(opt.formats.begin(), opt.formats.end(), "vtk") != opt.formats.end()) writeCampbellVtk(d, opt, files);
  // Mode shapes per operating point, when the sweep computed them (modal/mode_shapes.hpp).
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    bool any = false;
    for (const Mode& m : d.points[p].modes) any = any || !m.motion.empty();
    if (any) files.write("mode_shapes_" + std::to_string(p) + ".csv", modeShapesCsv(d, p));
  }
  // Rendered beside the tables before the commit, so the images belong to the set.
  if (opt.render) renderGnuplot(files.stagingFolder(), opt.gnuplot, "campbell", folder);
  files.commit();
  return files.paths();
}

}  // namespace whirl

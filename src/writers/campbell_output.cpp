// writeCampbell: all Campbell files of one diagram and their Gnuplot images, committed as one set.
#include "src/writers/campbell_output.hpp"

#include <algorithm>

#include "src/writers/campbell_html.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/hawcstab2_files.hpp"
#include "src/writers/mode_shape_tables.hpp"
#include "src/writers/output_set.hpp"
#include "src/model/error.hpp"

namespace whirl {

std::vector<std::string> writeCampbell(const CampbellDiagram& d, const std::string& dir, const CampbellPlotOptions& opt) {
  checkCampbell(d, opt);
  const std::string folder = dir.empty() ? "." : dir;
  prepareOutputFolder(folder);
  OutputSet files(folder);
  files.write("campbell.csv", campbellCsv(d));
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

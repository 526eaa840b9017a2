// writeCampbell: all Campbell files of one diagram and their Gnuplot images, committed as one set.
#include "src/writers/campbell_output.hpp"

#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"
#include "src/model/error.hpp"

namespace whirl {

std::vector<std::string> writeCampbell(const CampbellDiagram& d, const std::string& dir, const CampbellPlotOptions& opt) {
  checkCampbell(d, opt);
  const std::string folder = dir.empty() ? "." : dir;
  prepareOutputFolder(folder);
  OutputSet files(folder);
  files.write("campbell.csv", campbellCsv(d));
  files.write("campbell_modes.json", campbellModesJson(d));
  files.write("campbell.dat", campbellGnuplotData(d));
  files.write("campbell.gp", campbellGnuplotScript(d, opt));
  // Rendered beside the tables before the commit, so the images belong to the set.
  if (opt.render) renderGnuplot(files.stagingFolder(), opt.gnuplot, "campbell", folder);
  files.commit();
  return files.paths();
}

}  // namespace whirl

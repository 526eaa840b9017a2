// writeCampbell: all Campbell files of one diagram, written atomically, then rendered by Gnuplot.
#include "modal/campbell_output.hpp"

#include <cstdio>
#include <filesystem>

#include "src/io/atomic_file.hpp"
#include "src/io/gnuplot.hpp"
#include "src/model/error.hpp"

namespace whirl {

namespace fs = std::filesystem;

std::vector<std::string> writeCampbell(const CampbellDiagram& d, const std::string& dir, const CampbellPlotOptions& opt) {
  checkCampbell(d, opt);
  const fs::path folder = dir.empty() ? fs::path(".") : fs::path(dir);
  const std::vector<std::pair<std::string, std::string>> files{{"campbell.csv", campbellCsv(d)},
                                                               {"campbell_modes.json", campbellModesJson(d)},
                                                               {"campbell.dat", campbellGnuplotData(d)},
                                                               {"campbell.gp", campbellGnuplotScript(d, opt)}};
  ensureWritableFolder(folder.string());
  std::vector<std::string> written;
  try {
    for (const auto& [name, text] : files) {
      writeFileAtomic((folder / name).string(), text);
      written.push_back((folder / name).string());
    }
  } catch (const InputError&) {
    for (const auto& w : written) std::remove(w.c_str());  // all four tables or none
    throw;
  }
  if (opt.render) {
    for (auto& image : renderGnuplot(folder.string(), opt.gnuplot, "campbell")) written.push_back(std::move(image));
  }
  return written;
}

}  // namespace whirl

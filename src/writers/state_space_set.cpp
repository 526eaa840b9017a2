#include <cstdio>

#include "src/writers/state_space_files.hpp"

namespace whirl {

void writeStateSpaceFiles(const StateSpaceExport& e, const std::string& format, const std::string& title,
                          OutputSet& files) {
  if (format == "mat") {
    writeStateSpaceMat(e, files.stage("statespace.mat"));
  } else if (format == "json") {
    files.write("statespace.json", stateSpaceJson(e));
  } else {
    for (size_t j = 0; j < e.points.size(); ++j) {
      const ExportPoint& p = e.points[j];
      char stem[32];
      if (e.points.size() == 1) std::snprintf(stem, sizeof stem, "statespace");
      else std::snprintf(stem, sizeof stem, "statespace_%02zu", j + 1);
      if (p.azimuths.empty()) {
        files.write(std::string(stem) + ".1.lin", linFileText(p.model, title));
        continue;
      }
      for (size_t k = 0; k < p.azimuths.size(); ++k)
        files.write(std::string(stem) + "." + std::to_string(k + 1) + ".lin", linFileText(p.azimuths[k], title));
    }
  }
}

}  // namespace whirl

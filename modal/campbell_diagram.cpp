#include "modal/campbell_diagram.hpp"

#include <filesystem>

namespace whirl {

CampbellDiagram campbellDiagram(const Model& model, const std::vector<SweepPoint>& points,
                                const CampbellDiagramOptions& opt) {
  CampbellDiagram d;
  d.title = opt.title;
  d.points = campbellSweep(model, points, opt.sweep);
  // Under mpirun the other ranks hold no points; tracking them is nothing.
  if (!d.points.empty()) d.lines = trackModes(d.points, opt.tracking);
  return d;
}

std::vector<LineInstability> lineInstabilities(const CampbellDiagram& d) {
  std::vector<LineInstability> out;
  for (const CampbellLine& line : d.lines) {
    LineInstability u;
    u.name = line.name;
    for (std::size_t p = 0; p < d.points.size() && p < line.mode.size(); ++p) {
      if (line.mode[p] < 0) continue;
      const Mode& md = d.points[p].modes[static_cast<std::size_t>(line.mode[p])];
      if (md.rigid_body || !(md.damping_ratio < 0)) continue;
      ++u.points;
      if (md.damping_ratio < u.lowest_damping) {
        u.lowest_damping = md.damping_ratio;
        u.at = p;
      }
    }
    if (u.points > 0) out.push_back(u);
  }
  return out;
}

std::string campbellTitle(const Model& model, const std::string& case_path) {
  std::string name = model.name.substr(0, model.name.find(". "));
  if (name.empty() || name.size() > 70) name = std::filesystem::path(case_path).filename().string();
  return "Campbell diagram: " + name;
}

}  // namespace whirl

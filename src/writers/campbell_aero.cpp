// campbell_aero.csv (campbell_aero.hpp).
#include "src/writers/campbell_aero.hpp"

#include "modal/aero_roots.hpp"
#include "src/io/text/csv.hpp"

namespace whirl {

bool hasAeroRoots(const CampbellDiagram& d) {
  for (const CampbellPoint& p : d.points)
    for (const Mode& m : p.modes)
      if (isAeroRoot(m)) return true;
  return false;
}

std::string campbellAeroCsv(const CampbellDiagram& d) {
  std::string s = "rpm,wind_speed,mode,freq_hz,damped_freq_hz,damping_ratio,aero_share,dominant_state\n";
  for (const CampbellPoint& p : d.points) {
    const std::string head = formatNumber(p.rpm) + "," + (p.wind_speed ? formatNumber(*p.wind_speed) : "") + ",";
    for (const Mode& m : p.modes) {
      if (!isAeroRoot(m)) continue;
      Eigen::Index top = 0;
      if (m.participation.size() > 0) m.participation.maxCoeff(&top);
      const std::string dominant = top < static_cast<Eigen::Index>(p.coordinates.size())
                                       ? p.coordinates[static_cast<std::size_t>(top)]
                                       : "";
      s += head + csvField(m.name) + "," + formatNumber(m.freq_hz) + "," + formatNumber(m.damped_freq_hz) + "," +
           formatNumber(m.damping_ratio) + "," + formatNumber(m.name_share) + "," + csvField(dominant) + "\n";
    }
  }
  return s;
}

}  // namespace whirl

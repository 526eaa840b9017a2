// campbell.csv, campbell_modes.json and the checks shared by the Campbell writers.
#include <cmath>

#include <nlohmann/json.hpp>

#include "src/base/error.hpp"
#include "src/io/text/csv.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/mode_shape_tables.hpp"

namespace whirl {

void checkCampbell(const CampbellDiagram& d, const CampbellPlotOptions& opt) {
  const std::size_t P = d.points.size();
  for (const auto& line : d.lines) {
    const std::string key = "Campbell line '" + line.name + "'";
    if (line.mode.size() != P)
      throw InputError(
          where("", 0, key, std::to_string(line.mode.size()) + " entries for " + std::to_string(P) + " points"));
    for (std::size_t p = 0; p < P; ++p)
      if (line.mode[p] < -1 || line.mode[p] >= static_cast<int>(d.points[p].modes.size()))
        throw InputError(where("", 0, key,
                               "mode " + std::to_string(line.mode[p]) + " at point " + std::to_string(p) +
                                   " is not one of its " + std::to_string(d.points[p].modes.size()) + " modes"));
  }
  for (const std::string& f : opt.formats)
    if (f != "hawcstab2" && f != "openfast" && f != "vtk")
      throw InputError(
          where("", 0, "Campbell formats", "unknown format '" + f + "' (allowed: hawcstab2, openfast, vtk)"));
  for (int n : opt.harmonics)
    if (n < 1) throw InputError(where("", 0, "Campbell plot harmonics", std::to_string(n) + "P: must be 1 or more"));
  if (opt.versus_wind_speed)
    for (std::size_t p = 0; p < P; ++p)
      if (!d.points[p].wind_speed)
        throw InputError(
            where("", 0, "Campbell point " + std::to_string(p), "no wind speed for a plot versus wind speed"));
}

std::string campbellCsv(const CampbellDiagram& d) {
  std::string s = "rpm,wind_speed,mode,freq_hz,damping_ratio\n";
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    const auto& pt = d.points[p];
    const std::string head = formatNumber(pt.rpm) + "," + (pt.wind_speed ? formatNumber(*pt.wind_speed) : "") + ",";
    for (const auto& line : d.lines) {
      if (line.mode[p] < 0) continue;
      const Mode& m = pt.modes[line.mode[p]];
      s += head + csvField(line.name) + "," + formatNumber(m.freq_hz) + "," + formatNumber(m.damping_ratio) + "\n";
    }
  }
  return s;
}

std::string campbellModesJson(const CampbellDiagram& d) {
  using json = nlohmann::ordered_json;  // keys in the order written
  const auto number = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
  json j;
  j["title"] = d.title;
  j["lines"] = json::array();
  for (const auto& line : d.lines) j["lines"].push_back(line.name);
  j["points"] = json::array();
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    const auto& pt = d.points[p];
    json jp;
    jp["index"] = p;
    jp["rpm"] = number(pt.rpm);
    jp["wind_speed"] = pt.wind_speed ? number(*pt.wind_speed) : json(nullptr);
    jp["pitch_deg"] = pt.pitch_deg ? number(*pt.pitch_deg) : json(nullptr);
    jp["coordinates"] = pt.coordinates;
    if (!pt.validity_problems.empty()) jp["validity"] = {{"valid", false}, {"problems", pt.validity_problems}};
    jp["modes"] = json::array();
    for (std::size_t k = 0; k < pt.modes.size(); ++k) {
      const Mode& m = pt.modes[k];
      json jm;
      jm["index"] = k;
      jm["freq_hz"] = number(m.freq_hz);
      jm["damped_freq_hz"] = number(m.damped_freq_hz);
      jm["damping_ratio"] = number(m.damping_ratio);
      jm["rigid_body"] = m.rigid_body;
      jm["first_order"] = m.first_order;
      jm["name"] = m.name;
      jm["name_evidence"] = {{"share", number(m.name_share)},
                             {"runner_up", m.runner_up},
                             {"runner_up_share", number(m.runner_up_share)},
                             {"ambiguous", m.ambiguous}};
      jm["line"] = nullptr;
      for (const auto& line : d.lines)
        if (line.mode[p] == static_cast<int>(k)) jm["line"] = line.name;
      json part = json::object();
      for (Eigen::Index c = 0; c < m.participation.size(); ++c) {
        const std::string coord = c < static_cast<Eigen::Index>(pt.coordinates.size()) ? pt.coordinates[c]
                                                                                       : "q" + std::to_string(c);
        part[coord] = number(m.participation[c]);
      }
      jm["participation"] = std::move(part);
      if (!m.motion.empty()) jm["motion"] = modeMotionJson(m.motion);
      jp["modes"].push_back(std::move(jm));
    }
    j["points"].push_back(std::move(jp));
  }
  // Names are checked as UTF-8 where they are read (src/base/text.hpp); a byte that still is not
  // becomes U+FFFD here rather than an exception without file or key (fuzz_writers).
  return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace whirl

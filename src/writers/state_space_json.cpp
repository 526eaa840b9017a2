// JSON writer for state-space exports (same content as the .mat file).
#include <nlohmann/json.hpp>

#include "src/writers/state_space_files.hpp"

namespace whirl {
namespace {

using nlohmann::json;

json rows(const MatX& M) {
  json j = json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    json row = json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
    j.push_back(row);
  }
  return j;
}

json variables(const std::vector<StateSpaceVariable>& v, bool states) {
  json j = json::array();
  for (const auto& x : v) {
    json e = {{"name", x.name}, {"unit", x.unit}, {"op", x.op}, {"rotating_frame", x.blade >= 0}};
    if (x.blade >= 0) e["blade"] = x.blade + 1;
    if (states) {
      e["rate_of"] = x.rate_of >= 0 ? json(x.rate_of) : json(nullptr);
      if (x.azimuth) e["azimuth"] = true;
    }
    j.push_back(e);
  }
  return j;
}

json model(const StateSpaceModel& m) {
  json j;
  j["azimuth_rad"] = m.azimuth;
  j["rotor_speed_rad_s"] = m.rotor_speed;
  j["multiblade"] = m.multiblade;
  j["states"] = variables(m.x, true);
  j["inputs"] = variables(m.u, false);
  j["outputs"] = variables(m.y, false);
  j["xdot_op"] = std::vector<double>(m.xdot_op.data(), m.xdot_op.data() + m.xdot_op.size());
  j["A"] = rows(m.A);
  j["B"] = rows(m.B);
  j["C"] = rows(m.C);
  j["D"] = rows(m.D);
  return j;
}

}  // namespace

std::string stateSpaceJson(const StateSpaceExport& e) {
  json j;
  j["format"] = "whirl state-space export 1";
  j["source"] = e.source;
  j["model"] = e.model_name;
  j["conventions"] =
      "x' = A x + B u, y = C x + D u for deviations from the operating point (op); SI units; "
      "matrices as arrays of rows";
  j["operating_points"] = json::array();
  for (const ExportPoint& p : e.points) {
    json o;
    o["rpm"] = p.rpm;
    o["wind_speed"] = p.wind_speed ? json(*p.wind_speed) : json(nullptr);
    o["pitch_deg"] = p.pitch_deg ? json(*p.pitch_deg) : json(nullptr);
    o["model"] = model(p.model);
    o["azimuths"] = json::array();
    for (const auto& m : p.azimuths) o["azimuths"].push_back(model(m));
    j["operating_points"].push_back(o);
  }
  // Names are checked as UTF-8 where they are read (src/base/text.hpp); a byte that still is not
  // becomes U+FFFD here rather than an exception without file or key (fuzz_writers).
  return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace whirl

// Mode shapes as JSON and CSV tables (src/writers/mode_shape_tables.hpp).
#include "src/writers/mode_shape_tables.hpp"

#include <cmath>
#include <numbers>

#include "src/io/text/csv.hpp"

namespace whirl {
namespace {

using json = nlohmann::ordered_json;

const char* const kComponents[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

// Per row: the 6 amplitudes and the 6 phases.
void amplitudePhase(const Eigen::MatrixXcd& u, json& into) {
  json amp = json::array(), ph = json::array();
  for (Eigen::Index r = 0; r < u.rows(); ++r) {
    json a = json::array(), p = json::array();
    for (Eigen::Index c = 0; c < u.cols(); ++c) a.push_back(std::abs(u(r, c))), p.push_back(phaseDeg(u(r, c)));
    amp.push_back(std::move(a));
    ph.push_back(std::move(p));
  }
  into["amplitude"] = std::move(amp);
  into["phase_deg"] = std::move(ph);
}

}  // namespace

double phaseDeg(std::complex<double> u) {
  if (std::abs(u) < 1e-12) return 0;
  const double d = std::arg(u) * 180 / std::numbers::pi;
  return d <= -180 ? d + 360 : d;
}

json modeMotionJson(const ModeMotion& m) {
  if (m.empty()) return nullptr;
  json j;
  j["normalisation"] = "largest translational amplitude of any node = 1, at phase 0";
  j["frame"] = "body frame at the operating point (blades: rotating frame; rotor frozen at the first azimuth)";
  j["components"] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  j["bodies"] = json::array();
  for (const BodyMotion& b : m.bodies) {
    json jb;
    jb["body"] = b.body;
    jb["blade"] = b.blade >= 0 ? json(b.blade + 1) : json(nullptr);
    jb["role"] = b.role;
    jb["nodes"] = b.nodes;
    jb["x_m"] = std::vector<double>(b.x.data(), b.x.data() + b.x.size());
    json pos = json::array();
    for (Eigen::Index k = 0; k < b.position.cols(); ++k)
      pos.push_back({b.position(0, k), b.position(1, k), b.position(2, k)});
    jb["position_m"] = std::move(pos);
    jb["R"] = {{b.R(0, 0), b.R(0, 1), b.R(0, 2)}, {b.R(1, 0), b.R(1, 1), b.R(1, 2)}, {b.R(2, 0), b.R(2, 1), b.R(2, 2)}};
    amplitudePhase(b.u, jb);
    j["bodies"].push_back(std::move(jb));
  }
  if (m.collective.size() > 0) {
    json mb;
    mb["nodes"] = m.blade_nodes;
    mb["x_m"] = std::vector<double>(m.blade_x.data(), m.blade_x.data() + m.blade_x.size());
    for (const auto& [kind, u] : {std::pair<const char*, const Eigen::MatrixXcd*>{"collective", &m.collective},
                                  {"backward", &m.backward},
                                  {"forward", &m.forward}}) {
      json k;
      amplitudePhase(*u, k);
      mb[kind] = std::move(k);
    }
    j["multiblade"] = std::move(mb);
  }
  return j;
}

std::string modeShapesCsv(const CampbellDiagram& d, std::size_t p) {
  std::string s = "mode,line,name,freq_hz,damping_ratio,body,blade,node,x_m";
  for (const char* c : kComponents) s += std::string(",") + c + "_amp," + c + "_phase_deg";
  s += "\n";
  const CampbellPoint& pt = d.points.at(p);
  for (std::size_t k = 0; k < pt.modes.size(); ++k) {
    const Mode& m = pt.modes[k];
    std::string line;
    for (const auto& l : d.lines)
      if (p < l.mode.size() && l.mode[p] == static_cast<int>(k)) line = l.name;
    const std::string head = std::to_string(k) + "," + csvField(line) + "," + csvField(m.name) + "," +
                             formatNumber(m.freq_hz) + "," + formatNumber(m.damping_ratio) + ",";
    for (const BodyMotion& b : m.motion.bodies)
      for (Eigen::Index r = 0; r < b.u.rows(); ++r) {
        s += head + csvField(b.body) + "," + (b.blade >= 0 ? std::to_string(b.blade + 1) : "") + "," +
             csvField(b.nodes[static_cast<std::size_t>(r)]) + "," + formatNumber(b.x(r));
        for (Eigen::Index c = 0; c < 6; ++c)
          s += "," + formatNumber(std::abs(b.u(r, c))) + "," + formatNumber(phaseDeg(b.u(r, c)));
        s += "\n";
      }
  }
  return s;
}

}  // namespace whirl

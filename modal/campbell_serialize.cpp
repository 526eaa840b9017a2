#include "modal/campbell_serialize.hpp"

#include <nlohmann/json.hpp>

#include "linearize/cbor_bytes.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace {

using nlohmann::json;

json encodeMode(const Mode& m) {
  json j;
  j["f"] = m.freq_hz;
  j["fd"] = m.damped_freq_hz;
  j["z"] = m.damping_ratio;
  j["rb"] = m.rigid_body;
  j["fo"] = m.first_order;
  j["name"] = m.name;
  std::vector<double> re(m.shape.size()), im(m.shape.size());
  for (Eigen::Index i = 0; i < m.shape.size(); ++i) {
    re[i] = m.shape(i).real();
    im[i] = m.shape(i).imag();
  }
  j["re"] = re;
  j["im"] = im;
  j["p"] = std::vector<double>(m.participation.data(), m.participation.data() + m.participation.size());
  if (m.residual) j["res"] = *m.residual;
  return j;
}

Mode decodeMode(const json& j) {
  Mode m;
  m.freq_hz = j.at("f").get<double>();
  m.damped_freq_hz = j.at("fd").get<double>();
  m.damping_ratio = j.at("z").get<double>();
  m.rigid_body = j.at("rb").get<bool>();
  m.first_order = j.at("fo").get<bool>();
  m.name = j.at("name").get<std::string>();
  const auto re = j.at("re").get<std::vector<double>>(), im = j.at("im").get<std::vector<double>>();
  m.shape.resize(static_cast<Eigen::Index>(re.size()));
  for (size_t i = 0; i < re.size(); ++i) m.shape(static_cast<Eigen::Index>(i)) = {re.at(i), im.at(i)};
  const auto p = j.at("p").get<std::vector<double>>();
  m.participation = Eigen::Map<const VecX>(p.data(), static_cast<Eigen::Index>(p.size()));
  if (j.contains("res")) m.residual = j["res"].get<double>();
  return m;
}

}  // namespace

std::string encodeCampbellPoint(const CampbellPoint& pt) {
  json j;
  j["rpm"] = pt.rpm;
  if (pt.wind_speed) j["ws"] = *pt.wind_speed;
  if (pt.pitch_deg) j["pitch"] = *pt.pitch_deg;
  j["coords"] = pt.coordinates;
  if (!pt.validity_problems.empty()) j["invalid"] = pt.validity_problems;
  j["modes"] = json::array();
  for (const auto& m : pt.modes) j["modes"].push_back(encodeMode(m));
  return cborBytes(j);
}

CampbellPoint decodeCampbellPoint(const std::string& bytes) {
  return decodeCborBytes(bytes, "campbell point", [](const json& j) {
    CampbellPoint pt;
    pt.rpm = j.at("rpm").get<double>();
    if (j.contains("ws")) pt.wind_speed = j["ws"].get<double>();
    if (j.contains("pitch")) pt.pitch_deg = j["pitch"].get<double>();
    pt.coordinates = j.at("coords").get<std::vector<std::string>>();
    if (j.contains("invalid")) pt.validity_problems = j["invalid"].get<std::vector<std::string>>();
    for (const auto& m : j.at("modes")) pt.modes.push_back(decodeMode(m));
    return pt;
  });
}

}  // namespace whirl

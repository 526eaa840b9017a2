#include "modal/campbell_serialize.hpp"

#include <nlohmann/json.hpp>

#include "linearize/cbor_bytes.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

using nlohmann::json;

json encodeComplex(const Eigen::MatrixXcd& u) {
  std::vector<double> v;
  for (Eigen::Index c = 0; c < u.cols(); ++c)
    for (Eigen::Index r = 0; r < u.rows(); ++r) v.push_back(u(r, c).real()), v.push_back(u(r, c).imag());
  return {{"r", u.rows()}, {"c", u.cols()}, {"v", v}};
}

Eigen::MatrixXcd decodeComplex(const json& j) {
  const auto r = j.at("r").get<Eigen::Index>(), c = j.at("c").get<Eigen::Index>();
  const auto v = j.at("v").get<std::vector<double>>();
  if (v.size() != static_cast<std::size_t>(2 * r * c))
    throw ComputeError("campbell point: complex matrix of the wrong size");
  Eigen::MatrixXcd u(r, c);
  std::size_t k = 0;
  for (Eigen::Index jc = 0; jc < c; ++jc)
    for (Eigen::Index jr = 0; jr < r; ++jr, k += 2) u(jr, jc) = {v[k], v[k + 1]};
  return u;
}

json encodeReal(const MatX& a) { return encodeComplex(a.cast<std::complex<double>>()); }
MatX decodeReal(const json& j) { return decodeComplex(j).real(); }

json encodeMotion(const ModeMotion& mm) {
  json j;
  j["bodies"] = json::array();
  for (const BodyMotion& b : mm.bodies)
    j["bodies"].push_back({{"body", b.body},
                           {"blade", b.blade},
                           {"role", b.role},
                           {"nodes", b.nodes},
                           {"x", encodeReal(b.x)},
                           {"pos", encodeReal(b.position)},
                           {"R", encodeReal(b.R)},
                           {"u", encodeComplex(b.u)}});
  j["coll"] = encodeComplex(mm.collective);
  j["bw"] = encodeComplex(mm.backward);
  j["fw"] = encodeComplex(mm.forward);
  j["bnodes"] = mm.blade_nodes;
  j["bx"] = encodeReal(mm.blade_x);
  return j;
}

ModeMotion decodeMotion(const json& j) {
  ModeMotion mm;
  for (const json& jb : j.at("bodies")) {
    BodyMotion b;
    b.body = jb.at("body").get<std::string>();
    b.blade = jb.at("blade").get<int>();
    b.role = jb.at("role").get<std::string>();
    b.nodes = jb.at("nodes").get<std::vector<std::string>>();
    b.x = decodeReal(jb.at("x"));
    b.position = decodeReal(jb.at("pos"));
    b.R = decodeReal(jb.at("R"));
    b.u = decodeComplex(jb.at("u"));
    mm.bodies.push_back(std::move(b));
  }
  mm.collective = decodeComplex(j.at("coll"));
  mm.backward = decodeComplex(j.at("bw"));
  mm.forward = decodeComplex(j.at("fw"));
  mm.blade_nodes = j.at("bnodes").get<std::vector<std::string>>();
  mm.blade_x = decodeReal(j.at("bx"));
  return mm;
}

json encodeMode(const Mode& m) {
  json j;
  j["f"] = m.freq_hz;
  j["fd"] = m.damped_freq_hz;
  j["z"] = m.damping_ratio;
  j["rb"] = m.rigid_body;
  j["fo"] = m.first_order;
  j["name"] = m.name;
  j["ev"] = {m.name_share, m.runner_up_share};
  j["ru"] = m.runner_up;
  j["amb"] = m.ambiguous;
  std::vector<double> re(m.shape.size()), im(m.shape.size());
  for (Eigen::Index i = 0; i < m.shape.size(); ++i) {
    re[i] = m.shape(i).real();
    im[i] = m.shape(i).imag();
  }
  j["re"] = re;
  j["im"] = im;
  j["p"] = std::vector<double>(m.participation.data(), m.participation.data() + m.participation.size());
  if (m.residual) j["res"] = *m.residual;
  if (!m.motion.empty()) j["motion"] = encodeMotion(m.motion);
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
  const auto ev = j.at("ev").get<std::vector<double>>();
  if (ev.size() != 2) throw ComputeError("campbell point: name evidence of the wrong size");
  m.name_share = ev[0];
  m.runner_up_share = ev[1];
  m.runner_up = j.at("ru").get<std::string>();
  m.ambiguous = j.at("amb").get<bool>();
  const auto re = j.at("re").get<std::vector<double>>(), im = j.at("im").get<std::vector<double>>();
  m.shape.resize(static_cast<Eigen::Index>(re.size()));
  for (size_t i = 0; i < re.size(); ++i) m.shape(static_cast<Eigen::Index>(i)) = {re.at(i), im.at(i)};
  const auto p = j.at("p").get<std::vector<double>>();
  m.participation = Eigen::Map<const VecX>(p.data(), static_cast<Eigen::Index>(p.size()));
  if (j.contains("res")) m.residual = j["res"].get<double>();
  if (j.contains("motion")) m.motion = decodeMotion(j["motion"]);
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

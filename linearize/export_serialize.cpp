#include "linearize/export_serialize.hpp"

#include <cstdint>
#include <nlohmann/json.hpp>

#include "linearize/cbor_bytes.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

using nlohmann::json;

struct Corrupt : std::runtime_error {
  using std::runtime_error::runtime_error;
};

json doubles(const double* v, size_t n) { return cborDoubles(v, n); }
void readDoubles(const json& j, double* v, size_t n) { readCborDoubles(j, v, n); }

json scalar(double x) { return doubles(&x, 1); }
double readScalar(const json& j) {
  double x;
  readDoubles(j, &x, 1);
  return x;
}

json matrix(const MatX& m) {
  return {{"r", m.rows()}, {"c", m.cols()}, {"v", doubles(m.data(), static_cast<size_t>(m.size()))}};
}

MatX readMatrix(const json& j) {
  const auto r = j.at("r").get<std::int64_t>(), c = j.at("c").get<std::int64_t>();
  const size_t bytes = j.at("v").get_binary().size();
  // Checked before allocating: a corrupt size must not ask for gigabytes.
  if (r < 0 || c < 0 || (r > 0 && static_cast<std::uint64_t>(c) > bytes / 8 / static_cast<std::uint64_t>(r)))
    throw Corrupt("matrix " + std::to_string(r) + " x " + std::to_string(c) + " in " + std::to_string(bytes) +
                  " bytes");
  MatX m(r, c);
  readDoubles(j.at("v"), m.data(), static_cast<size_t>(m.size()));
  return m;
}

json vec(const VecX& v) { return doubles(v.data(), static_cast<size_t>(v.size())); }
VecX readVector(const json& j) {
  VecX v(static_cast<Eigen::Index>(j.get_binary().size() / 8));
  readDoubles(j, v.data(), static_cast<size_t>(v.size()));
  return v;
}

// A list of variables as parallel columns.
json variables(const std::vector<StateSpaceVariable>& vars) {
  json j = {{"name", json::array()},
            {"unit", json::array()},
            {"blade", json::array()},
            {"rate_of", json::array()},
            {"azimuth", json::array()}};
  std::vector<double> op;
  for (const auto& v : vars) {
    j["name"].push_back(v.name);
    j["unit"].push_back(v.unit);
    j["blade"].push_back(v.blade);
    j["rate_of"].push_back(v.rate_of);
    j["azimuth"].push_back(v.azimuth);
    op.push_back(v.op);
  }
  j["op"] = doubles(op.data(), op.size());
  return j;
}

std::vector<StateSpaceVariable> readVariables(const json& j) {
  const size_t n = j.at("name").size();
  for (const char* col : {"unit", "blade", "rate_of", "azimuth"})
    if (j.at(col).size() != n) throw Corrupt(std::string("variable column ") + col + " of another length");
  std::vector<StateSpaceVariable> vars(n);
  std::vector<double> op(n);
  readDoubles(j.at("op"), op.data(), n);
  for (size_t i = 0; i < n; ++i) {
    vars[i].name = j.at("name").at(i).get<std::string>();
    vars[i].unit = j.at("unit").at(i).get<std::string>();
    vars[i].blade = j.at("blade").at(i).get<int>();
    vars[i].rate_of = j.at("rate_of").at(i).get<int>();
    vars[i].azimuth = j.at("azimuth").at(i).get<bool>();
    vars[i].op = op[i];
  }
  return vars;
}

json model(const StateSpaceModel& s) {
  json j = {{"x", variables(s.x)},     {"u", variables(s.u)},
            {"y", variables(s.y)},     {"xdot_op", vec(s.xdot_op)},
            {"A", matrix(s.A)},        {"B", matrix(s.B)},
            {"C", matrix(s.C)},        {"D", matrix(s.D)},
            {"az", scalar(s.azimuth)}, {"omega", scalar(s.rotor_speed)},
            {"mbc", s.multiblade}};
  if (s.wind_speed) j["ws"] = scalar(*s.wind_speed);
  return j;
}

StateSpaceModel readModel(const json& j) {
  StateSpaceModel s;
  s.x = readVariables(j.at("x"));
  s.u = readVariables(j.at("u"));
  s.y = readVariables(j.at("y"));
  s.xdot_op = readVector(j.at("xdot_op"));
  s.A = readMatrix(j.at("A"));
  s.B = readMatrix(j.at("B"));
  s.C = readMatrix(j.at("C"));
  s.D = readMatrix(j.at("D"));
  s.azimuth = readScalar(j.at("az"));
  s.rotor_speed = readScalar(j.at("omega"));
  s.multiblade = j.at("mbc").get<bool>();
  if (j.contains("ws")) s.wind_speed = readScalar(j["ws"]);
  return s;
}

// The frozen wake travels with the point: linearizing at it again (the Python module's second-order
// matrices) needs the elements' induction.
json operatingPoint(const OperatingPoint& op) {
  return {{"q", vec(op.q)},
          {"ind_ax", vec(op.inflow.axial)},
          {"ind_tn", vec(op.inflow.tangential)},
          {"qd", vec(op.qd)},
          {"qdd", vec(op.qdd)},
          {"u", vec(op.u)},
          {"solved", op.solved},
          {"held", op.held},
          {"held_load", vec(op.held_load)},
          {"iter", op.iterations},
          {"res", scalar(op.residual_norm)},
          {"res_max", scalar(op.residual_max_active)},
          {"res_dof", op.residual_max_dof}};
}

OperatingPoint readOperatingPoint(const json& j) {
  OperatingPoint op;
  op.q = readVector(j.at("q"));
  op.inflow.axial = readVector(j.at("ind_ax"));
  op.inflow.tangential = readVector(j.at("ind_tn"));
  op.qd = readVector(j.at("qd"));
  op.qdd = readVector(j.at("qdd"));
  op.u = readVector(j.at("u"));
  op.solved = j.at("solved").get<std::vector<int>>();
  op.held = j.at("held").get<std::vector<int>>();
  op.held_load = readVector(j.at("held_load"));
  op.iterations = j.at("iter").get<int>();
  op.residual_norm = readScalar(j.at("res"));
  op.residual_max_active = readScalar(j.at("res_max"));
  op.residual_max_dof = j.at("res_dof").get<std::string>();
  return op;
}

}  // namespace

std::string encodeExportPoint(const ExportPoint& p) {
  json j = {{"rpm", scalar(p.rpm)},
            {"model", model(p.model)},
            {"azimuths", json::array()},
            {"equilibrium", operatingPoint(p.equilibrium)}};
  if (p.wind_speed) j["ws"] = scalar(*p.wind_speed);
  if (p.pitch_deg) j["pitch"] = scalar(*p.pitch_deg);
  for (const auto& s : p.azimuths) j["azimuths"].push_back(model(s));
  return cborBytes(j);
}

ExportPoint decodeExportPoint(const std::string& bytes) {
  return decodeCborBytes(bytes, "export point", [](const json& j) {
    ExportPoint p;
    p.rpm = readScalar(j.at("rpm"));
    if (j.contains("ws")) p.wind_speed = readScalar(j["ws"]);
    if (j.contains("pitch")) p.pitch_deg = readScalar(j["pitch"]);
    p.model = readModel(j.at("model"));
    for (const auto& s : j.at("azimuths")) p.azimuths.push_back(readModel(s));
    p.equilibrium = readOperatingPoint(j.at("equilibrium"));
    return p;
  });
}

}  // namespace whirl

#include "linearize/trim_serialize.hpp"

#include <nlohmann/json.hpp>

#include "linearize/cbor_bytes.hpp"

namespace whirl {
namespace {

using nlohmann::json;

json scalar(double x) { return cborDoubles(&x, 1); }

double readScalar(const json& j) {
  double x = 0;
  readCborDoubles(j, &x, 1);
  return x;
}

json doubleList(const std::vector<double>& v) { return cborDoubles(v.data(), v.size()); }

std::vector<double> readDoubleList(const json& j) {
  std::vector<double> v(j.get_binary().size() / 8);
  readCborDoubles(j, v.data(), v.size());
  return v;
}

// An optional double: absent key = no value.
void putOptional(json& j, const char* key, const std::optional<double>& x) {
  if (x) j[key] = scalar(*x);
}

std::optional<double> readOptional(const json& j, const char* key) {
  if (!j.contains(key)) return std::nullopt;
  return readScalar(j.at(key));
}

json condition(const OperatingCondition& c) {
  json j = {{"omega", scalar(c.rotor_speed)}, {"offsets", doubleList(c.blade_pitch_offsets)}};
  putOptional(j, "azimuth", c.azimuth);
  putOptional(j, "pitch", c.collective_pitch);
  putOptional(j, "wind", c.wind_speed);
  putOptional(j, "gen_torque", c.generator_torque);
  putOptional(j, "yaw", c.yaw);
  return j;
}

OperatingCondition readCondition(const json& j) {
  OperatingCondition c;
  c.rotor_speed = readScalar(j.at("omega"));
  c.blade_pitch_offsets = readDoubleList(j.at("offsets"));
  c.azimuth = readOptional(j, "azimuth");
  c.collective_pitch = readOptional(j, "pitch");
  c.wind_speed = readOptional(j, "wind");
  c.generator_torque = readOptional(j, "gen_torque");
  c.yaw = readOptional(j, "yaw");
  return c;
}

// The scalars of a SteadyState, by key: one list for encoding and decoding, so neither can miss one.
template <class S, class F>
void eachScalar(S& s, F&& f) {
  f("min_pitch", s.min_pitch);
  f("gen_eff", s.generator_efficiency);
  f("aero_torque", s.aero_torque);
  f("thrust", s.thrust);
  f("gen_torque", s.generator_torque);
  f("gen_speed", s.generator_speed);
  f("imbalance", s.imbalance);
  f("tip", s.tip_deflection);
  f("ttfa", s.tower_top_fa);
  f("slope", s.search_slope);
}

json stateJson(const SteadyState& s) {
  json j = {{"condition", condition(s.condition)},
            {"above", s.above_rated},
            {"region", s.region},
            {"evaluations", s.evaluations},
            {"q", json::array()}};
  eachScalar(s, [&](const char* key, double x) { j[key] = scalar(x); });
  for (const VecX& q : s.azimuth_q) j["q"].push_back(cborDoubles(q.data(), static_cast<std::size_t>(q.size())));
  return j;
}

SteadyState readState(const json& j) {
  SteadyState s;
  s.condition = readCondition(j.at("condition"));
  s.above_rated = j.at("above").get<bool>();
  s.region = j.at("region").get<std::string>();
  s.evaluations = j.at("evaluations").get<int>();
  eachScalar(s, [&](const char* key, double& x) { x = readScalar(j.at(key)); });
  for (const json& q : j.at("q")) {
    VecX v(static_cast<Eigen::Index>(q.get_binary().size() / 8));
    readCborDoubles(q, v.data(), static_cast<std::size_t>(v.size()));
    s.azimuth_q.push_back(std::move(v));
  }
  return s;
}

}  // namespace

std::string encodeSteadyState(const SteadyState& s) { return cborBytes(stateJson(s)); }

SteadyState decodeSteadyState(const std::string& bytes) {
  return decodeCborBytes(bytes, "steady state", [](const json& j) { return readState(j); });
}

std::string encodeSteadyStates(const std::vector<SteadyState>& states) {
  json j = json::array();
  for (const SteadyState& s : states) j.push_back(stateJson(s));
  return cborBytes(j);
}

std::vector<SteadyState> decodeSteadyStates(const std::string& bytes) {
  return decodeCborBytes(bytes, "steady states", [](const json& j) {
    if (!j.is_array()) throw std::runtime_error("not a list of states");
    std::vector<SteadyState> out;
    for (const json& s : j) out.push_back(readState(s));
    return out;
  });
}

}  // namespace whirl

// OpenFAST's descriptions, units and scale factors of whirl's inputs and outputs (lin_channels.hpp).
#include "src/writers/lin_channels.hpp"

#include <map>
#include <numbers>
#include <regex>

namespace whirl {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;  // rad → deg
constexpr double kRpm = 30.0 / std::numbers::pi;   // rad/s → rpm

struct Known {
  const char* module;
  const char* unit;
  double scale;
};

// Output channels with an OpenFAST counterpart: module prefix, OpenFAST's unit, scale from SI. Blade
// channels ("RootMFlp1") are looked up without their blade number.
const std::map<std::string, Known>& knownOutputs() {
  static const std::map<std::string, Known> k = {
      {"GenSpeed", {"ED", "rpm", kRpm}},     {"RotSpeed", {"ED", "rpm", kRpm}},
      {"NacYaw", {"ED", "deg", kDeg}},       {"TTDspFA", {"ED", "m", 1}},
      {"TTDspSS", {"ED", "m", 1}},           {"YawBrTAxp", {"ED", "m/s^2", 1}},
      {"YawBrTAyp", {"ED", "m/s^2", 1}},     {"TwrBsMyt", {"ED", "kN-m", 1e-3}},
      {"TwrBsMxt", {"ED", "kN-m", 1e-3}},    {"RootMFlp", {"ED", "kN-m", 1e-3}},
      {"RootMEdg", {"ED", "kN-m", 1e-3}},    {"BldPitch", {"ED", "deg", kDeg}},
      {"TeetDefl", {"ED", "deg", kDeg}},     {"NcIMURAys", {"ED", "deg/s^2", kDeg}},
      {"YawBrTVxp", {"ED", "m/s", 1}},       {"NcIMURVys", {"ED", "deg/s", kDeg}},
      {"PtfmSurge", {"ED", "m", 1}},         {"PtfmSway", {"ED", "m", 1}},
      {"PtfmHeave", {"ED", "m", 1}},         {"PtfmRoll", {"ED", "deg", kDeg}},
      {"PtfmPitch", {"ED", "deg", kDeg}},    {"PtfmYaw", {"ED", "deg", kDeg}},
      {"PtfmTVxi", {"ED", "m/s", 1}},        {"PtfmTVyi", {"ED", "m/s", 1}},
      {"PtfmTVzi", {"ED", "m/s", 1}},        {"PtfmTAxi", {"ED", "m/s^2", 1}},
      {"PtfmTAyi", {"ED", "m/s^2", 1}},      {"PtfmTAzi", {"ED", "m/s^2", 1}},
      {"PtfmRVxi", {"ED", "deg/s", kDeg}},   {"PtfmRVyi", {"ED", "deg/s", kDeg}},
      {"PtfmRVzi", {"ED", "deg/s", kDeg}},   {"PtfmRAxi", {"ED", "deg/s^2", kDeg}},
      {"PtfmRAyi", {"ED", "deg/s^2", kDeg}}, {"PtfmRAzi", {"ED", "deg/s^2", kDeg}},
      {"RtSpeed", {"AD", "rpm", kRpm}},      {"RtAeroFxh", {"AD", "N", 1}},
      {"RtAeroMxh", {"AD", "N-m", 1}},       {"RtAeroPwr", {"AD", "W", 1}},
      {"GenTq", {"SrvD", "kN-m", 1e-3}},     {"GenPwr", {"SrvD", "kW", 1e-3}},
  };
  return k;
}

}  // namespace

LinChannel linInputChannel(const StateSpaceVariable& u) {
  static const std::regex blade(R"(blade (\d+) pitch)");
  std::smatch m;
  if (u.name == "wind speed") return {"IfW Extended input: horizontal wind speed (steady/uniform wind)", "m/s", 1, 0};
  if (std::regex_match(u.name, m, blade)) return {"ED Blade " + m[1].str() + " pitch command", "rad", 1, 1};
  if (u.name == "yaw moment") return {"ED Yaw moment", "Nm", 1, 2};
  if (u.name == "generator torque") return {"ED Generator torque", "Nm", 1, 3};
  if (u.name == "collective pitch") return {"ED Extended input: collective blade-pitch command", "rad", 1, 4};
  return {"whirl " + u.name, u.unit, 1, 5};
}

LinChannel linOutputChannel(const StateSpaceVariable& y) {
  static const std::regex blade(R"((RootMFlp|RootMEdg|BldPitch)([1-3]))");
  std::smatch m;
  const std::string key = std::regex_match(y.name, m, blade) ? m[1].str() : y.name;
  const auto it = knownOutputs().find(key);
  if (it == knownOutputs().end()) return {"whirl " + y.name, y.unit, 1, 99};
  return {std::string(it->second.module) + " " + y.name, it->second.unit, it->second.scale, 99};
}

std::string linInputDescription(const StateSpaceVariable& u) {
  const LinChannel c = linInputChannel(u);
  return c.unit.empty() ? c.text : c.text + ", " + c.unit;
}

std::string linOutputDescription(const StateSpaceVariable& y) {
  const LinChannel c = linOutputChannel(y);
  return c.unit.empty() ? c.text : c.text + ", (" + c.unit + ")";
}

}  // namespace whirl

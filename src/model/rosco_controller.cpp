#include "src/model/rosco_controller.hpp"

#include <algorithm>

namespace whirl {

Where RoscoController::at(const std::string& key) const {
  const auto it = where.find(key);
  if (it != where.end()) return it->second;
  return Where{file, 0, key, ""};
}

double roscoInterp(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  // Functions.f90, interp1d: the end values beyond the table, linear in between.
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const double x0 = xs[k - 1], x1 = xs[k];
  if (x1 == x0) return ys[k];
  return ys[k - 1] + (ys[k] - ys[k - 1]) * (x - x0) / (x1 - x0);
}

double roscoMinimumPitch(const RoscoController& c, double wind) {
  // Controllers.f90, PitchControl: PC_MinPit = max(PitchSaturation, PC_FinePit) with PS_Mode > 0, else
  // PC_FinePit; the actuated pitch is then held above the physical limit CntrPar%PC_MinPit.
  double lo = c.PC_FinePit;
  if (c.PS_Mode > 0) lo = std::max(lo, roscoInterp(c.PS_WindSpeeds, c.PS_BldPitchMin, wind));
  return std::max(lo, c.PC_MinPit);
}

RoscoPitchGains roscoPitchGains(const RoscoController& c, double pitch) {
  return {roscoInterp(c.PC_GS_angles, c.PC_GS_KP, pitch), roscoInterp(c.PC_GS_angles, c.PC_GS_KI, pitch)};
}

double roscoAboveRatedTorque(const RoscoController& c, double gen_speed) {
  // Controllers.f90, VariableSpeedControl: VS_ConstPwr_GenTq = VS_RtPwr/(VS_GenEff/100)/GenSpeedF,
  // VS_MaxTq = min(that, CntrPar%VS_MaxTq) with VS_ConstPower = 1, else VS_RtTq.
  if (c.VS_ConstPower == 1) return std::min(c.VS_RtPwr / c.VS_GenEff / gen_speed, c.VS_MaxTq);
  return std::min(c.VS_RtTq, c.VS_MaxTq);
}

double roscoTorqueLimit(const RoscoController& c, double gen_speed) {
  // TSR tracking: PIController(VS_SpdErr, …, VS_MinTq, LocalVar%VS_MaxTq); k·Ω²: region 2½'s PI
  // saturates at VS_ArSatTq (Controllers.f90, VariableSpeedControl).
  if (c.VS_ControlMode == 1) return std::min(c.VS_ArSatTq, c.VS_MaxTq);
  return roscoAboveRatedTorque(c, gen_speed);
}

}  // namespace whirl

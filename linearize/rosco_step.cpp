#include "linearize/rosco_step.hpp"

#include <algorithm>
#include <cmath>

#include <memory>

#include "linearize/simulation_setup.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace {

/// First-order low pass over a step dt with the input held: exact.
double lowPass(double y, double x, double corner, double dt) {
  return corner > 0 ? x + (y - x) * std::exp(-corner * dt) : x;
}

void require(const RoscoController& c, bool ok, const char* key, const std::string& why) {
  if (!ok) {
    const Where w = c.at(key);
    throw InputError(where(w.file, w.line, key, why + " (simulate --closed-loop runs ROSCO's VS_ControlMode 2 with "
                                                     "a first-order speed filter, no notches, no actuator model)"));
  }
}

double torqueLimit(const RoscoController& c, double speed) {
  return c.VS_ConstPower == 1 ? std::min(c.VS_RtPwr / c.VS_GenEff / speed, c.VS_MaxTq) : c.VS_RtTq;
}

}  // namespace

RoscoState roscoSteadyMemory(const RoscoController& c, const SteadyState& steady) {
  require(c, c.VS_ControlMode == 2, "VS_ControlMode", std::to_string(c.VS_ControlMode) + ": not in the time step");
  require(c, c.F_LPFType == 1, "F_LPFType", "2: not in the time step");
  require(c, c.gen_speed_notches.empty(), "F_GenSpdNotch_Ind", "notch filters: not in the time step");
  require(c, c.PA_Mode == 0, "PA_Mode", std::to_string(c.PA_Mode) + ": not in the time step");
  require(c, c.Fl_Mode == 0, "Fl_Mode", std::to_string(c.Fl_Mode) + ": not in the time step");
  require(c, !c.VS_KP.empty() && !c.VS_KI.empty(), "VS_KP", "no torque gains");
  RoscoState s;
  const double wind = steady.condition.wind_speed.value_or(0);
  s.speed = steady.generator_speed;
  s.reference = c.VS_TSRopt * wind / c.WE_BladeRadius * c.WE_GearboxRatio;
  s.pitch = steady.condition.collective_pitch.value_or(0);
  s.torque = steady.generator_torque;
  s.pitch_integral = s.pitch;    // every error zero: the command is the integral term
  s.torque_integral = s.torque;
  return s;
}

RoscoCommand roscoStep(const RoscoController& c, RoscoState& s, double gen_speed, double wind, double dt) {
  s.speed = lowPass(s.speed, gen_speed, c.F_LPFCornerFreq, dt);
  // Torque: PI on the TSR reference (ComputeVariablesSetpoints, VariableSpeedControl).
  s.reference = lowPass(s.reference, c.VS_TSRopt * wind / c.WE_BladeRadius * c.WE_GearboxRatio, c.F_VSRefSpdCornerFreq, dt);
  const double ref = std::max(std::clamp(s.reference, c.VS_MinOMSpd, c.VS_RefSpd), c.VS_MinOMSpd);
  const double t_max = std::min(torqueLimit(c, s.speed), c.VS_MaxTq);
  const double e_t = ref - s.speed;
  s.torque_integral = std::clamp(s.torque_integral + dt * c.VS_KI.front() * e_t, c.VS_MinTq, t_max);
  double torque = std::clamp(c.VS_KP.front() * e_t + s.torque_integral, c.VS_MinTq, t_max);
  torque = std::clamp(torque, s.torque - c.VS_MaxRat * dt, s.torque + c.VS_MaxRat * dt);
  // Pitch: gain-scheduled PI on PC_RefSpd, between the minimum-pitch schedule and PC_MaxPit.
  double pitch = s.pitch;
  if (c.PC_ControlMode == 1) {
    const RoscoPitchGains g = roscoPitchGains(c, s.pitch);
    const double lo = roscoMinimumPitch(c, wind), hi = c.PC_MaxPit;
    const double e_p = c.PC_RefSpd - s.speed;
    s.pitch_integral = std::clamp(s.pitch_integral + dt * g.ki * e_p, lo, hi);
    pitch = std::clamp(g.kp * e_p + s.pitch_integral, lo, hi);
    pitch = std::clamp(pitch, s.pitch + c.PC_MinRat * dt, s.pitch + c.PC_MaxRat * dt);
  }
  s.torque = torque;
  s.pitch = pitch;
  return {torque, pitch};
}

DiscreteController roscoInTheLoop(const Model& m, const RoscoController& c, const SteadyState& st, double dt,
                                  const OperatingPoint& start) {
  int gen = -1;
  for (size_t i = 0; i < m.outputs.size(); ++i)
    if (m.outputs[i].name == "GenSpeed") gen = static_cast<int>(i);
  if (gen < 0 || m.roles.wind_speed_input < 0 || m.roles.generator_torque_input < 0)
    throw InputError("simulate: --closed-loop needs the model's GenSpeed output, wind speed and generator torque inputs");
  DiscreteController k;
  k.dt = dt;
  k.inputs = {m.roles.generator_torque_input, simulationInput(m, "collective pitch", "controller")};
  auto memory = std::make_shared<RoscoState>(roscoSteadyMemory(c, st));
  const Output out = m.outputs[static_cast<size_t>(gen)];
  const int wind = m.roles.wind_speed_input;
  // The pitch input moves the blades from the start point's pitch (an increment on the frozen pitch
  // coordinates): the command is passed as its change from the steady pitch.
  const double pitch_offset = start.u(k.inputs[1]) - st.condition.collective_pitch.value_or(0);
  k.step = [c, memory, out, wind, dt, pitch_offset](double, const VecX&, const VecX& qd, const VecX& u) {
    double speed = 0;  // GenSpeed is a combination of coordinate rates
    for (const auto& [d, g] : out.terms) speed += g * qd(d);
    const RoscoCommand cmd = roscoStep(c, *memory, speed, u(wind), dt);
    VecX v(2);
    v << cmd.torque, cmd.pitch + pitch_offset;
    return v;
  };
  return k;
}


}  // namespace whirl

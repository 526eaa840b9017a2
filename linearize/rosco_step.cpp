#include "linearize/rosco_step.hpp"

#include <algorithm>
#include <cmath>

#include <memory>

#include "linearize/closed_loop.hpp"
#include "linearize/simulation_setup.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/outputs.hpp"

namespace whirl {
namespace {

/// First-order low pass over a step dt with the input held: exact.
double lowPass(double y, double x, double corner, double dt) {
  return corner > 0 ? x + (y - x) * std::exp(-corner * dt) : x;
}

void require(const RoscoController& c, bool ok, const char* key, const std::string& why) {
  if (!ok) {
    const Where w = c.at(key);
    throw InputError(where(w.file, w.line, key,
                           why + " (simulate --closed-loop runs ROSCO's VS_ControlMode 2 with "
                                 "a first-order speed filter, no notches on the speed, no actuator model)"));
  }
}

/// The floating feedback's filter chain (the linear model's, closed_loop.hpp) from velocity to pitch,
/// discretized by the trapezoidal (Tustin) rule at dt.
void discretizeFloatingFeedback(const RoscoController& c, const SteadyState& steady, double dt, RoscoState& s) {
  LinearController k;
  k.pitch_active = true;  // zero PI gains: the chain alone reaches the pitch input
  k.floating_mode = c.Fl_Mode;
  k.floating_kp = c.Fl_Kp.size() == 1 ? c.Fl_Kp.front()
                                      : roscoInterp(c.Fl_U, c.Fl_Kp, steady.condition.wind_speed.value_or(0));
  k.floating_lpf_freq = c.F_FlCornerFreq;
  k.floating_lpf_damping = c.F_FlCornerDamp;
  k.floating_hpf_freq = c.F_FlHighPassFreq;
  for (const RoscoNotch& n : c.twr_top_notches) k.floating_notches.push_back({n.freq, n.beta_num, n.beta_den});
  const StateSpaceModel f = controllerStateSpace(k);
  const Eigen::Index n = f.A.rows();
  const MatX I = MatX::Identity(n, n);
  const Eigen::PartialPivLU<MatX> lu(I - dt / 2 * f.A);
  s.fl_A = lu.solve(I + dt / 2 * f.A);
  s.fl_B = lu.solve(dt * f.B.col(4));
  s.fl_C = f.C.row(2).transpose();  // the actuator input: the PI's part is zero
  s.fl_D = f.D(2, 4);
  s.fl_x = VecX::Zero(n);
}

double torqueLimit(const RoscoController& c, double speed) {
  return c.VS_ConstPower == 1 ? std::min(c.VS_RtPwr / c.VS_GenEff / speed, c.VS_MaxTq) : c.VS_RtTq;
}

/// One output of the model evaluated from the state (a velocity: no accelerations needed).
struct FloatingSensor {
  Model model;
  Workspace<double> ws;
  VecX y, qdd;
  FloatingSensor(const Model& m, const std::string& name) : model(onlyOutput(m, name)), ws(model) {}
  static Model onlyOutput(const Model& m, const std::string& name) {
    const auto i = m.findOutput(name);
    if (!i) throw InputError(where("", 0, name, "the floating feedback needs this output of the model"));
    Model k = m;
    k.outputs = {m.outputs[static_cast<size_t>(*i)]};
    return k;
  }
  double read(const VecX& q, const VecX& qd, const VecX& u) {
    qdd = VecX::Zero(q.size());
    y = VecX::Zero(1);
    evaluateOutputs(model, ws, q, qd, qdd, y, &u);
    return y(0);
  }
};

}  // namespace

RoscoState roscoSteadyMemory(const RoscoController& c, const SteadyState& steady, double dt) {
  require(c, c.VS_ControlMode == 2, "VS_ControlMode", std::to_string(c.VS_ControlMode) + ": not in the time step");
  require(c, c.F_LPFType == 1, "F_LPFType", "2: not in the time step");
  require(c, c.gen_speed_notches.empty(), "F_GenSpdNotch_Ind", "notch filters: not in the time step");
  require(c, c.PA_Mode == 0, "PA_Mode", std::to_string(c.PA_Mode) + ": not in the time step");
  require(c, !c.VS_KP.empty() && !c.VS_KI.empty(), "VS_KP", "no torque gains");
  RoscoState s;
  const double wind = steady.condition.wind_speed.value_or(0);
  s.speed = steady.generator_speed;
  s.reference = c.VS_TSRopt * wind / c.WE_BladeRadius * c.WE_GearboxRatio;
  s.pitch = steady.condition.collective_pitch.value_or(0);
  s.torque = steady.generator_torque;
  s.pitch_integral = s.pitch;  // every error zero: the command is the integral term
  s.torque_integral = s.torque;
  // At rest the velocity is zero and so is every filter state (the high pass removes any offset).
  if (c.Fl_Mode > 0 && !c.Fl_Kp.empty()) discretizeFloatingFeedback(c, steady, dt, s);
  return s;
}

RoscoCommand roscoStep(const RoscoController& c, RoscoState& s, double gen_speed, double wind, double dt,
                       double floating_velocity) {
  s.speed = lowPass(s.speed, gen_speed, c.F_LPFCornerFreq, dt);
  // Torque: PI on the TSR reference (ComputeVariablesSetpoints, VariableSpeedControl).
  s.reference = lowPass(s.reference, c.VS_TSRopt * wind / c.WE_BladeRadius * c.WE_GearboxRatio, c.F_VSRefSpdCornerFreq,
                        dt);
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
    if (s.fl_x.size() > 0) {
      // FloatingFeedback adds to the PI's (saturated) command, then the whole is saturated again.
      s.fl_x = s.fl_A * s.fl_x + s.fl_B * (floating_velocity + s.fl_last) / 2;
      s.fl_last = floating_velocity;
      pitch = std::clamp(pitch + s.fl_C.dot(s.fl_x) + s.fl_D * floating_velocity, lo, hi);
    }
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
    throw InputError(
        "simulate: --closed-loop needs the model's GenSpeed output, wind speed and generator torque inputs");
  DiscreteController k;
  k.dt = dt;
  k.inputs = {m.roles.generator_torque_input, simulationInput(m, "collective pitch", "controller")};
  auto memory = std::make_shared<RoscoState>(roscoSteadyMemory(c, st, dt));
  const Output out = m.outputs[static_cast<size_t>(gen)];
  const int wind = m.roles.wind_speed_input;
  // The floating feedback's sensor: a model with that output alone, evaluated at each call.
  std::shared_ptr<FloatingSensor> sensor;
  if (memory->fl_x.size() > 0) sensor = std::make_shared<FloatingSensor>(m, c.Fl_Mode == 2 ? "NcIMURVys" : "YawBrTVxp");
  // The pitch input moves the blades from the start point's pitch (an increment on the frozen pitch
  // coordinates): the command is passed as its change from the steady pitch.
  const double pitch_offset = start.u(k.inputs[1]) - st.condition.collective_pitch.value_or(0);
  k.step = [c, memory, out, wind, dt, pitch_offset, sensor](double, const VecX& q, const VecX& qd, const VecX& u) {
    double speed = 0;  // GenSpeed is a combination of coordinate rates
    for (const auto& [d, g] : out.terms) speed += g * qd(d);
    const double velocity = sensor ? sensor->read(q, qd, u) : 0;
    const RoscoCommand cmd = roscoStep(c, *memory, speed, u(wind), dt, velocity);
    VecX v(2);
    v << cmd.torque, cmd.pitch + pitch_offset;
    return v;
  };
  return k;
}

}  // namespace whirl

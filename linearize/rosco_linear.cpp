#include "linearize/rosco_linear.hpp"

#include <algorithm>

#include "src/base/error.hpp"

namespace whirl {
namespace {

/// The torque ROSCO's region-3 law holds at generator speed ω: its slope dτ/dω_f [N m s/rad], 0 when
/// the torque is constant (VS_ConstPower = 0, or the constant-power torque capped at VS_MaxTq).
double regionThreeTorqueSlope(const RoscoController& c, double gen_speed) {
  if (c.VS_ConstPower != 1) return 0;
  const double power_torque = c.VS_RtPwr / c.VS_GenEff / gen_speed;
  if (power_torque >= c.VS_MaxTq) return 0;
  return -power_torque / gen_speed;
}

void setTorqueAtLimit(const RoscoController& c, double gen_speed, LinearController& k) {
  // TSR tracking saturates at the region-3 torque; k·Ω² with PI transitions at VS_ArSatTq (constant).
  const double slope = c.VS_ControlMode == 1 ? 0 : regionThreeTorqueSlope(c, gen_speed);
  if (slope == 0) return;
  k.torque = LinearController::Torque::Static;
  k.torque_slope = slope;
}

void setTorquePI(const RoscoController& c, LinearController& k) {
  k.torque = LinearController::Torque::PI;
  k.torque_kp = c.VS_KP.empty() ? 0 : c.VS_KP.front();
  k.torque_ki = c.VS_KI.empty() ? 0 : c.VS_KI.front();
}

/// ROSCO's floating feedback (Fl_Mode) on the pitch loop, its gain scheduled on the wind-speed estimate
/// (equal to the wind at a steady state); at a steady state the velocity is zero, so the schedule's
/// slope drops out as the pitch gains' does.
void setFloatingFeedback(const RoscoController& c, const SteadyState& s, LinearController& k) {
  if (c.Fl_Mode == 0 || c.Fl_Kp.empty()) return;
  const double wind = s.condition.wind_speed.value_or(0);
  k.floating_mode = c.Fl_Mode;
  k.floating_kp = c.Fl_Kp.size() == 1 ? c.Fl_Kp.front() : roscoInterp(c.Fl_U, c.Fl_Kp, wind);
  k.floating_lpf_freq = c.F_FlCornerFreq;
  k.floating_lpf_damping = c.F_FlCornerDamp;
  k.floating_hpf_freq = c.F_FlHighPassFreq;
  for (const RoscoNotch& n : c.twr_top_notches) k.floating_notches.push_back({n.freq, n.beta_num, n.beta_den});
}

}  // namespace

LinearController linearRosco(const RoscoController& c, const SteadyState& s, const RoscoLinearOptions& opt) {
  const std::string base = s.region.substr(0, s.region.find(" + "));
  if (base.empty())
    throw InputError(where(c.file, 0, "region", "the operating point was not trimmed with this controller"));
  LinearController k;
  k.lpf_order = opt.without_speed_filter ? 0 : c.F_LPFType;
  k.lpf_freq = c.F_LPFCornerFreq;
  k.lpf_damping = c.F_LPFDamping;
  for (const RoscoNotch& n : c.gen_speed_notches) k.notches.push_back({n.freq, n.beta_num, n.beta_den});
  const double w = s.generator_speed;
  if (base == "3") {
    if (c.PC_ControlMode == 1) {
      const RoscoPitchGains g = roscoPitchGains(c, s.condition.collective_pitch.value_or(0));
      k.pitch_active = true;
      k.pitch_kp = g.kp;
      k.pitch_ki = g.ki;
      k.actuator_order = c.PA_Mode;
      k.actuator_freq = c.PA_CornerFreq;
      k.actuator_damping = c.PA_Damping;
      setFloatingFeedback(c, s, k);
    }
    setTorqueAtLimit(c, w, k);
    if (c.VS_ControlMode == 1) {
      // k·Ω² with PI transitions: region 3 is constant power or constant torque by VS_ConstPower.
      const double slope = regionThreeTorqueSlope(c, w);
      if (slope != 0) k.torque = LinearController::Torque::Static, k.torque_slope = slope;
    }
  } else if (base == "2.5 saturated") {
    setTorqueAtLimit(c, w, k);
  } else if (base == "2.5" || base == "1.5") {
    setTorquePI(c, k);
  } else if (base == "2") {
    if (c.VS_ControlMode == 1) {
      k.torque = LinearController::Torque::Static;
      k.torque_slope = 2 * c.VS_Rgn2K * w;
    } else {
      setTorquePI(c, k);
      if (c.VS_ControlMode == 2) {
        k.reference_per_wind = c.VS_TSRopt * c.WE_GearboxRatio / c.WE_BladeRadius;
        k.reference_filter_freq = c.F_VSRefSpdCornerFreq;
      }
    }
  } else {
    throw InputError(where(c.file, 0, "region", "'" + s.region + "' is not one of ROSCO's regions"));
  }
  return k;
}

std::vector<std::string> linearRoscoNotes(const RoscoController& c) {
  std::vector<std::string> n;
  if (c.VS_ControlMode == 2)
    n.push_back(
        "VS_ControlMode = 2: below rated the torque loop's speed reference follows the wind (the wind-speed "
        "estimate taken equal to it) through its low pass F_VSRefSpdCornerFreq; the estimator's own "
        "dependence on rotor speed, pitch and torque is not in the linear model");
  if (c.VS_ControlMode == 3 || c.VS_ControlMode == 4)
    n.push_back("VS_ControlMode = " + std::to_string(c.VS_ControlMode) +
                ": in region 2 the torque loop's speed reference is held at its steady value (its dependence "
                "on the generator " +
                (c.VS_ControlMode == 3 ? std::string("power") : std::string("torque")) + " is left out)");
  if (c.SS_Mode == 1)
    n.push_back(
        "SS_Mode = 1: the setpoint smoother shifts the reference of the loop that is saturated at every "
        "steady state (the pitch loop's below rated, the torque loop's above), so it leaves the "
        "linear model unchanged");
  if (c.Fl_Mode > 0)
    n.push_back("Fl_Mode = " + std::to_string(c.Fl_Mode) + ": the floating feedback acts in region 3 (below rated " +
                "the pitch sits at its minimum, where ROSCO's saturation passes only the positive half of it); " +
                "the integral of the filtered " +
                (c.Fl_Mode == 1 ? std::string("tower-top acceleration is the filtered velocity YawBrTVxp")
                                : std::string("nacelle pitch acceleration is the filtered pitch rate NcIMURVys")));
  if (c.PA_Mode == 0)
    n.push_back("PA_Mode = 0: no pitch actuator in the controller; the pitch command is the blades' pitch");
  n.push_back(
      "discrete-time filters and integrators as their continuous equivalents (phase error ω·DT/2), the "
      "sample-and-hold delay and rate limits (PC_MaxRat, VS_MaxRat) left out");
  return n;
}

}  // namespace whirl

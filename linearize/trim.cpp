#include "linearize/trim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "src/base/brent.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/generator_torque.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace {

// Generator speed per unit rotor speed: the GenSpeed output's gain on the rotor azimuth (the torque law's
// speed output, or the model's "GenSpeed" without a law); 0 without one.
double gearRatio(const Model& m, int azimuth) {
  const int out = m.generator.active() ? m.generator.speed_output : m.findOutput("GenSpeed").value_or(-1);
  if (out < 0) return 0;
  double g = 0;
  for (const auto& [d, k] : m.outputs[out].terms)
    if (d == azimuth) g += k;
  return g;
}

struct Balance {
  double f = 0;  ///< azimuth-averaged generalized force on the rotor azimuth [N m]
  double torque = 0, thrust = 0, tip = 0, tower = 0;
};

// Out-of-plane elastic displacement of the last element of blade 1 [m]: its displacement in the body
// frame, along the body's y axis turned back by the pitch (AeroDyn's x of the blade, aero_model.hpp).
double tipDeflection(const Model& m, const VecX& q) {
  const AeroBlade& bl = m.aero.blades.front();
  const Body& b = m.bodies[bl.body];
  const BodyPoint& pt = b.points[bl.stations.back().point];
  Vec3 s = Vec3::Zero();
  for (int j = 0; j < b.inertia.ne; ++j) s += pt.P.col(1 + j) * q(b.elastic_dof + j);
  const double pitch = bl.pitch_dof >= 0 ? q(bl.pitch_dof) : 0.0;
  return s.dot(axisRotation(b.axis, -pitch) * Vec3::UnitY());
}

// Torque balance at (Ω, β): the mean of the generalized force on the rotor azimuth over equilibria at n
// azimuths k·2π/(B n) (B blades): one blade passage, the period of the BP torque ripple of gravity,
// tilt and shear, which the mean then removes up to its n-th harmonic.
class TorqueBalance {
 public:
  TorqueBalance(const Model& m, double wind, const TrimOptions& opt)
      : m_(m), wind_(wind), opt_(opt), lw_(m), guess_(opt.azimuths), y_(m.noutput()) {
    tower_ = m.findOutput("TTDspFA").value_or(-1);
  }
  /// Starts from a neighbouring wind speed's equilibria (TrimGuess::q, stiffness).
  TorqueBalance(const Model& m, double wind, const TrimGuess& g, const TrimOptions& opt) : TorqueBalance(m, wind, opt) {
    if (g.q.size() != guess_.size() || g.stiffness.size() != stiffness_.size()) return;
    guess_ = g.q;
    stiffness_ = g.stiffness;
  }

  /// The balance at rotor speed `omega`, pitch `pitch` and, when not NaN, the generator torque `torque`
  /// [N m] as the generator-torque input (a controller's torque; NaN: the model's torque law).
  Balance operator()(double omega, double pitch, double torque = std::numeric_limits<double>::quiet_NaN()) {
    for (const auto& [w, p, t, b] : done_)  // the root finder's last point, evaluated again at the end
      if (w == omega && p == pitch && (t == torque || (std::isnan(t) && std::isnan(torque)))) return b;
    done_.push_back({omega, pitch, torque, evaluate(omega, pitch, torque)});
    return std::get<3>(done_.back());
  }

  int evaluations = 0;
  /// The last evaluation's equilibria (all coordinates) and Newton matrices, per azimuth.
  const std::vector<VecX>& equilibria() const { return guess_; }
  const std::vector<MatX>& stiffness() const { return stiffness_; }

 private:
  Balance evaluate(double omega, double pitch, double torque) {
    ++evaluations;
    Balance b;
    const int az = m_.roles.azimuth.front();
    const int blades = std::max<int>(1, static_cast<int>(m_.aero.blades.size()));
    // Where this point lies on the line through the last two (0: not on it, or fewer than two).
    double s = 0.0;
    if (evaluations > 2) {
      const auto& [w1, p1] = at_[1];
      const auto& [w0, p0] = at_[0];
      if (w1 == w0 && omega == w1 && p1 != p0) s = (pitch - p1) / (p1 - p0);
      if (p1 == p0 && pitch == p1 && w1 != w0) s = (omega - w1) / (w1 - w0);
      if (!(std::abs(s) <= 2.0)) s = 0.0;  // a far step: the line says little there
    }
    at_[0] = at_[1];
    at_[1] = {omega, pitch};
    previous_.resize(guess_.size());
    const std::vector<int> active = m_.activeDofs();
    for (int k = 0; k < opt_.azimuths; ++k) {
      OperatingCondition c;
      c.wind_speed = wind_;
      c.rotor_speed = omega;
      c.collective_pitch = pitch;
      c.azimuth = 2 * std::numbers::pi * k / (blades * opt_.azimuths);
      if (!std::isnan(torque)) c.generator_torque = torque;
      OperatingPoint start = initialPoint(m_, c);
      // Warm start: the previous evaluation's deflections at this azimuth, and its Newton matrix for
      // chord steps (the stiffness barely changes between the trim's nearby rotor speeds or pitches).
      EquilibriumOptions eq;
      eq.newton_matrix = &stiffness_[k];
      OperatingPoint cold;
      if (guess_[k].size() == start.q.size()) {
        cold = start;
        copyDeflections(m_, guess_[k], start.q);
        // The search moves one variable (rotor speed or pitch) along a smooth branch of equilibria:
        // the last two evaluations' deflections extrapolated to this one start ~10–100× closer.
        if (s != 0.0 && previous_[k].size() == start.q.size())
          for (int i : active)
            if (!m_.dofs[i].rotating) start.q(i) += s * (guess_[k](i) - previous_[k](i));
        eq.load_scale = scale_[k];  // the tolerance of the cold start this continues (0: not solved here yet)
        eq.scale_from = &cold;
        if (stiffness_[k].size() > 0) eq.chord_matrix = &stiffness_[k];
      }
      const OperatingPoint op = solveOperatingPoint(m_, start, eq, lw_);
      previous_[k] = std::move(guess_[k]);
      guess_[k] = op.q;
      scale_[k] = op.load_scale;
      const double w = 1.0 / opt_.azimuths;
      b.f += w * op.e(az);
      b.torque += w * op.aero.torque;
      b.thrust += w * op.aero.thrust;
      b.tip += w * tipDeflection(m_, op.q);
      if (tower_ >= 0) {
        evaluateOutputs(m_, lw_.ws, op.q, op.qd, op.qdd, y_, &op.u, &op.inflow);
        b.tower += w * y_(tower_);
      }
    }
    return b;
  }

  const Model& m_;
  double wind_;
  const TrimOptions& opt_;
  LinearizeWorkspace lw_;
  std::vector<VecX> guess_, previous_;             // per azimuth: the last evaluation's equilibria and the one's before
  std::array<std::pair<double, double>, 2> at_{};  // (rotor speed, pitch) of those two evaluations
  std::vector<MatX> stiffness_ = std::vector<MatX>(static_cast<std::size_t>(opt_.azimuths));
  std::vector<double> scale_ = std::vector<double>(static_cast<std::size_t>(opt_.azimuths), 0.0);
  VecX y_;
  int tower_ = -1;
  std::vector<std::tuple<double, double, double, Balance>> done_;
};

// Checks what a steady state needs; `at` starts every message.
void requireSteadyModel(const Model& m, const std::string& at) {
  if (!m.aero.active()) throw InputError(at + "the model has no aerodynamics");
  if (m.roles.azimuth.empty()) throw InputError(at + "the model has no rotating coordinate");
}

SteadyState stateOf(const Model& m, const OperatingCondition& c, TorqueBalance& balance) {
  const Balance b = balance(c.rotor_speed, *c.collective_pitch,
                            c.generator_torque.value_or(std::numeric_limits<double>::quiet_NaN()));
  SteadyState out;
  out.condition = c;
  out.aero_torque = b.torque;
  out.thrust = b.thrust;
  out.imbalance = b.f;
  out.tip_deflection = b.tip;
  out.tower_top_fa = b.tower;
  out.evaluations = balance.evaluations;
  out.azimuth_q = balance.equilibria();
  out.azimuth_stiffness = balance.stiffness();
  if (m.generator.active()) {
    out.generator_speed = gearRatio(m, m.roles.azimuth.front()) * c.rotor_speed;
    out.generator_torque = generatorTorque(m.generator, out.generator_speed);
  } else if (c.generator_torque) {
    out.generator_speed = gearRatio(m, m.roles.azimuth.front()) * c.rotor_speed;
    out.generator_torque = *c.generator_torque;
  }
  return out;
}

std::string rpmText(double omega) { return std::to_string(omega * 30 / std::numbers::pi) + " rpm"; }

}  // namespace

SteadyState steadyState(const Model& m, const OperatingCondition& c, const TrimOptions& opt) {
  requireSteadyModel(m, "steady state: ");
  if (!c.wind_speed) throw InputError("steady state: no wind speed");
  TorqueBalance balance(m, *c.wind_speed, opt);
  OperatingCondition cp = c;
  cp.collective_pitch = c.collective_pitch.value_or(opt.min_pitch);
  return stateOf(m, cp, balance);
}

namespace {

// A root of the decreasing function f on [lo, hi] (f(lo) > 0 > f(hi); flo, fhi when known, else
// NaN), searched from the guess g: a first step aimed at the root with `slope` (f' at a neighbour's
// root, if negative), else a step of δ towards it; then secant steps aimed a fifth past it, until a
// pair brackets the root or the balance is within ftol; Brent then needs a step or two on that short
// bracket instead of a dozen on the whole range. A guess far off (the first pitched wind speed after
// rated) costs a step or two more, not the whole range. An end of the range is evaluated by `outer`
// (which may throw to say the root is not in the range). `slope` receives f' of the search's first
// pair (0 if none).
template <class F>
BrentResult guessedRoot(F&& f, double lo, double hi, double flo, double fhi, double g, double delta, double ftol,
                        const std::function<double(double)>& outer, double& slope) {
  auto at = [&](double x) {
    if (x == lo) return std::isnan(flo) ? (flo = outer(lo)) : flo;
    if (x == hi) return std::isnan(fhi) ? (fhi = outer(hi)) : fhi;
    return f(x);
  };
  const double hint = slope;
  slope = 0;
  double x0 = std::clamp(g, lo, hi), f0 = at(x0);
  int evals = 1;
  if (std::abs(f0) < ftol) return {x0, f0, evals, true};
  const double dir = f0 > 0 ? 1.0 : -1.0;  // f decreases: the root is above x0 where f > 0
  double step = hint < 0 ? std::clamp(std::abs(f0 / hint), 1e-3 * delta, 8 * delta) : delta;
  for (int k = 0; k < 8; ++k) {
    const double x1 = std::clamp(x0 + dir * step, lo, hi);
    if (x1 == x0) break;  // at an end with the root beyond it
    const double f1 = at(x1);
    ++evals;
    const double secant = (f1 - f0) / (x1 - x0);
    if (k == 0) slope = secant;
    if (std::abs(f1) < ftol) return {x1, f1, evals, true};
    if ((f1 > 0) != (f0 > 0)) {
      BrentResult r = brent(f, std::min(x0, x1), std::max(x0, x1), x0 < x1 ? f0 : f1, x0 < x1 ? f1 : f0, ftol, 1e-10,
                            100);
      r.evals += evals;
      return r;
    }
    // The secant's distance to the root, 1.2× (to land past it), at least the last step, at most 8×.
    const double reach = secant < 0 ? 1.2 * std::abs(f1 / secant) : 8 * step;
    step = std::clamp(reach, std::abs(x1 - x0), 8 * std::abs(x1 - x0));
    x0 = x1, f0 = f1;
  }
  return {x0, f0, evals, false};
}

// The generator torque [N m] that balances the rotor at rotor speed `omega` and pitch `beta`: the
// balance falls by about `gear` per N m of generator torque (the torque acts through the gearbox), and
// is close to linear in it (only the deflections move), so secant steps from that first step converge
// in two or three evaluations.
double balancingTorque(TorqueBalance& balance, double omega, double beta, double gear, double ftol,
                       const std::string& at) {
  double t0 = 0.0, f0 = balance(omega, beta, t0).f;
  if (std::abs(f0) < ftol) return t0;
  double t1 = t0 + f0 / gear, f1 = balance(omega, beta, t1).f;
  for (int k = 0; k < 20 && std::abs(f1) >= ftol; ++k) {
    const double slope = (f1 - f0) / (t1 - t0);
    if (!(slope < 0)) break;
    t0 = t1, f0 = f1;
    t1 = t0 - f0 / slope;
    f1 = balance(omega, beta, t1).f;
  }
  if (!(std::abs(f1) < ftol)) throw ComputeError(at + "the generator-torque balance did not converge");
  return t1;
}

// The checks of a trim with ROSCO: a generator speed output on the rotor azimuth (gear > 0), a
// generator-torque input, and torque control.
void requireControllerTrim(const Model& m, const RoscoController& c, double gear, const std::string& at) {
  if (!(gear > 0)) throw InputError(at + "the model has no generator speed output (GenSpeed) on the rotor azimuth");
  if (m.roles.generator_torque_input < 0) throw InputError(at + "the model has no generator-torque input");
  if (c.VS_ControlMode == 0) {
    const Where w = c.at("VS_ControlMode");
    throw InputError(where(w.file, w.line, w.key, "0: no torque control, so no steady state to trim to"));
  }
}

// What ROSCO's trim at one wind speed [m/s] works with: the balance, the gearbox ratio, the balance's
// tolerance [N m], the minimum pitch [rad] and the messages' prefix `at`.
struct ControllerTrim {
  const Model& m;
  const RoscoController& c;
  const TrimOptions& opt;
  TorqueBalance& balance;
  double wind, gear, ftol, beta_min;
  const std::string& at;
  // A generator speed [rad/s] as the rotor speed in rpm.
  std::string rpmOf(double gen_speed) const {
    const double rpm = 30 / std::numbers::pi;
    return std::to_string(gen_speed / gear * rpm) + " rpm";
  }
};

// The point ROSCO's trim settles at: rotor speed [rad/s], generator torque [N m], pitch [rad], and the
// controller's region.
struct ControllerPoint {
  double omega = 0, torque = std::numeric_limits<double>::quiet_NaN(), pitch = 0;
  std::string region;
};

// The torque loop at the minimum pitch: its speed reference and the branch it is on (TSR tracking:
// TSRopt·V/R clipped to [VS_MinOMSpd, VS_RefSpd]; k·Ω²: the balance with Rgn2K·ω², clipped likewise),
// with the torque that balances the rotor there. ComputeError below cut-in (torque below VS_MinTq).
ControllerPoint torqueLoopPoint(const ControllerTrim& x) {
  const RoscoController& c = x.c;
  const double gear = x.gear;
  ControllerPoint p;
  p.pitch = x.beta_min;
  const double w_lo = std::max(c.VS_MinOMSpd / gear,
                               c.VS_MinOMSpd > 0 ? 0.0 : x.opt.min_tsr * x.wind / x.m.aero.rotor_radius);
  const double w_hi = c.VS_RefSpd / gear;
  if (c.VS_ControlMode == 2) {
    const double ref = c.VS_TSRopt * x.wind / c.WE_BladeRadius * c.WE_GearboxRatio;  // ComputeVariablesSetpoints
    p.omega = std::clamp(ref, c.VS_MinOMSpd, c.VS_RefSpd) / gear;
    p.region = ref <= c.VS_MinOMSpd ? "1.5" : ref >= c.VS_RefSpd ? "2.5" : "2";
  } else {
    // k·Ω² (1) and the power- or torque-based TSR tracking (3, 4), whose references settle on k·Ω².
    auto fk = [&](double w) {
      const double wg = gear * w;
      return x.balance(w, x.beta_min, c.VS_Rgn2K * wg * wg).f;
    };
    const double f_lo = fk(w_lo), f_hi = fk(w_hi);
    if (f_lo <= 0) {
      p.omega = w_lo, p.region = "1.5";
    } else if (f_hi >= 0) {
      p.omega = w_hi, p.region = "2.5";
    } else {
      const BrentResult r = brent(fk, w_lo, w_hi, f_lo, f_hi, x.ftol, 1e-10, 100);
      if (!r.converged) throw ComputeError(x.at + "the rotor-speed trim on VS_Rgn2K did not converge");
      p.omega = r.x, p.region = "2";
      const double wg = gear * p.omega;
      p.torque = c.VS_Rgn2K * wg * wg;
    }
  }
  if (std::isnan(p.torque)) p.torque = balancingTorque(x.balance, p.omega, x.beta_min, gear, x.ftol, x.at);
  if (p.torque < c.VS_MinTq)
    throw ComputeError(x.at + "below cut-in: at the torque loop's speed " + x.rpmOf(gear * p.omega) +
                       " the aerodynamic torque needs a generator torque of " + std::to_string(p.torque) +
                       " N m, below VS_MinTq = " + std::to_string(c.VS_MinTq) + " N m");
  return p;
}

// Above rated, where the minimum pitch leaves excess aerodynamic torque at PC_RefSpd (f_min > 0 the
// balance there): the pitch loop holds PC_RefSpd with the region-3 torque t3 [N m], at the pitch that
// balances the rotor, searched from the neighbour's pitch when it is above the minimum.
ControllerPoint regionThreePoint(const ControllerTrim& x, const TrimGuess& guess, double f_min) {
  const RoscoController& c = x.c;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double w3 = c.PC_RefSpd / x.gear, t3 = roscoAboveRatedTorque(c, c.PC_RefSpd);
  const double p_hi = std::min(c.PC_MaxPit, x.opt.max_pitch);
  auto fp = [&](double b) { return x.balance(w3, b, t3).f; };
  auto top = [&](double b) {
    const double ft = fp(b);
    if (ft > 0)
      throw ComputeError(x.at + "the controller cannot hold rated speed " + x.rpmOf(c.PC_RefSpd) +
                         ": the aerodynamic torque exceeds the region-3 torque even at " +
                         std::to_string(p_hi * 180 / std::numbers::pi) + " deg pitch");
    return ft;
  };
  double slope = guess.pitch_slope;
  const BrentResult r = guess.pitch > x.beta_min
                            ? guessedRoot(fp, x.beta_min, p_hi, f_min, nan, guess.pitch, 0.01, x.ftol, top, slope)
                            : brent(fp, x.beta_min, p_hi, f_min, top(p_hi), x.ftol, 1e-10, 100);
  if (!r.converged) throw ComputeError(x.at + "the pitch trim did not converge");
  ControllerPoint p;
  p.omega = w3, p.torque = t3, p.pitch = r.x, p.region = "3";
  return p;
}

// Torque at its limit, pitch at its minimum: the speed rises above the torque loop's reference (of
// `below`) until the aerodynamic torque meets the limit, below the pitch loop's (f_min: the balance
// there at the region-3 torque, ≤ 0).
ControllerPoint saturatedTorquePoint(const ControllerTrim& x, const ControllerPoint& below, double f_min) {
  const RoscoController& c = x.c;
  const double gear = x.gear;
  const double w3 = c.PC_RefSpd / gear;
  auto fs = [&](double w) { return x.balance(w, x.beta_min, roscoTorqueLimit(c, gear * w)).f; };
  const double f_lo = fs(below.omega);
  if (!(w3 > below.omega) || !(f_lo > 0))
    throw ComputeError(x.at + "no steady state between the torque loop's speed " + x.rpmOf(gear * below.omega) +
                       " and the pitch loop's " + x.rpmOf(c.PC_RefSpd) + " with the torque at its limit");
  const BrentResult r = brent(fs, below.omega, w3, f_lo, f_min, x.ftol, 1e-10, 100);
  if (!r.converged) throw ComputeError(x.at + "the rotor-speed trim at the torque limit did not converge");
  ControllerPoint p;
  p.omega = r.x, p.torque = roscoTorqueLimit(c, gear * p.omega), p.pitch = x.beta_min, p.region = "2.5 saturated";
  return p;
}

// The pitch loop, when the torque loop's point needs more torque than the torque loop's limit: the
// region-3 point, or the saturated one when even the minimum pitch leaves too little aerodynamic torque
// at PC_RefSpd. ComputeError when the pitch control is off.
ControllerPoint pitchLoopPoint(const ControllerTrim& x, const TrimGuess& guess, const ControllerPoint& below) {
  const RoscoController& c = x.c;
  if (c.PC_ControlMode == 0)
    throw ComputeError(x.at + "the controller cannot hold rated speed: the aerodynamic torque needs " +
                       std::to_string(below.torque) + " N m at " + x.rpmOf(x.gear * below.omega) +
                       ", above the torque limit, and the pitch control is off (PC_ControlMode = 0)");
  const double w3 = c.PC_RefSpd / x.gear, t3 = roscoAboveRatedTorque(c, c.PC_RefSpd);
  const double f_min = x.balance(w3, x.beta_min, t3).f;
  return f_min > 0 ? regionThreePoint(x, guess, f_min) : saturatedTorquePoint(x, below, f_min);
}

// ROSCO's steady state at `wind` (docs/theory/controller.md): its wind-speed estimate equals the wind, its
// integrators have removed every speed error, and the generator torque balances the rotor. In turn:
// the torque loop's speed (TSR tracking: TSRopt·V/R clipped to [VS_MinOMSpd, VS_RefSpd]; k·Ω²: the
// balance with Rgn2K·ω², clipped likewise) at the minimum pitch, with the torque that balances it; if
// that torque exceeds the torque loop's limit, the pitch loop's rated speed PC_RefSpd with the region-3
// torque and the pitch that balances it; if even the minimum pitch leaves too little aerodynamic torque
// there, the speed between the two references where the saturated torque balances (region 2½ saturated).
// Controllers.f90 (VariableSpeedControl, PitchControl) and ControllerBlocks.f90
// (ComputeVariablesSetpoints, SetpointSmoother, whose shifts vanish in these steady states: below rated
// it only raises the pitch loop's reference, above rated only lowers the torque loop's).
SteadyState controllerTrim(const Model& m, double wind, const TrimGuess& guess, const TrimOptions& opt,
                           const std::string& at) {
  const RoscoController& c = *opt.controller;
  const double gear = gearRatio(m, m.roles.azimuth.front());
  requireControllerTrim(m, c, gear, at);
  const double ftol = opt.tolerance * std::max(1.0, gear * c.VS_RtTq);
  TorqueBalance balance(m, wind, guess, opt);
  const ControllerTrim x{m, c, opt, balance, wind, gear, ftol, roscoMinimumPitch(c, wind), at};
  ControllerPoint p = torqueLoopPoint(x);
  if (p.torque > roscoTorqueLimit(c, gear * p.omega)) p = pitchLoopPoint(x, guess, p);
  if (p.pitch == x.beta_min && x.beta_min > c.PC_FinePit) p.region += " + min pitch";
  OperatingCondition cond;
  cond.wind_speed = wind;
  cond.rotor_speed = p.omega;
  cond.collective_pitch = p.pitch;
  cond.generator_torque = p.torque;
  SteadyState out = stateOf(m, cond, balance);
  out.above_rated = p.region.starts_with("3");
  out.region = p.region;
  out.min_pitch = x.beta_min;
  out.generator_efficiency = c.VS_GenEff;
  return out;
}

}  // namespace

SteadyState trimAtWindSpeed(const Model& m, double wind, const TrimOptions& opt) {
  return trimAtWindSpeed(m, wind, TrimGuess{}, opt);
}

namespace {

// The rotor speed [rad/s] of a fixed-speed rotor (induction generator, `gear` generator per rotor speed):
// where the torque-slip curve meets the aerodynamic torque, at fine pitch, between the motoring and
// generating pull-out slips. ComputeError when the balance is not between them.
double inductionRotorSpeed(const Model& m, TorqueBalance& balance, double gear, double ftol, const TrimOptions& opt,
                           const std::string& at) {
  const auto [glo, ghi] = pulloutSpeeds(m.generator);
  const double lo = glo / gear, hi = ghi / gear;
  auto f = [&](double w) { return balance(w, opt.min_pitch).f; };
  const double flo = f(lo), fhi = f(hi);
  if (fhi > 0 || flo < 0)
    throw ComputeError(at + "no torque balance between the induction generator's pull-out slips (" + rpmText(lo) +
                       " to " + rpmText(hi) + "): the aerodynamic torque " +
                       (fhi > 0 ? "exceeds the pull-out torque (runaway)" : "is below the motoring pull-out torque"));
  const BrentResult r = brent(f, lo, hi, flo, fhi, ftol, 1e-10, 100);
  if (!r.converged) throw ComputeError(at + "the rotor-speed trim did not converge");
  return r.x;
}

// A variable-speed rotor's trim searches at one wind speed with the model's torque law: the balance f
// decreases with pitch [rad] at rated speed and with rotor speed [rad/s] at fine pitch, between the
// rotor speed `low` (tip-speed ratio opt.min_tsr) and `rated`.
struct TorqueLawSearch {
  TorqueBalance& balance;
  const TrimOptions& opt;
  const std::string& at;
  double rated, low, ftol;

  double atPitch(double p) const { return balance(rated, p).f; }          // at rated speed
  double atSpeed(double w) const { return balance(w, opt.min_pitch).f; }  // at fine pitch
  // At the top pitch: ComputeError if the torque still exceeds the rated torque.
  double atTopPitch(double p) const {
    const double ft = atPitch(p);
    if (ft > 0)
      throw ComputeError(at + "the aerodynamic torque exceeds the rated generator torque even at " +
                         std::to_string(opt.max_pitch * 180 / std::numbers::pi) + " deg pitch");
    return ft;
  }
  // At the lowest speed: ComputeError if the aerodynamic torque does not overcome the torque law there.
  double atLowSpeed(double w) const {
    const double fs = atSpeed(w);
    if (fs <= 0)
      throw ComputeError(at + "no torque balance between " + rpmText(low) + " (tip-speed ratio " +
                         std::to_string(opt.min_tsr) + ") and rated " + rpmText(rated) +
                         ": the aerodynamic torque does not overcome the generator torque law (below cut-in?)");
    return fs;
  }
};

// The guessed search met the balance at rated speed and fine pitch on the other side of rated.
struct OtherSide {};

// The search from a neighbour's trim (TrimGuess): the pitch when its pitch is above fine pitch (then
// `above`), the rotor speed when its speed is between `low` and rated; none without such a guess or
// when the search meets the other side of rated. search_slope: f' of the search (0 without one).
std::optional<BrentResult> guessedTorqueLawTrim(const TorqueLawSearch& s, const TrimGuess& guess, bool& above,
                                                double& search_slope) {
  const TrimOptions& opt = s.opt;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto fp = [&](double p) { return s.atPitch(p); };
  auto fw = [&](double w) { return s.atSpeed(w); };
  std::optional<BrentResult> r;
  try {
    if (guess.pitch > opt.min_pitch) {
      search_slope = guess.pitch_slope;
      r = guessedRoot(
          fp, opt.min_pitch, opt.max_pitch, nan, nan, guess.pitch, 0.01, s.ftol,
          [&](double p) {
            if (p != opt.min_pitch) return s.atTopPitch(p);
            const double f_fine = fp(p);
            if (f_fine <= 0) throw OtherSide{};
            return f_fine;
          },
          search_slope);
      above = true;
    } else if (guess.rotor_speed > s.low && guess.rotor_speed < s.rated) {
      search_slope = guess.speed_slope;
      r = guessedRoot(
          fw, s.low, s.rated, nan, nan, guess.rotor_speed, 0.01 * guess.rotor_speed, s.ftol,
          [&](double w) {
            if (w != s.rated) return s.atLowSpeed(w);
            const double f_rated = fw(w);
            if (f_rated > 0) throw OtherSide{};
            return f_rated;
          },
          search_slope);
    }
  } catch (const OtherSide&) {
    r.reset();
    above = false;
    search_slope = 0;
  }
  return r;
}

// The variable-speed rotor's trim with the model's torque law: above rated (excess torque at rated
// speed and fine pitch) the pitch that removes the excess; below, the rotor speed of the balance at
// fine pitch, above the tip-speed ratio opt.min_tsr (near standstill BEM has no solution on much of the
// blade, and AeroDyn itself blends the induction off at low tip-speed ratios). f decreases with pitch
// and with rotor speed (as every search here assumes), so a root bracketed next to a neighbour's pitch
// (speed) also shows the side of rated, without the balance at rated speed and fine pitch, whose
// equilibria are far from the root's. Sets omega [rad/s] or pitch [rad], above and search_slope.
void torqueLawTrim(const TorqueLawSearch& s, const TrimGuess& guess, double& omega, double& pitch, bool& above,
                   double& search_slope) {
  const TrimOptions& opt = s.opt;
  auto fp = [&](double p) { return s.atPitch(p); };
  auto fw = [&](double w) { return s.atSpeed(w); };
  std::optional<BrentResult> r = guessedTorqueLawTrim(s, guess, above, search_slope);
  if (!r) {
    const double at_rated = fw(s.rated);
    above = at_rated > 0;
    r = above ? brent(fp, opt.min_pitch, opt.max_pitch, at_rated, s.atTopPitch(opt.max_pitch), s.ftol, 1e-10, 100)
              : brent(fw, s.low, s.rated, s.atLowSpeed(s.low), at_rated, s.ftol, 1e-10, 100);
  }
  if (!r->converged)
    throw ComputeError(s.at + (above ? "the pitch trim did not converge" : "the rotor-speed trim did not converge"));
  (above ? pitch : omega) = r->x;
}

// The checks of a trim with the model's torque law; returns the generator speed per rotor speed.
double requireTorqueLawTrim(const Model& m, double wind, const std::string& at) {
  if (!m.generator.active())
    throw InputError(at + "the model has no generator torque law (ServoDyn VSContrl = 1, or 0 with GenModel = 1 or 2)");
  if (!(wind > 0) || !std::isfinite(wind)) throw InputError(at + "the wind speed must be positive");
  const double gear = gearRatio(m, m.roles.azimuth.front());
  if (!(gear > 0)) throw InputError(at + "the generator speed does not follow the rotor azimuth");
  return gear;
}

}  // namespace

SteadyState trimAtWindSpeed(const Model& m, double wind, const TrimGuess& guess, const TrimOptions& opt) {
  const std::string at = "trim at " + std::to_string(wind) + " m/s: ";
  requireSteadyModel(m, at);
  if (opt.controller) {
    if (!(wind > 0) || !std::isfinite(wind)) throw InputError(at + "the wind speed must be positive");
    return controllerTrim(m, wind, guess, opt, at);
  }
  const double gear = requireTorqueLawTrim(m, wind, at);
  const GeneratorTorqueLaw& law = m.generator;
  const double rated = law.rated_speed / gear;
  const double scale = std::max(1.0, gear * law.rated_torque);
  const double ftol = opt.tolerance * scale;
  TorqueBalance balance(m, wind, guess, opt);

  double omega = rated, pitch = opt.min_pitch;
  double search_slope = 0;  // f' of the guessed search, for the next wind speed's (SteadyState::search_slope)
  bool above = false;
  if (law.induction()) {
    omega = inductionRotorSpeed(m, balance, gear, ftol, opt, at);
  } else {
    const double low = std::min(0.5 * rated, opt.min_tsr * wind / m.aero.rotor_radius);
    torqueLawTrim(TorqueLawSearch{balance, opt, at, rated, low, ftol}, guess, omega, pitch, above, search_slope);
  }
  OperatingCondition c;
  c.wind_speed = wind;
  c.rotor_speed = omega;
  c.collective_pitch = pitch;
  SteadyState out = stateOf(m, c, balance);
  out.above_rated = above;
  out.search_slope = search_slope;
  return out;
}

SweepPoint sweepPointOf(const SteadyState& t) {
  const double rpm = t.condition.rotor_speed * 30 / std::numbers::pi;
  SweepPoint p = sweepPoint(rpm, t.condition.wind_speed, *t.condition.collective_pitch * 180 / std::numbers::pi);
  p.condition = t.condition;  // the trimmed values, not their round trip through rpm and degrees
  if (!t.azimuth_q.empty()) p.deflections = t.azimuth_q.front();
  return p;
}

}  // namespace whirl

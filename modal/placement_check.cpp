#include "modal/placement_check.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl {

namespace {

LinearController placedController(double kp, double ki, double gen_speed, const TuningTurbine& t,
                                  const TuningGoals& goals, const PlacementCheckOptions& opt) {
  LinearController c;
  c.lpf_order = opt.speed_filter > 0 ? 1 : 0;
  c.lpf_freq = opt.speed_filter;
  c.pitch_active = true;
  c.pitch_kp = kp;
  c.pitch_ki = ki;
  if (goals.constant_power) {
    // The one-state model's constant-power term: N τ_g = P/Ω, so δτ_g = −P/ω_g² δω_g.
    c.torque = LinearController::Torque::Static;
    c.torque_slope = -t.rated_power / (gen_speed * gen_speed);
  }
  return c;
}

std::complex<double> targetRoot(const TuningGoals& goals) {
  return {-goals.pc_zeta * goals.pc_omega,
          goals.pc_omega * std::sqrt(std::max(0.0, 1 - goals.pc_zeta * goals.pc_zeta))};
}

/// The closed loop's eigenvalue nearest `near`.
std::complex<double> nearestRoot(const StateSpaceModel& closed, std::complex<double> near) {
  const Eigen::VectorXcd ev = Eigen::EigenSolver<MatX>(closed.A, false).eigenvalues();
  std::complex<double> best = ev(0);
  for (Eigen::Index i = 1; i < ev.size(); ++i)
    if (std::abs(ev(i) - near) < std::abs(best - near)) best = ev(i);
  return best.imag() < 0 ? std::conj(best) : best;
}

/// The plant's options of both functions (the loop needs only the generator speed), after checking
/// that there is one trimmed point per point of the schedule.
ClosedLoopOptions plantOptions(const std::vector<SteadyState>& trimmed, const GainSchedule& g,
                               const PlacementCheckOptions& opt) {
  if (trimmed.size() != g.wind_speed.size())
    throw InputError("placement: " + std::to_string(trimmed.size()) + " trimmed points for " +
                     std::to_string(g.wind_speed.size()) + " points of the pitch schedule");
  ClosedLoopOptions clo;
  clo.azimuths = opt.azimuths;
  clo.outputs = {clo.ports.speed_output};
  return clo;
}

/// The check of one closed-loop point: its root nearest the target.
PlacementCheck checkOf(const ClosedLoopPoint& p, double wind_speed, std::complex<double> target) {
  PlacementCheck r;
  r.wind_speed = wind_speed;
  r.target = target;
  r.stable = p.stable;
  double best = std::numeric_limits<double>::infinity();
  for (const ClosedLoopMode& m : p.closed_modes)
    if (std::abs(m.eigenvalue - target) < best) {
      best = std::abs(m.eigenvalue - target);
      r.pole = m.eigenvalue;
      r.omega = 2 * std::numbers::pi * m.freq_hz;
      r.zeta = m.damping_ratio;
    }
  return r;
}

}  // namespace

std::vector<PlacementCheck> checkPlacement(const Model& model, const std::vector<SteadyState>& trimmed,
                                           const GainSchedule& g, const TuningTurbine& t, const TuningGoals& goals,
                                           const PlacementCheckOptions& opt) {
  const ClosedLoopOptions clo = plantOptions(trimmed, g, opt);
  std::vector<PlacementCheck> out;
  for (size_t k = 0; k < trimmed.size(); ++k) {
    const LinearController c = placedController(g.kp[k], g.ki[k], trimmed[k].generator_speed, t, goals, opt);
    out.push_back(checkOf(closedLoopPoint(model, trimmed[k], c, clo), g.wind_speed[k], targetRoot(goals)));
  }
  return out;
}

FullModelPlacement placeOnFullModel(const Model& model, const std::vector<SteadyState>& trimmed, const GainSchedule& g,
                                    const TuningTurbine& t, const TuningGoals& goals,
                                    const PlacementCheckOptions& opt) {
  const ClosedLoopOptions clo = plantOptions(trimmed, g, opt);
  const std::complex<double> target = targetRoot(goals);
  FullModelPlacement out{g, std::vector<bool>(g.kp.size(), false), {}};
  for (size_t k = 0; k < trimmed.size(); ++k) {
    const double w = trimmed[k].generator_speed;
    const StateSpaceModel plant =
        closedLoopPoint(model, trimmed[k], placedController(g.kp[k], g.ki[k], w, t, goals, opt), clo).plant;
    double kp = g.kp[k], ki = g.ki[k];
    std::complex<double> root = nearestRoot(closeLoop(plant, placedController(kp, ki, w, t, goals, opt)), target);
    auto rootAt = [&](double p, double i) {
      return nearestRoot(closeLoop(plant, placedController(p, i, w, t, goals, opt)), root);
    };
    for (int it = 0; it < 30 && std::abs(root - target) >= 1e-9 * std::abs(target); ++it) {
      const double hp = 1e-6 * std::abs(kp), hi = 1e-6 * std::abs(ki);
      const std::complex<double> dp = (rootAt(kp + hp, ki) - rootAt(kp - hp, ki)) / (2 * hp);
      const std::complex<double> di = (rootAt(kp, ki + hi) - rootAt(kp, ki - hi)) / (2 * hi);
      // [Re dp, Re di; Im dp, Im di] [Δp; Δi] = target − root
      const double det = dp.real() * di.imag() - di.real() * dp.imag();
      if (!(std::abs(det) > 0)) break;
      const std::complex<double> r = target - root;
      kp += (r.real() * di.imag() - di.real() * r.imag()) / det;
      ki += (dp.real() * r.imag() - r.real() * dp.imag()) / det;
      root = rootAt(kp, ki);
    }
    if (std::abs(root - target) < 1e-9 * std::abs(target) && std::isfinite(kp) && std::isfinite(ki)) {
      out.gains.kp[k] = kp;
      out.gains.ki[k] = ki;
      out.converged[k] = true;
    }
    // The check of the gains kept, on the plant at hand (not linearized again).
    const LinearController kept = placedController(out.gains.kp[k], out.gains.ki[k], w, t, goals, opt);
    out.checks.push_back(checkOf(closedLoopPoint(plant, trimmed[k], kept, clo), g.wind_speed[k], target));
  }
  return out;
}

}  // namespace whirl

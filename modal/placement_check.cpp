#include "modal/placement_check.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "src/model/error.hpp"

namespace whirl {

std::vector<PlacementCheck> checkPlacement(const Model& model, const std::vector<SteadyState>& trimmed,
                                           const GainSchedule& g, const TuningTurbine& t, const TuningGoals& goals,
                                           const PlacementCheckOptions& opt) {
  if (trimmed.size() != g.wind_speed.size())
    throw InputError("placement check: " + std::to_string(trimmed.size()) + " trimmed points for " +
                     std::to_string(g.wind_speed.size()) + " points of the pitch schedule");
  const std::complex<double> target(-goals.pc_zeta * goals.pc_omega,
                                    goals.pc_omega * std::sqrt(std::max(0.0, 1 - goals.pc_zeta * goals.pc_zeta)));
  ClosedLoopOptions clo;
  clo.azimuths = opt.azimuths;
  clo.outputs = {clo.ports.speed_output};
  std::vector<PlacementCheck> out;
  for (size_t k = 0; k < trimmed.size(); ++k) {
    LinearController c;
    c.lpf_order = opt.speed_filter > 0 ? 1 : 0;
    c.lpf_freq = opt.speed_filter;
    c.pitch_active = true;
    c.pitch_kp = g.kp[k];
    c.pitch_ki = g.ki[k];
    if (goals.constant_power) {
      // The one-state model's constant-power term: N τ_g = P/Ω, so δτ_g = −P/ω_g² δω_g.
      const double w = trimmed[k].generator_speed;
      c.torque = LinearController::Torque::Static;
      c.torque_slope = -t.rated_power / (w * w);
    }
    const ClosedLoopPoint p = closedLoopPoint(model, trimmed[k], c, clo);
    PlacementCheck r;
    r.wind_speed = g.wind_speed[k];
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
    out.push_back(r);
  }
  return out;
}

}  // namespace whirl

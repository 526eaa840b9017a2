#include "linearize/controller_tuning.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "src/base/error.hpp"

namespace whirl {
namespace {

constexpr double kPi = std::numbers::pi;

/// NumPy's linspace(a, b, n).
std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(static_cast<size_t>(n));
  const double step = (b - a) / (n - 1);
  for (int i = 0; i < n; ++i) v[static_cast<size_t>(i)] = a + i * step;
  if (n > 1) v.back() = b;
  return v;
}

/// SciPy's interp1d (linear) of the pairs (x, y) at xq, after sorting by x.
double interpLinear(std::vector<std::pair<double, double>> xy, double xq) {
  std::stable_sort(xy.begin(), xy.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  if (xy.size() == 1) return xy[0].second;
  size_t i = 1;
  while (i + 1 < xy.size() && xy[i].first < xq) ++i;
  const auto& [x0, y0] = xy[i - 1];
  const auto& [x1, y1] = xy[i];
  return y0 + (xq - x0) * (y1 - y0) / (x1 - x0);
}

/// ROSCO's pitch for a wanted Cp at λ: on the grid pitches from the one of the largest Cp upwards,
/// the wanted Cp clipped to their range and interpolated linearly (tune_controller's f_cp_pitch).
double pitchForCp(const aero::PerformanceSurface& cp, double tsr, double& cp_wanted) {
  const VecX row = cp.valuesAtGridPitches(tsr);
  Eigen::Index imax = 0;
  for (Eigen::Index k = 1; k < row.size(); ++k)
    if (row(k) > row(imax)) imax = k;  // NumPy argmax: the first maximum
  const std::vector<double>& pitch = cp.pitchGrid();
  std::vector<std::pair<double, double>> xy;
  double lo = row(imax), hi = row(imax);
  for (Eigen::Index k = imax; k < row.size(); ++k) {
    xy.push_back({row(k), pitch[static_cast<size_t>(k)]});
    lo = std::min(lo, row(k));
    hi = std::max(hi, row(k));
  }
  cp_wanted = std::clamp(cp_wanted, lo, hi);
  return interpLinear(std::move(xy), cp_wanted);
}

/// NumPy's polyfit(x, y, 1) evaluated at x: the least-squares line.
std::vector<double> leastSquaresLine(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0;
  for (size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i];
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  const double slope = sxy / sxx;
  std::vector<double> f(x.size());
  for (size_t i = 0; i < x.size(); ++i) f[i] = my + slope * (x[i] - mx);
  return f;
}

}  // namespace

std::vector<double> roscoWindSpeeds(const TuningTurbine& t, const TuningGoals& g) {
  if (g.pc_gs_n < 2 || g.ws_gs_n <= g.pc_gs_n + 1)
    throw InputError(where("", 0, "WS_GS_n",
                           "needs more wind speeds than PC_GS_n + 1 (" + std::to_string(g.ws_gs_n) + " vs " +
                               std::to_string(g.pc_gs_n) + ")"));
  if (!(t.v_min < t.v_rated && t.v_rated < t.v_max))
    throw InputError(where("", 0, "v_rated", "wind speeds must satisfy v_min < v_rated < v_max"));
  std::vector<double> v = linspace(t.v_min, t.v_rated, g.ws_gs_n - g.pc_gs_n);
  v.pop_back();
  for (double u : linspace(t.v_rated, t.v_max, g.pc_gs_n + 1)) v.push_back(u);
  return v;
}

std::vector<TuningPoint> roscoTuningSchedule(const aero::RotorPerformance& perf, const TuningTurbine& t,
                                             const TuningGoals& g) {
  const aero::PerformanceSurface cp(perf.pitch, perf.tsr, perf.cp);
  const double min_pitch = g.min_pitch.value_or(cp.optimalPitch());
  const double tsr_op = g.tsr_operational.value_or(cp.optimalTsr());
  const double R = t.rotor_radius, area = kPi * R * R;
  const std::vector<double> v = roscoWindSpeeds(t, g);
  const size_t n_below = static_cast<size_t>(g.ws_gs_n - g.pc_gs_n - 1);
  const double tsr_rated = t.rated_rotor_speed * R / t.v_rated;
  const double cp_rated = cp.value(min_pitch, tsr_rated);
  std::vector<TuningPoint> s;
  for (size_t i = 0; i < v.size(); ++i) {
    TuningPoint p;
    p.wind_speed = v[i];
    p.above_rated = i >= n_below;
    const double rated_tsr = t.rated_rotor_speed * R / v[i];
    p.tsr = p.above_rated ? rated_tsr : std::min(tsr_op, rated_tsr);
    double cp_op = p.above_rated ? cp_rated * std::pow(p.tsr / tsr_rated, 3) : cp.value(min_pitch, p.tsr);
    const double pitch = pitchForCp(cp, p.tsr, cp_op);
    p.pitch = v[i] <= t.v_rated ? std::min(min_pitch, pitch) : std::max(min_pitch, pitch);
    p.rotor_speed = p.tsr * v[i] / R;
    const aero::PerformanceSurface::Gradient d = cp.gradient(p.pitch, p.tsr);
    const double q = 0.5 * t.air_density * area * R * v[i] * v[i];  // torque per Cp/λ
    p.dq_dpitch = q / p.tsr * d.pitch;
    p.dq_domega = q / (p.tsr * p.tsr) * (d.tsr * p.tsr - cp_op) * R / v[i];
    // ROSCO's dtau_dv = ρA/(2Ω_rated) (∂Cp/∂λ · ∂λ/∂U · U³ + 3 Cp U²), ∂λ/∂U = −λ/U.
    p.dq_dwind = 0.5 * t.air_density * area / t.rated_rotor_speed *
                 (d.tsr * (-p.tsr / v[i]) * v[i] * v[i] * v[i] + 3 * cp_op * v[i] * v[i]);
    s.push_back(p);
  }
  return s;
}

GainSchedule placePoles(const std::vector<TuningPoint>& schedule, const TuningTurbine& t, const TuningGoals& g) {
  const double J = t.inertia, N = t.gearbox_ratio;
  GainSchedule gs;
  std::vector<double> a, b;
  const TuningPoint* last_below = nullptr;
  for (const TuningPoint& p : schedule) {
    if (!p.above_rated) {
      last_below = &p;
      continue;
    }
    double A = p.dq_domega / J;
    if (g.constant_power) A += t.rated_power / (J * t.rated_rotor_speed * t.rated_rotor_speed);
    gs.wind_speed.push_back(p.wind_speed);
    gs.pitch.push_back(p.pitch);
    a.push_back(A);
    b.push_back(N * p.dq_dpitch / J);
  }
  // ROSCO places the pitch loop from the second above-rated point on (rated itself is left out).
  if (gs.wind_speed.size() < 3 || !last_below)
    throw ComputeError("tuning: the schedule needs a point below rated and at least three above rated");
  gs.wind_speed.erase(gs.wind_speed.begin());
  gs.pitch.erase(gs.pitch.begin());
  a.erase(a.begin());
  b.erase(b.begin());
  if (g.fit_linear_in_wind) {
    a = leastSquaresLine(gs.wind_speed, a);
    b = leastSquaresLine(gs.wind_speed, b);
  }
  for (size_t i = 0; i < a.size(); ++i) {
    if (b[i] == 0)
      throw ComputeError("tuning: dQ/dpitch = 0 at " + std::to_string(gs.wind_speed[i]) + " m/s, no pitch gain");
    gs.kp.push_back((2 * g.pc_zeta * g.pc_omega + a[i]) / b[i]);
    gs.ki.push_back(g.pc_omega * g.pc_omega / b[i]);
  }
  gs.a = a;
  gs.b = b;
  gs.vs_a = last_below->dq_domega / J;
  const double b_tau = -N * N / J;
  gs.vs_kp = (2 * g.vs_zeta * g.vs_omega + gs.vs_a) / b_tau;
  gs.vs_ki = g.vs_omega * g.vs_omega / b_tau;
  return gs;
}

double floatingFeedbackGain(const std::vector<TuningPoint>& schedule, double wind) {
  for (size_t i = 0; i + 1 < schedule.size(); ++i) {
    const TuningPoint &a = schedule[i], &b = schedule[i + 1];
    if (wind < a.wind_speed || wind > b.wind_speed) continue;
    if (a.dq_dpitch == 0 || b.dq_dpitch == 0)
      throw ComputeError("tuning: dQ/dpitch = 0 near " + std::to_string(wind) + " m/s, no floating-feedback gain");
    const double ka = a.dq_dwind / a.dq_dpitch, kb = b.dq_dwind / b.dq_dpitch;
    const double f = b.wind_speed > a.wind_speed ? (wind - a.wind_speed) / (b.wind_speed - a.wind_speed) : 0;
    return ka + f * (kb - ka);
  }
  throw ComputeError("tuning: the floating-feedback wind speed " + std::to_string(wind) +
                     " m/s is outside the schedule's wind speeds");
}

}  // namespace whirl

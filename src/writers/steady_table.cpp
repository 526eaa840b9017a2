#include "src/writers/steady_table.hpp"

#include <numbers>

#include "src/io/text/csv.hpp"

namespace whirl {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

const std::vector<std::string>& steadyColumns() {
  static const std::vector<std::string> columns = {"wind_speed_m_s",
                                                   "rotor_speed_rpm",
                                                   "pitch_deg",
                                                   "aero_power_kw",
                                                   "generator_power_kw",
                                                   "aero_torque_knm",
                                                   "thrust_kn",
                                                   "cp",
                                                   "ct",
                                                   "tsr",
                                                   "tip_deflection_m",
                                                   "tower_top_fa_m",
                                                   "generator_torque_knm",
                                                   "region"};
  return columns;
}

SteadyRow steadyRow(const Model& m, const SteadyState& s) {
  SteadyRow r;
  const double U = *s.condition.wind_speed, R = m.aero.rotor_radius, rho = m.aero.air_density;
  const double area = kPi * R * R, omega = s.condition.rotor_speed;
  r.cp = s.aero_torque * omega / (0.5 * rho * area * U * U * U);
  r.ct = s.thrust / (0.5 * rho * area * U * U);
  r.tsr = omega * R / U;
  const double eff = m.generator.active() ? m.generator.efficiency : s.generator_efficiency;
  r.values = {U,
              omega * 30 / kPi,
              s.condition.collective_pitch.value_or(0) * 180 / kPi,
              s.aero_torque * omega / 1e3,
              s.generator_torque * s.generator_speed * eff / 1e3,
              s.aero_torque / 1e3,
              s.thrust / 1e3,
              r.cp,
              r.ct,
              r.tsr,
              s.tip_deflection,
              s.tower_top_fa,
              s.generator_torque / 1e3};
  // A controller's branch (SteadyState::region: "ROSCO 2", "ROSCO 3", …), else the torque law's side of rated.
  r.region = !s.region.empty()       ? "ROSCO " + s.region
             : !m.generator.active() ? "given"
             : s.above_rated         ? "above rated"
                                     : "below rated";
  return r;
}

std::string steadyCsv(const Model& m, const std::vector<SteadyState>& states) {
  std::string t;
  for (const std::string& c : steadyColumns()) t += (t.empty() ? "" : ",") + c;
  t += "\n";
  for (const SteadyState& s : states) {
    const SteadyRow r = steadyRow(m, s);
    for (double v : r.values) t += formatNumber(v) + ",";
    t += r.region + "\n";
  }
  return t;
}

}  // namespace whirl

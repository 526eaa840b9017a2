#pragma once
// A synthetic Campbell diagram that looks like a 5 MW three-bladed turbine (frequencies close to
// the NREL 5MW's, not computed by whirl): tower FA/SS ≈ 0.32 Hz (FA softening slightly with speed,
// so the two cross), drivetrain ≈ 0.62 Hz, flap 1 collective 0.70 Hz stiffening with rpm and its
// BW/FW pair split by ∓1P, edge 1 BW/FW ≈ 1.08 Hz ∓ 1P. Shapes are in multiblade coordinates
// (whirl modes are complex: cos + i·sin for BW, cos − i·sin for FW) so tracking must follow them
// through the crossings. With a wind schedule, aerodynamic damping is added (flap ~45 %).
#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <vector>

#include "modal/campbell.hpp"
#include "modal/tracking.hpp"

namespace whirl::test {

inline CampbellPoint syntheticTurbinePoint(double rpm, std::optional<double> wind, std::optional<double> pitch) {
  using cd = std::complex<double>;
  const std::vector<std::string> coords{"tower FA 1", "tower SS 1", "drivetrain", "flap 1 collective", "flap 1 cos",
                                        "flap 1 sin", "edge 1 cos", "edge 1 sin", "edge 1 collective"};
  const double W = rpm / 60;                  // 1P [Hz]
  const double load = wind ? rpm / 12.1 : 0;  // 0 without aerodynamics
  const double feather = pitch ? 1 - 0.3 * *pitch / 25 : 1;
  const double flap = std::sqrt(0.70 * 0.70 + 1.75 * W * W), edge = std::sqrt(1.08 * 1.08 + 0.8 * W * W);
  struct Spec {
    std::string name;
    double f, zeta;
    std::vector<std::pair<int, cd>> shape;
  };
  const cd i(0, 1);
  std::vector<Spec> specs{
      {"tower FA 1", 0.326 - 0.0006 * rpm, 0.01 + 0.04 * load, {{0, 1}, {3, 0.08}}},
      {"tower SS 1", 0.3215, 0.008 + 0.003 * load, {{1, 1}, {6, 0.05}, {7, 0.05 * i}}},
      {"drivetrain", 0.62 + 0.002 * W, 0.006 + 0.015 * load, {{2, 1}, {8, 0.4}}},
      {"flap 1 collective", flap + 0.012, 0.005 + 0.45 * load * feather, {{3, 1}, {0, 0.15}}},
      {"flap 1 BW", flap - 0.02 - W, 0.005 + 0.38 * load * feather, {{4, 1}, {5, i}, {1, 0.1}}},
      {"flap 1 FW", flap - 0.01 + W, 0.005 + 0.42 * load * feather, {{4, 1}, {5, -i}, {0, 0.05}}},
      {"edge 1 BW", edge - W, 0.005 + 0.012 * load, {{6, 1}, {7, i}, {1, 0.08}}},
      {"edge 1 FW", edge + W, 0.005 + 0.016 * load, {{6, 1}, {7, -i}, {1, 0.03}}},
  };
  CampbellPoint p;
  p.rpm = rpm;
  p.wind_speed = wind;
  p.pitch_deg = pitch;
  p.coordinates = coords;
  for (const auto& s : specs) {
    Mode m;
    m.freq_hz = s.f;
    m.damping_ratio = s.zeta;
    m.damped_freq_hz = s.f * std::sqrt(std::max(0.0, 1 - s.zeta * s.zeta));
    m.shape = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(coords.size()));
    for (const auto& [k, v] : s.shape) m.shape[k] = v;
    m.participation = m.shape.cwiseAbs2() / m.shape.squaredNorm();
    m.name = s.name;
    p.modes.push_back(m);
  }
  // Where flap 1 BW passes the drivetrain, the mode namer would report the pair.
  if (std::abs(specs[4].f - specs[2].f) < 0.03) p.modes[4].name = "flap 1 BW / drivetrain";
  std::sort(p.modes.begin(), p.modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  return p;
}

/// Rotor-speed sweep 0–14 rpm (no wind) or the NREL 5MW-like schedule 3–25 m/s, tracked.
inline CampbellDiagram syntheticTurbineCampbell(bool with_wind) {
  CampbellDiagram d;
  if (with_wind) {
    d.title = "Campbell diagram: synthetic 5 MW turbine, operating schedule";
    const std::vector<std::pair<double, double>> pitch{{11.4, 0},   {12, 3.83},  {13, 6.6},   {14, 8.7},   {15, 10.45},
                                                       {16, 12.06}, {18, 14.92}, {20, 17.47}, {22, 19.94}, {25, 23.47}};
    for (double ws = 3; ws <= 25; ws += 1) {
      const double rpm = std::clamp(1.144 * ws, 6.97, 12.1);
      double pd = 0;
      for (std::size_t k = 0; k + 1 < pitch.size(); ++k)
        if (ws > pitch[k].first && ws <= pitch[k + 1].first)
          pd = pitch[k].second +
               (ws - pitch[k].first) / (pitch[k + 1].first - pitch[k].first) * (pitch[k + 1].second - pitch[k].second);
      d.points.push_back(syntheticTurbinePoint(rpm, ws, pd));
    }
  } else {
    d.title = "Campbell diagram: synthetic 5 MW turbine, rotor-speed sweep without wind";
    for (double rpm = 0; rpm <= 14.0 + 1e-9; rpm += 1) d.points.push_back(syntheticTurbinePoint(rpm, {}, {}));
  }
  d.lines = trackModes(d.points);
  return d;
}

}  // namespace whirl::test

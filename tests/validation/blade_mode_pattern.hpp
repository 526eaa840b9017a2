#pragma once
// Naming the modes of a parked three-bladed turbine without the multiblade transform: the share of
// each DOF group (tower FA, tower SS, yaw, drivetrain, flap 1, edge 1, flap 2) in the mode's energy,
// and, for a blade group, the phase pattern of the three blades in the eigenvector.
//
// With blade b at azimuth ψ_b = ψ + 2π(b−1)/3 (0 = up) and q_b its (phase-aligned, real) component,
// q0 = (1/3) Σ q_b, qc = (2/3) Σ q_b cos ψ_b, qs = (2/3) Σ q_b sin ψ_b ([Bir2008]; docs/dev/architecture.md,
// notation), and Σ q_b² = 3 q0² + (3/2)(qc² + qs²). Collective: 3 q0² carries most of Σ q_b². Asymmetric:
// - out of plane (flap): cos ψ (upper blade against the lower ones) tilts the rotor ("pitch"),
//   sin ψ (one side against the other) yaws it ("yaw");
// - in plane (edge): blade b moves along j2 = (0, cos ψ_b, sin ψ_b) in shaft axes (y left, z up),
//   so the net in-plane hub force is (3/2)(0, qc, qs): cos ψ pushes the hub sideways ("yaw"),
//   sin ψ up and down ("pitch").
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "modal/modes.hpp"

namespace whirl::test {

/// The DOF group of a coordinate name: "tower FA", "tower SS", "yaw", "drivetrain", "generator azimuth",
/// or for "blade b <x>" the blade group "<x>" ("flap 1", "edge 1", "flap 2").
inline std::string dofGroup(const std::string& name) {
  if (name.rfind("tower FA", 0) == 0) return "tower FA";
  if (name.rfind("tower SS", 0) == 0) return "tower SS";
  if (name.rfind("blade ", 0) == 0 && name.size() > 8) return name.substr(8);
  return name;
}

struct ModeClass {
  std::string group;        ///< dominant DOF group by energy share
  double share = 0;         ///< its share
  bool collective = false;  ///< blade group: 3 q0² > half of Σ q_b²
  std::string asymmetry;    ///< blade group, not collective: "pitch" or "yaw"
  std::string label() const {
    if (group != "flap 1" && group != "edge 1" && group != "flap 2") return group;
    return group + (collective ? " collective" : " asymmetric " + asymmetry);
  }
};

/// Classifies `mode` of a linear model with coordinate `names`; `psi` = azimuth of blade 1 [rad].
inline ModeClass classify(const Mode& mode, const std::vector<std::string>& names, double psi) {
  std::map<std::string, double> share;
  for (std::size_t i = 0; i < names.size(); ++i)
    share[dofGroup(names[i])] += mode.participation(static_cast<Eigen::Index>(i));
  ModeClass c;
  for (const auto& [g, s] : share)
    if (s > c.share) c = ModeClass{g, s, false, ""};
  if (c.group != "flap 1" && c.group != "edge 1" && c.group != "flap 2") return c;
  std::complex<double> z[3];
  for (int b = 0; b < 3; ++b)
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == "blade " + std::to_string(b + 1) + " " + c.group) z[b] = mode.shape(static_cast<Eigen::Index>(i));
  // Align the phases on the largest blade component, then take the real parts.
  int ref = 0;
  for (int b = 1; b < 3; ++b)
    if (std::abs(z[b]) > std::abs(z[ref])) ref = b;
  const std::complex<double> rot = std::conj(z[ref]) / std::abs(z[ref]);
  double q0 = 0, qc = 0, qs = 0, sum2 = 0;
  for (int b = 0; b < 3; ++b) {
    const double q = (z[b] * rot).real(), p = psi + 2 * std::numbers::pi * b / 3;
    q0 += q / 3;
    qc += 2 * q * std::cos(p) / 3;
    qs += 2 * q * std::sin(p) / 3;
    sum2 += q * q;
  }
  c.collective = 3 * q0 * q0 > 0.5 * sum2;
  const bool cos_dominant = std::abs(qc) > std::abs(qs);
  if (c.group == "edge 1") c.asymmetry = cos_dominant ? "yaw" : "pitch";
  else c.asymmetry = cos_dominant ? "pitch" : "yaw";
  return c;
}

}  // namespace whirl::test

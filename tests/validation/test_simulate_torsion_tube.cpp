// [Branlard2019, §5.3] in the time domain: the torsion tube (four torsion shapes) under the tip
// moment M0 sin(Ω t), Ω = 1.0002 ω_1, integrated by `simulate` (IDA), against the closed-form
// transient of a damped single-DOF oscillator from rest, one per shape (the shapes are the exact
// modes: M, K and the stiffness-proportional C are diagonal, so each coordinate is such an
// oscillator and the tip torsion is their sum). The seed writes the transient with ω_1 in place of
// the damped ω_d = ω_1 √(1 − ζ²); here it is exact.
// Also: with damping off, the energy ½ q̇ᵀ M q̇ + ½ qᵀ K q of the free tube is conserved.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linearize/linearize.hpp"
#include "linearize/simulate.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr double kM0 = 5e10;       // [N m], [Branlard2019, §5.3]
constexpr double kRatio = 1.0002;  // Ω/ω_1
const double kZeta = 1 / (10 * std::numbers::pi);

// q(t) of q̈ + 2ζω q̇ + ω² q = (F/m) sin(Ω t), q(0) = q̇(0) = 0.
double forcedFromRest(double F_over_m, double w, double zeta, double W, double t) {
  const double r = W / w;
  const double H = F_over_m / (w * w) / std::hypot(1 - r * r, 2 * zeta * r);
  const double phi = std::atan2(2 * zeta * r, 1 - r * r);
  const double wd = w * std::sqrt(1 - zeta * zeta);
  const double a = H * std::sin(phi);                            // cancels q_p(0) = −H sin φ
  const double b = (zeta * w * a - H * W * std::cos(phi)) / wd;  // cancels q̇_p(0) = H Ω cos φ
  return std::exp(-zeta * w * t) * (a * std::cos(wd * t) + b * std::sin(wd * t)) + H * std::sin(W * t - phi);
}

TEST(SimulateTorsionTube, ForcedTransientMatchesClosedForm) {
  const Model forced = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/torsion_tube/torsion_tube_forced.yaml");
  const LinearModel lin = test::linearizeAtEquilibrium(forced);
  const double w1 = std::sqrt(lin.K(0, 0) / lin.M(0, 0));
  const double W = kRatio * w1;
  SimulationOptions o;
  o.t_end = 5;
  o.dt_out = 0.01;
  o.rtol = 1e-9;
  o.atol = 1e-12;
  TimeSignal s;
  s.kind = TimeSignal::Kind::Sine;
  s.parameters = {kM0, W / (2 * std::numbers::pi)};
  o.inputs.push_back({*forced.findInput("tip moment"), s});
  const Simulation sim = simulate(forced, initialPoint(forced), o);
  ASSERT_EQ(sim.time.size(), 501u);
  double peak = 0, err = 0;
  for (size_t k = 0; k < sim.time.size(); ++k) {
    double tip = 0, tip_ref = 0;
    for (int j = 0; j < 4; ++j) {
      const double wj = std::sqrt(lin.K(j, j) / lin.M(j, j));
      const double sign = j % 2 == 0 ? 1.0 : -1.0;  // sin(β_j) at the tip
      // stiffness-proportional: ζ_j = ζ ω_j/ω_1; tip moment projected on shape j: M0 sin β_j
      tip_ref += sign * forcedFromRest(sign * kM0 / lin.M(j, j), wj, kZeta * wj / w1, W, sim.time[k]);
      tip += sign * sim.q(static_cast<Eigen::Index>(k), j);
    }
    peak = std::max(peak, std::abs(tip_ref));
    err = std::max(err, std::abs(tip - tip_ref));
  }
  // The exact modes give diagonal matrices, so the only error is IDA's (rtol 1e-9): 1e-6 of the peak.
  EXPECT_LT(err, 1e-6 * peak) << "peak " << peak;
  EXPECT_GT(peak, 0.01);  // the resonance builds up: tens of mrad
}

TEST(SimulateTorsionTube, EnergyIsConservedWithoutDamping) {
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/torsion_tube/torsion_tube_forced.yaml",
                           {parseOverride("bodies.tube.damping.stiffness_proportional=0")});
  const LinearModel lin = test::linearizeAtEquilibrium(m);  // K: the elastic stiffness (linear in q)
  OperatingPoint start = initialPoint(m);
  start.q(0) = 0.01;
  start.q(1) = -0.002;
  start.qd(2) = 0.05;
  const double T1 = 2 * std::numbers::pi / std::sqrt(lin.K(0, 0) / lin.M(0, 0));
  SimulationOptions o;
  o.t_end = 100 * T1;  // 100 periods of the lowest mode
  o.dt_out = T1 / 10;
  o.rtol = 1e-10;
  o.atol = 1e-13;
  const Simulation sim = simulate(m, start, o);
  auto energy = [&](size_t k) {
    const VecX q = sim.q.row(static_cast<Eigen::Index>(k)).transpose();
    const VecX v = sim.qd.row(static_cast<Eigen::Index>(k)).transpose();
    return 0.5 * v.dot(lin.M * v) + 0.5 * q.dot(lin.K * q);
  };
  const double E0 = energy(0);
  double drift = 0;
  for (size_t k = 0; k < sim.time.size(); ++k) drift = std::max(drift, std::abs(energy(k) - E0) / E0);
  EXPECT_LT(drift, 1e-6);
}

// SimulationOptions::stop ends the integration at the instant it names, keeping the record up to it
// (what stops a diverging model at its first invalid instant, stopAtInvalidMotion; issue 48). The
// kept instants equal the same instants of the run to the end.
TEST(SimulateTorsionTube, StopEndsTheRecordAtItsInstant) {
  const Model forced = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/torsion_tube/torsion_tube_forced.yaml");
  SimulationOptions o;
  o.t_end = 1;
  o.dt_out = 0.1;
  TimeSignal s;
  s.kind = TimeSignal::Kind::Sine;
  s.parameters = {kM0, 1.0};
  o.inputs.push_back({*forced.findInput("tip moment"), s});
  const Simulation full = simulate(forced, initialPoint(forced), o);
  o.stop = [](double t, const VecX& q) { return t > 0.45 && q.allFinite(); };
  const Simulation part = simulate(forced, initialPoint(forced), o);
  EXPECT_FALSE(full.stopped);
  ASSERT_TRUE(part.stopped);
  ASSERT_EQ(part.time.size(), 6u);  // 0, 0.1, …, 0.5
  EXPECT_EQ(part.q.rows(), 6);
  EXPECT_EQ(part.y.rows(), 6);
  EXPECT_DOUBLE_EQ(part.time.back(), 0.5);
  EXPECT_EQ(part.q, full.q.topRows(6));
}

}  // namespace
}  // namespace whirl

// ServoDyn's induction generators as whirl builds them from a deck (src/turbine/elastodyn_aero.cpp,
// src/dynamics/generator_torque.hpp): the Thevenin-equivalent generator of AWT-27 (certification
// Test02) against the torque of its equivalent circuit written independently, as the textbook gives
// it (Chapman, "Electric Machinery Fundamentals", induced torque from the Thevenin equivalent of the
// stator), and the simple induction generator of AOC 15/50 (Test07) against ServoDyn's definition of
// its keys (rated torque at rated slip, held at the pull-out torque beyond the pull-out slip).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "linearize/trim.hpp"
#include "src/dynamics/generator_torque.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

std::string deck(const std::string& rel) {
  return std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/decks/certtest/" + rel;
}

// Generator torque (positive generating) at mechanical speed w of a machine with per-phase stator
// resistance r1 and leakage x1, rotor resistance r2 and leakage x2, magnetizing reactance xm, line
// voltage vll, line frequency f and p poles. Motor convention first: slip s = (ws − w)/ws, torque
// 3 |Vth|² (r2/s) / (ws |Zth + r2/s + j x2|²); a generator turns faster than ws (s < 0) and the
// torque it takes from the shaft is minus the motor torque.
double circuitTorque(double w, double r1, double x1, double r2, double x2, double xm, double vll, double f, int p) {
  using C = std::complex<double>;
  const double ws = 4.0 * std::numbers::pi * f / p;  // synchronous mechanical speed [rad/s]
  const C z1(r1, x1), zm(0.0, xm);
  const C vth = (vll / std::sqrt(3.0)) * zm / (z1 + zm);  // Thevenin source (phase voltage)
  const C zth = z1 * zm / (z1 + zm);                      // Thevenin impedance
  const double s = (ws - w) / ws;
  const double motor = 3.0 * std::norm(vth) * (r2 / s) / (ws * std::norm(zth + C(r2 / s, x2)));
  return -motor;
}

TEST(GeneratorTorque, TheveninGeneratorIsItsEquivalentCircuit) {
  // AWT27/Test02_ServoDyn.dat: TEC_Freq 60 Hz, TEC_NPol 6, TEC_SRes 0.0185, TEC_RRes 0.017, TEC_VLL 480 V,
  // TEC_SLR 0.034, TEC_RLR 0.005, TEC_MR 0.775 ohm.
  const Model m = readElastoDynModel(deck("Test02.fst"));
  ASSERT_EQ(m.generator.kind, GeneratorTorqueLaw::Kind::Thevenin);
  const double ws = 4.0 * std::numbers::pi * 60.0 / 6.0;
  EXPECT_NEAR(m.generator.sync_speed, ws, 1e-12 * ws);
  EXPECT_DOUBLE_EQ(generatorTorque(m.generator, ws), 0.0);
  for (double slip : {-0.05, -0.01, 0.001, 0.005, 0.0151, 0.03, 0.2}) {
    SCOPED_TRACE(slip);
    const double w = ws * (1.0 + slip);
    const double ref = circuitTorque(w, 0.0185, 0.034, 0.017, 0.005, 0.775, 480.0, 60.0, 6);
    EXPECT_NEAR(generatorTorque(m.generator, w), ref, 1e-10 * std::abs(ref));
  }
  // The trim's bracket ends are the pull-out speeds: the torque is largest there.
  const auto [lo, hi] = pulloutSpeeds(m.generator);
  const double t = generatorTorque(m.generator, hi);
  EXPECT_GT(t, generatorTorque(m.generator, hi * 0.999));
  EXPECT_GT(t, generatorTorque(m.generator, hi * 1.001));
  EXPECT_LT(generatorTorque(m.generator, lo), generatorTorque(m.generator, lo * 1.001));
}

TEST(GeneratorTorque, SimpleInductionGeneratorFollowsServoDynsKeys) {
  // AOC/Test07_ServoDyn.dat: SIG_SlPc 2.222 %, SIG_SySp 1800 rpm, SIG_RtTq 314.3 N m, SIG_PORt 1.75.
  const Model m = readElastoDynModel(deck("Test07.fst"));
  const GeneratorTorqueLaw& g = m.generator;
  ASSERT_EQ(g.kind, GeneratorTorqueLaw::Kind::SimpleInduction);
  const double sync = 1800.0 * std::numbers::pi / 30.0, rated = sync * 1.02222;
  EXPECT_NEAR(generatorTorque(g, sync), 0.0, 1e-12);
  EXPECT_NEAR(generatorTorque(g, rated), 314.3, 1e-9);
  EXPECT_NEAR(generatorTorque(g, 2.0 * sync - rated), -314.3, 1e-9);  // motoring, same slope
  const double pullout = sync + 1.75 * (rated - sync);
  EXPECT_NEAR(generatorTorque(g, pullout * 0.9999999), 1.75 * 314.3, 1e-2);
  EXPECT_DOUBLE_EQ(generatorTorque(g, pullout * 1.01), 1.75 * 314.3);  // beyond pull-out: held
  EXPECT_DOUBLE_EQ(generatorTorque(g, 0.5 * sync), -1.75 * 314.3);
}

// A fixed-speed, stall-regulated rotor trims to the speed where the torque-slip line carries the
// aerodynamic torque: between synchronous and pull-out speed, the azimuth's generalized force zero.
TEST(GeneratorTorque, FixedSpeedRotorTrimsOnTheSlipLine) {
  const Model m = readElastoDynModel(deck("Test07.fst"));
  const double gear = 28.25;  // AOC/Test07_ElastoDyn.dat GBRatio
  const auto [lo, hi] = pulloutSpeeds(m.generator);
  const SteadyState s = trimAtWindSpeed(m, 8.0);
  EXPECT_GT(s.condition.rotor_speed * gear, m.generator.sync_speed);
  EXPECT_LT(s.condition.rotor_speed * gear, hi);
  EXPECT_NEAR(s.generator_speed, s.condition.rotor_speed * gear, 1e-9 * s.generator_speed);
  EXPECT_GT(s.aero_torque, 0.0);
  EXPECT_LT(std::abs(s.imbalance), 1e-6 * s.aero_torque);
  // Beyond the pull-out torque there is no balance: the message says so.
  TrimOptions weak;
  Model m2 = m;
  m2.generator.rated_torque *= 0.01;
  try {
    trimAtWindSpeed(m2, 12.0, weak);
    FAIL() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the pull-out torque (runaway)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace whirl

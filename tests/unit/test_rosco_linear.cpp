// ROSCO's controller linearized at its steady states (linearize/rosco_linear.hpp), on the shipped NREL 5MW
// DISCON.IN (cases/nrel5mw/rosco/DISCON.IN, ROSCO's Examples/Tune_Cases NREL5MW): which loops act in each
// region and the gains they act with, from the file's values.
#include <gtest/gtest.h>

#include <cmath>

#include "linearize/rosco_linear.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

RoscoController shipped() { return io::readDiscon(test::nrel5mwDir() / "rosco" / "DISCON.IN"); }

SteadyState pointAt(const std::string& region, double pitch, double gen_speed) {
  SteadyState s;
  s.region = region;
  s.condition.collective_pitch = pitch;
  s.generator_speed = gen_speed;
  return s;
}

TEST(RoscoLinear, RegionThreeIsThePitchPiWithConstantPower) {
  const RoscoController c = shipped();
  const LinearController k = linearRosco(c, pointAt("3", 0.15, 122.90967));
  EXPECT_TRUE(k.pitch_active);
  const RoscoPitchGains g = roscoPitchGains(c, 0.15);
  EXPECT_EQ(k.pitch_kp, g.kp);
  EXPECT_EQ(k.pitch_ki, g.ki);
  EXPECT_LT(k.pitch_kp, 0);  // ROSCO's PC_GS_KP are negative: error ω_ref − ω_f
  EXPECT_EQ(k.lpf_order, 1);
  EXPECT_DOUBLE_EQ(k.lpf_freq, 1.5708);  // F_LPFCornerFreq
  EXPECT_EQ(k.actuator_order, 0);        // PA_Mode 0
  // VS_ConstPower 1: τ = VS_RtPwr/(η ω_f), δτ = −VS_RtPwr/(η ω_f²) δω_f with η = 94.4 % (VS_GenEff).
  ASSERT_EQ(k.torque, LinearController::Torque::Static);
  EXPECT_NEAR(k.torque_slope, -5e6 / 0.944 / (122.90967 * 122.90967), 1e-12 * 350);
}

TEST(RoscoLinear, RegionTwoTracksTheTipSpeedRatioThroughTheReferenceFilter) {
  const RoscoController c = shipped();
  const LinearController k = linearRosco(c, pointAt("2", 0, 80));
  EXPECT_FALSE(k.pitch_active);
  ASSERT_EQ(k.torque, LinearController::Torque::PI);
  EXPECT_DOUBLE_EQ(k.torque_kp, -697.771);  // VS_KP
  EXPECT_DOUBLE_EQ(k.torque_ki, -104.507);  // VS_KI
  // ω_ref = VS_TSRopt · WE_GearboxRatio · U / WE_BladeRadius = 7.5 · 97 / 63 per m/s.
  EXPECT_NEAR(k.reference_per_wind, 7.5 * 97 / 63, 1e-12);
  EXPECT_DOUBLE_EQ(k.reference_filter_freq, 0.20944);  // F_VSRefSpdCornerFreq
}

TEST(RoscoLinear, TransitionRegionsHoldTheirReference) {
  const RoscoController c = shipped();
  for (const char* r : {"1.5", "2.5"}) {
    const LinearController k = linearRosco(c, pointAt(r, 0, 100));
    EXPECT_EQ(k.torque, LinearController::Torque::PI) << r;
    EXPECT_EQ(k.reference_per_wind, 0) << r;
    EXPECT_FALSE(k.pitch_active) << r;
  }
  // Torque at its limit (constant power for TSR tracking), pitch on its minimum: no PI acts.
  const LinearController sat = linearRosco(c, pointAt("2.5 saturated + min pitch", 0.06, 120));
  EXPECT_FALSE(sat.pitch_active);
  EXPECT_EQ(sat.torque, LinearController::Torque::Static);
  EXPECT_NEAR(sat.torque_slope, -5e6 / 0.944 / (120.0 * 120.0), 1e-9);
}

TEST(RoscoLinear, WithoutSpeedFilterKeepsTheRest) {
  RoscoLinearOptions o;
  o.without_speed_filter = true;
  const LinearController k = linearRosco(shipped(), pointAt("3", 0.15, 122.90967), o);
  EXPECT_EQ(k.lpf_order, 0);
  EXPECT_TRUE(k.pitch_active);
}

TEST(RoscoLinear, KOmegaSquaredLawInRegionTwo) {
  RoscoController c = shipped();
  c.VS_ControlMode = 1;
  const LinearController k = linearRosco(c, pointAt("2", 0, 80));
  ASSERT_EQ(k.torque, LinearController::Torque::Static);
  EXPECT_NEAR(k.torque_slope, 2 * 2.31055 * 80, 1e-9);  // d(VS_Rgn2K ω²)/dω
}

TEST(RoscoLinear, PointWithoutRegionIsAnInputErrorNamingTheFile) {
  const RoscoController c = shipped();
  try {
    linearRosco(c, pointAt("", 0, 80));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("DISCON.IN"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not trimmed with this controller"), std::string::npos) << e.what();
  }
  EXPECT_THROW(linearRosco(c, pointAt("4", 0, 80)), InputError);
}

TEST(RoscoLinear, NotesNameWhatTheLinearModelLeavesOut) {
  const std::vector<std::string> n = linearRoscoNotes(shipped());
  auto has = [&](const std::string& key) {
    for (const std::string& s : n)
      if (s.rfind(key, 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(has("VS_ControlMode = 2"));
  EXPECT_TRUE(has("SS_Mode = 1"));
  EXPECT_TRUE(has("PA_Mode = 0"));
}

}  // namespace
}  // namespace whirl

// ROSCO's pole placement reproduced (linearize/controller_tuning.hpp): with ROSCO's inputs for the NREL
// 5MW (tests/data/rosco/NREL5MW.yaml: ω, ζ of both loops, rotor inertia, rated speed and power, wind
// range; the deck's GenIner, GBRatio, TipRad, AirDens) and ROSCO's Cp surface
// (tests/data/rosco/Cp_Ct_Cq.NREL5MW.txt), the gain schedule ROSCO wrote into
// tests/data/rosco/DISCON.IN (NREL/ROSCO v2.10.3, Examples/Test_Cases/NREL-5MW) to every digit it prints.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "linearize/controller_tuning.hpp"
#include "src/aero/not_a_knot_spline.hpp"
#include "src/base/error.hpp"
#include "src/io/openfast/servodyn/rotor_performance_input.hpp"

namespace whirl {
namespace {

std::string roscoFile(const std::string& name) { return std::string(WHIRL_SOURCE_DIR) + "/tests/data/rosco/" + name; }

/// The value words of the DISCON.IN line whose comment names `key` (the test's own look-up, not a reader).
std::vector<std::string> disconWords(const std::string& key) {
  std::ifstream in(roscoFile("DISCON.IN"));
  for (std::string line; std::getline(in, line);) {
    const size_t bang = line.find('!');
    if (bang == std::string::npos) continue;
    std::istringstream comment(line.substr(bang + 1)), values(line.substr(0, bang));
    std::string label;
    comment >> label;
    if (label != key) continue;
    std::vector<std::string> w;
    for (std::string s; values >> s;) w.push_back(s);
    return w;
  }
  ADD_FAILURE() << "no " << key << " in DISCON.IN";
  return {};
}

std::string printed(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

TuningTurbine nrel5mwTurbine() {
  TuningTurbine t;
  // NREL5MW.yaml turbine_params.rotor_inertia plus GenIner (534.116 kg m², NRELOffshrBsline5MW_Onshore_ElastoDyn.dat)
  // · GBRatio² (97²), as ROSCO's turbine.py forms J; the sum is DISCON.IN's WE_Jtot 43702538.057.
  t.inertia = 38677040.613 + 534.116 * 97 * 97;
  t.rotor_radius = 63;            // TipRad
  t.air_density = 1.225;          // AirDens, cases/nrel5mw/Main_Onshore.fst
  t.gearbox_ratio = 97;           // GBRatio
  t.rated_rotor_speed = 1.26711;  // NREL5MW.yaml
  t.rated_power = 5e6;
  t.v_min = 3;
  t.v_rated = 11.4;
  t.v_max = 25;
  return t;
}

TuningGoals nrel5mwGoals() {
  TuningGoals g;  // NREL5MW.yaml controller_params: omega_pc, zeta_pc, omega_vs, zeta_vs; VS_ConstPower 1
  g.pc_omega = 0.6;
  g.pc_zeta = 0.7;
  g.vs_omega = 0.15;
  g.vs_zeta = 0.7;
  return g;
}

void expectPrinted(const std::string& key, const char* format, const std::vector<double>& ours) {
  const std::vector<std::string> ref = disconWords(key);
  ASSERT_EQ(ref.size(), ours.size()) << key;
  for (size_t i = 0; i < ref.size(); ++i) EXPECT_EQ(printed(format, ours[i]), ref[i]) << key << "[" << i << "]";
}

TEST(ControllerTuning, CpSurfaceReproducesRoscoGainSchedule) {
  const aero::RotorPerformance perf = io::readRotorPerformance(roscoFile("Cp_Ct_Cq.NREL5MW.txt"));
  const TuningTurbine t = nrel5mwTurbine();
  const TuningGoals g = nrel5mwGoals();
  const GainSchedule gs = placePoles(roscoTuningSchedule(perf, t, g), t, g);
  // ROSCO's write_DISCON formats (rosco/toolbox/utilities.py): angles '<12.3f', gains '<12.3e', VS '<14.5e'.
  expectPrinted("PC_GS_angles", "%.3f", gs.pitch);
  expectPrinted("PC_GS_KP", "%.3e", gs.kp);
  expectPrinted("PC_GS_KI", "%.3e", gs.ki);
  expectPrinted("VS_KP", "%.5e", {gs.vs_kp});
  expectPrinted("VS_KI", "%.5e", {gs.vs_ki});
}

TEST(ControllerTuning, ScheduleAtRatedFollowsTheSurface) {
  const aero::RotorPerformance perf = io::readRotorPerformance(roscoFile("Cp_Ct_Cq.NREL5MW.txt"));
  const std::vector<TuningPoint> s = roscoTuningSchedule(perf, nrel5mwTurbine(), nrel5mwGoals());
  ASSERT_EQ(s.size(), 60u);  // WS_GS_n
  // The grid's best point is Cp 0.465861 at 0° and λ 7.5 (row 12, column 6 of the Cp block); DISCON.IN's
  // VS_TSRopt is 7.5 and PC_MinPit 0: below rated ROSCO keeps λ 7.5 at 0° until the rated speed.
  EXPECT_DOUBLE_EQ(s[0].tsr, 7.5);
  EXPECT_DOUBLE_EQ(s[0].pitch, 0.0);
  // ∂Q/∂β < 0 above rated (pitching to feather unloads the rotor). Issue 43 quotes ROSCO's ∂Q/∂β at
  // 14 m/s as −30.5 MN m/rad (at whirl's trimmed 12.1 rpm, 8.668°; here on ROSCO's schedule), interpolated between the
  // schedule's 13.67 and 14.12 m/s.
  for (const TuningPoint& p : s) {
    if (p.above_rated && p.wind_speed > 12) {
      EXPECT_LT(p.dq_dpitch, 0) << p.wind_speed;
    }
  }
  ASSERT_NEAR(s[34].wind_speed, 13.6667, 1e-4);
  ASSERT_NEAR(s[35].wind_speed, 14.12, 1e-4);
  const double w = (14 - s[34].wind_speed) / (s[35].wind_speed - s[34].wind_speed);
  const double dq = (1 - w) * s[34].dq_dpitch + w * s[35].dq_dpitch;
  EXPECT_NEAR(dq / 1e6, -30.5, 0.05);
}

TEST(ControllerTuning, NotAKnotSplineIsExactForCubics) {
  // A cubic is its own not-a-knot interpolant (a natural spline is not: its end curvature is zero).
  const std::vector<double> x = {0.0, 0.3, 1.0, 1.2, 2.0, 3.5};
  auto f = [](double s) { return 1 - 2 * s + 0.5 * s * s - 0.25 * s * s * s; };
  VecX y(static_cast<Eigen::Index>(x.size()));
  for (size_t i = 0; i < x.size(); ++i) y(static_cast<Eigen::Index>(i)) = f(x[i]);
  const aero::NotAKnotSpline s(x);
  for (double q : {0.05, 0.7, 1.1, 2.9, 3.4}) EXPECT_NEAR(s.weights(q).dot(y), f(q), 1e-12) << q;
}

TEST(ControllerTuning, RotorPerformanceErrorsNameFileLineKey) {
  const std::string dir = ::testing::TempDir();
  const std::string path = dir + "/short_cp.txt";
  {
    std::ofstream out(path);
    out << "# Pitch angle vector\n-1 0 1 2\n# TSR vector\n4 5 6 7\n# Power coefficient\n\n0.1 0.2 0.3\n";
  }
  try {
    io::readRotorPerformance(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":7: Cp: 3 values, expected one per pitch angle (4)");
  }
  {
    std::ofstream out(path);
    out << "# Pitch angle vector\n-1 0 2 1\n# TSR vector\n4 5 6 7\n";
  }
  try {
    io::readRotorPerformance(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":2: pitch: values must increase");
  }
}

}  // namespace
}  // namespace whirl

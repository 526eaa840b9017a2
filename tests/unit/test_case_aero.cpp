// Aerodynamics from the case file (`wind:`, `aero:`): the rotor of tests/support/aero_rotor_model.hpp
// written as YAML gives the same blade elements and the same linear model as built through the C++
// API; its flap damping in attached flow equals the closed form; the example case reads and solves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case_file_test_util.hpp"
#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/trim.hpp"
#include "tests/unit/aero_case_util.hpp"

namespace whirl {
namespace {

using test::AeroRotorOptions;

Model readAeroRotorCase(const testing::TempCaseDir& tmp, const AeroRotorOptions& o) {
  tmp.write("thin.dat", test::thinAirfoilFile(o.cd));
  return readCase(tmp.write("rotor.yaml", test::aeroRotorCase(o)));
}

// Largest entry-wise difference relative to the largest entry of `b`.
double relativeDifference(const MatX& a, const MatX& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1e-300, b.cwiseAbs().maxCoeff());
}

TEST(CaseAero, BladeElementsEqualTheRotorBuiltInCpp) {
  testing::TempCaseDir tmp;
  const AeroRotorOptions o;  // precone 2.5°, pitch 2°, induction on
  const Model yaml = readAeroRotorCase(tmp, o);
  const Model cpp = test::aeroRotorModel(o);
  const AeroModel &a = yaml.aero, &b = cpp.aero;
  ASSERT_EQ(a.blades.size(), 3u);
  // Derived from the rest pose here, written by hand there (HubRad, (HubRad + span) cos(precone)).
  EXPECT_NEAR(a.hub_radius, b.hub_radius, 1e-12);
  EXPECT_NEAR(a.tip_radius, b.tip_radius, 1e-12);
  EXPECT_NEAR(a.rotor_radius, b.rotor_radius, 1e-12);
  EXPECT_EQ(a.hub_body, b.hub_body);
  EXPECT_EQ(a.induction, b.induction);
  EXPECT_EQ(a.bem.tip_loss, b.bem.tip_loss);
  EXPECT_EQ(a.bem.ai_drag, b.bem.ai_drag);
  EXPECT_EQ(yaml.inputs[yaml.roles.wind_speed_input].name, "wind speed");
  EXPECT_EQ(yaml.inputs[yaml.roles.wind_speed_input].value, o.wind);
  EXPECT_EQ(a.wind.reference_height, b.wind.reference_height);
  for (int k = 0; k < 3; ++k) {
    const AeroBlade &p = a.blades[k], &q = b.blades[k];
    EXPECT_EQ(p.body, q.body);
    EXPECT_EQ(p.pitch_dof, q.pitch_dof);
    ASSERT_EQ(p.stations.size(), q.stations.size());
    for (size_t s = 0; s < p.stations.size(); ++s) {
      const AeroStation &u = p.stations[s], &v = q.stations[s];
      EXPECT_NEAR(u.span, v.span, 1e-12);
      EXPECT_NEAR(u.z, v.z, 1e-12);
      EXPECT_NEAR(u.chord, v.chord, 1e-14);
      EXPECT_NEAR(u.twist, v.twist, 1e-15);
      EXPECT_NEAR(u.weight, v.weight, 1e-12);
      EXPECT_EQ(u.polar, v.polar);
      const BodyPoint &pu = yaml.bodies[p.body].points[u.point], &pv = cpp.bodies[q.body].points[v.point];
      EXPECT_LT((pu.P - pv.P).cwiseAbs().maxCoeff(), 1e-12);
      EXPECT_LT((pu.theta - pv.theta).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

TEST(CaseAero, AerodynamicCentreOffsetsAndFractions) {
  // AeroDyn's BlCrvAC, BlSwpAC as `ac_y`, `ac_z`: the element's point moves off the mean line in body
  // y, z, and its distance from the apex runs along the offset nodes (AeroDyn's curvilinear zLocal).
  testing::TempCaseDir tmp;
  AeroRotorOptions o;
  o.elements = 3;  // stations 0, 20, 40 m
  std::string text = test::aeroRotorCase(o);
  text = testing::replaced(text, "        airfoil: [1, 1, 1]\n",
                           "        airfoil: [1, 1, 1]\n        ac_y: [0, 0.3, 0.6]\n        ac_z: [0, 0, -0.4]\n");
  text = testing::replaced(text, "        x: [0, 20, 40]\n        chord",
                           "        fraction: [0, 0.5, 1]\n        chord");
  tmp.write("thin.dat", test::thinAirfoilFile(o.cd));
  text = testing::replaced(text, "      pitch: blade 1 pitch\n", "");  // the default: the body's joint about −x
  const Model m = readCase(tmp.write("rotor.yaml", text));
  const AeroBlade& b = m.aero.blades[0];
  EXPECT_EQ(b.pitch_dof, *m.findDof("blade 1 pitch"));
  const Body& body = m.bodies[b.body];
  EXPECT_NEAR(body.points[b.stations[1].point].P(1, 0), 0.3, 1e-15);
  EXPECT_NEAR(body.points[b.stations[2].point].P(2, 0), -0.4, 1e-15);
  EXPECT_NEAR(b.stations[2].span, 40, 1e-12);
  EXPECT_NEAR(b.stations[1].z - b.stations[0].z, std::hypot(20, 0.3), 1e-12);
  EXPECT_NEAR(b.stations[2].z - b.stations[1].z, std::sqrt(20 * 20 + 0.3 * 0.3 + 0.4 * 0.4), 1e-12);
  EXPECT_NEAR(m.aero.tip_radius, b.stations[2].z, 1e-12);
  // The other blades have no offsets: one tip radius per rotor is the largest.
  EXPECT_GT(m.aero.tip_radius, m.aero.blades[1].stations[2].z);
}

TEST(CaseAero, LinearModelEqualsTheRotorBuiltInCpp) {
  // The two paths share the equations; what differs is every number the reader derives (rest-pose
  // geometry, element weights and distances, the polar read back from an airfoil file, the wind and
  // pitch inputs). Equilibrium with BEM induction, then the frozen-wake linearization of both.
  testing::TempCaseDir tmp;
  const AeroRotorOptions o;
  const Model yaml = readAeroRotorCase(tmp, o);
  const Model cpp = test::aeroRotorModel(o);
  const LinearModel ly = linearize(yaml, solveOperatingPoint(yaml, initialPoint(yaml)));
  const LinearModel lc = linearize(cpp, solveOperatingPoint(cpp, initialPoint(cpp)));
  ASSERT_EQ(ly.dof_names, lc.dof_names);
  // Round-off only (measured ≤ 6e-16): the 17-digit rotations, the airfoil's α in degrees.
  EXPECT_LT(relativeDifference(ly.M, lc.M), 1e-12);
  EXPECT_LT(relativeDifference(ly.C, lc.C), 1e-12);
  EXPECT_LT(relativeDifference(ly.K, lc.K), 1e-12);
  for (const std::string name : {"wind speed", "collective pitch"}) {
    const auto col = [&](const Model& m, const LinearModel& l) { return l.Q.col(*m.findInput(name)); };
    EXPECT_LT(relativeDifference(col(yaml, ly), col(cpp, lc)), 1e-12) << name;
    EXPECT_GT(col(cpp, lc).cwiseAbs().maxCoeff(), 1e3) << name;
  }
  EXPECT_GT(lc.C.cwiseAbs().maxCoeff(), 1e3);  // aerodynamic damping present
}

TEST(CaseAero, FlapDampingOfAttachedFlowEqualsClosedForm) {
  // As AeroLoads.FlapDampingOfAttachedFlowEqualsClosedForm (test_aero_loads.cpp), on the model read
  // from the case: without induction, Cl = 2π α, Cd = 0, the damping of the flap coordinate is
  //   Σ w_s φ_s² ∂Fx/∂Vx,  ∂Fx/∂Vx = ½ ρ c 2π [2 Vx (φ − θ) cos φ + W² ∂φ/∂Vx (cos φ − (φ − θ) sin φ)],
  // φ = atan2(Vx, Vy), W² = Vx² + Vy², ∂φ/∂Vx = Vy / W² (Hansen 2004, quasi-steady aerodynamic damping).
  testing::TempCaseDir tmp;
  AeroRotorOptions o;
  o.induction = false;
  o.cd = 0;
  o.precone_deg = 0;
  o.pitch_deg = 0;
  const Model m = readAeroRotorCase(tmp, o);
  const LinearModel lin = linearize(m, initialPoint(m));
  const int flap = *m.findDof("blade 1 flap 1");
  int row = -1;
  for (size_t k = 0; k < lin.dofs.size(); ++k)
    if (lin.dofs[k] == flap) row = static_cast<int>(k);
  ASSERT_GE(row, 0);
  const double omega = o.rpm * std::numbers::pi / 30, rho = m.aero.air_density;
  double c = 0;
  const Body& blade = m.bodies[m.aero.blades[0].body];
  for (const AeroStation& st : m.aero.blades[0].stations) {
    const double vx = o.wind, vy = omega * st.z, th = st.twist;
    const double phi = std::atan2(vx, vy), w2 = vx * vx + vy * vy, dphi = vy / w2;
    const double dFx = 0.5 * rho * st.chord * 2 * std::numbers::pi *
                       (2 * vx * (phi - th) * std::cos(phi) + w2 * dphi * (std::cos(phi) - (phi - th) * std::sin(phi)));
    const double shape = blade.points[st.point].P(1, 1);
    c += st.weight * dFx * shape * shape;
  }
  // Exact up to round-off (the airfoil file's α in degrees, Cl to 17 digits; measured 3e-16), as the
  // C++-built model's 1e-9 in test_aero_loads.cpp.
  EXPECT_NEAR(lin.C(row, row), c, 1e-9 * c);
  EXPECT_GT(c, 1e3);
}

TEST(CaseAero, ExampleCaseReadsAndProducesPower) {
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/aero_rotor/aero_rotor.yaml");
  ASSERT_EQ(m.aero.blades.size(), 3u);
  EXPECT_EQ(m.aero.blades[0].stations.size(), 11u);
  EXPECT_EQ(m.aero.polars.size(), 1u);
  // Hub radius 1.5 m, 40 m blades, no cone: written in the case (offset, length, stations).
  EXPECT_NEAR(m.aero.hub_radius, 1.5, 1e-12);
  EXPECT_NEAR(m.aero.tip_radius, 41.5, 1e-12);
  EXPECT_NEAR(m.aero.rotor_radius, 41.5, 1e-12);
  EXPECT_NEAR(m.aero.blades[1].stations[3].twist, 7 * std::numbers::pi / 180, 1e-15);
  EXPECT_EQ(m.roles.blade_pitch.size(), 3u);
  EXPECT_EQ(m.aero.blades[2].pitch_dof, *m.findDof("blade 3 pitch"));
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  // At 12 rpm and 8 m/s (tip-speed ratio 6.5) the rotor pushes downwind and drives the shaft.
  EXPECT_GT(op.aero.thrust, 1e4);
  EXPECT_GT(op.aero.torque, 1e4);
  EXPECT_TRUE(m.findOutput("RtAeroFxh") && m.findOutput("RtAeroMxh") && m.findOutput("RtAeroPwr"));
}

TEST(CaseAero, GeneratorLawTrimsTheExampleBelowRated) {
  // The example's `generator:` in ServoDyn's units: VS_RtGnSp 14 rpm, VS_RtTq 1.35e6 N m, VS_Rgn2K
  // 3400 N m/rpm², VS_SlPc 10 %. Trimmed at 6 m/s (region 2): the law's torque is k ω² at the rotor
  // speed found, and it balances the aerodynamic torque (direct drive, gear ratio 1).
  const Model m = readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/aero_rotor/aero_rotor.yaml");
  ASSERT_TRUE(m.generator.active());
  EXPECT_EQ(m.inputs[m.roles.generator_torque_input].name, "generator torque");
  EXPECT_NEAR(m.generator.rated_speed, 14 * std::numbers::pi / 30, 1e-15);
  EXPECT_NEAR(m.generator.slip, 0.1, 1e-15);
  EXPECT_EQ(m.generator.efficiency, 1.0);
  const SteadyState s = trimAtWindSpeed(m, 6.0);
  EXPECT_FALSE(s.above_rated);
  const double rpm = s.condition.rotor_speed * 30 / std::numbers::pi;
  EXPECT_GT(rpm, 5);
  EXPECT_LT(rpm, 14 / 1.1);  // below region 2½ (synchronous speed 14 / 1.1 rpm)
  EXPECT_NEAR(s.generator_torque, 3400 * rpm * rpm, 1e-9 * s.generator_torque);
  EXPECT_NEAR(s.aero_torque, s.generator_torque, 1e-6 * s.generator_torque);
}

}  // namespace
}  // namespace whirl

// The ElastoDyn-equivalent NREL 5MW (cases/nrel5mw) built from whirl's bodies and joints: DOF names and
// switches, masses against ElastoDyn's summary numbers, geometry against ElastoDyn's own formulas
// (SetCoordSy, CalculatePositions), and the directions of DOFs and inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linearize/linearize.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi, deg = pi / 180;

std::string fst() { return (test::nrel5mwDir() / "Main_Onshore.fst").string(); }

double bodyMass(const Model& m, const std::string& name) { return m.bodies[*m.findBody(name)].inertia.mass; }

TEST(ElastoDynModel, DofNamesAndSwitchesOfTheNrel5mwFile) {
  const Model m = readElastoDynModel(fst(), {});
  std::vector<std::string> names;
  for (const Dof& d : m.dofs) names.push_back(d.name);
  std::vector<std::string> expected{"tower FA 1", "tower SS 1",        "tower FA 2", "tower SS 2",
                                    "yaw",        "generator azimuth", "drivetrain"};
  for (int b = 1; b <= 3; ++b)
    for (const char* s : {"pitch", "flap 1", "edge 1", "flap 2"})
      expected.push_back("blade " + std::to_string(b) + " " + s);
  EXPECT_EQ(names, expected);
  for (const Dof& d : m.dofs) EXPECT_EQ(d.frozen, d.name.find("pitch") != std::string::npos) << d.name;
  const Dof& az = m.dofs[*m.findDof("generator azimuth")];
  EXPECT_TRUE(az.rotating);
  EXPECT_DOUBLE_EQ(az.rate, 10.0 * pi / 30);  // RotSpeed 10 rpm
  EXPECT_EQ(m.inputs.size(), 9u);
  for (const char* in : {"generator torque", "rotor thrust", "rotor torque", "tower-top force", "tower-top side force",
                         "collective pitch", "blade 1 pitch", "blade 2 pitch", "blade 3 pitch"})
    EXPECT_TRUE(m.findInput(in).has_value()) << in;
  EXPECT_EQ(m.inputs[*m.findInput("collective pitch")].dofs.size(), 3u);
  EXPECT_EQ(m.inputs[*m.findInput("blade 2 pitch")].blade, 1);
  EXPECT_EQ(m.outputs.size(),
            22u);  // 15 + BldPitch1..3, TwrBsMyt, NcIMURAys (issue 41), YawBrTVxp, NcIMURVys (issue 43)
  ASSERT_EQ(m.springs.size(), 2u);  // drivetrain, yaw (ServoDyn)
  EXPECT_DOUBLE_EQ(m.springs[0].k, 8.67637e8);
  EXPECT_DOUBLE_EQ(m.springs[0].c, 6.215e6);
  EXPECT_DOUBLE_EQ(m.springs[1].k, 9.02832e9);
  EXPECT_DOUBLE_EQ(m.springs[1].c, 1.916e7);
  EXPECT_EQ(m.dofs[m.springs[1].dof].name, "yaw");
  EXPECT_DOUBLE_EQ(m.gravity.z(), -9.80665);
}

TEST(ElastoDynModel, SwitchedOffDofsAreFrozenAtTheirInitialValues) {
  const Model m = readElastoDynModel(fst(), {"GenDOF=False", "DrTrDOF=False", "FlapDOF2=False", "TwSSDOF2=False",
                                             "YawDOF=False", "EdgeDOF=False", "NacYaw=10", "Azimuth=120", "AzimB1Up=90",
                                             "BlPitch(2)=5", "RotSpeed=12.1"});
  const std::vector<std::string> frozen{"tower SS 2", "yaw", "generator azimuth", "drivetrain"};
  for (const Dof& d : m.dofs) {
    const bool off = std::find(frozen.begin(), frozen.end(), d.name) != frozen.end() ||
                     d.name.find("pitch") != std::string::npos || d.name.find("flap 2") != std::string::npos ||
                     d.name.find("edge 1") != std::string::npos;
    EXPECT_EQ(d.frozen, off) << d.name;
  }
  EXPECT_EQ(m.activeDofs().size(), 6u);  // tower FA 1, SS 1, FA 2, blade k flap 1
  EXPECT_NEAR(m.dofs[*m.findDof("yaw")].value, 10 * deg, 1e-15);
  const Dof& az = m.dofs[*m.findDof("generator azimuth")];
  EXPECT_NEAR(az.value, 30 * deg, 1e-15);  // Azimuth − AzimB1Up: 0 = blade 1 up
  EXPECT_NEAR(az.rate, 12.1 * pi / 30, 1e-15);
  EXPECT_NEAR(m.dofs[*m.findDof("blade 2 pitch")].value, 5 * deg, 1e-15);
  EXPECT_TRUE(m.springs.empty());  // no drivetrain or yaw freedom: no spring, ServoDyn not needed
}

TEST(ElastoDynModel, MassesMatchElastoDynsSummary) {
  const Model m = readElastoDynModel(fst(), {});
  // ElastoDyn (Coeff): TwrMass = Σ TMassDen·AdjTwMa·ΔH on TwrNodes = 20 equal elements; its summary
  // prints 347,460 kg for the NREL 5MW tower.
  EXPECT_NEAR(bodyMass(m, "tower"), 347460.232, 1e-3);
  EXPECT_DOUBLE_EQ(bodyMass(m, "nacelle"), 240000.0);
  EXPECT_DOUBLE_EQ(bodyMass(m, "hub"), 56780.0);
  EXPECT_DOUBLE_EQ(bodyMass(m, "yaw bearing"), 0.0);
  // Rotor: HubMass + 3 BldMass, BldMass = Σ BMassDen·AdjBlMs·ΔR on BldNodes = 17 equal elements
  // (17,536.614 kg). The design report's 110,000 kg (17,740 kg per blade) comes from FAST's 2009 blade
  // discretization, AeroDyn's 17 unequal elements, for which AdjBlMs = 1.04536 was tuned: 0.56 % more.
  double rotor = bodyMass(m, "hub");
  for (int b = 1; b <= 3; ++b) {
    EXPECT_NEAR(bodyMass(m, "blade " + std::to_string(b)), 17536.614, 1e-3);
    rotor += bodyMass(m, "blade " + std::to_string(b));
  }
  EXPECT_NEAR(rotor, 109389.842, 1e-3);
  EXPECT_NEAR(rotor, 110000.0, 0.006 * 110000.0);
  // Tower-top mass (ElastoDyn's TwrTpMass = RotMass + NacMass + YawBrMass) and turbine mass.
  const double top = rotor + bodyMass(m, "nacelle") + bodyMass(m, "yaw bearing") + bodyMass(m, "generator");
  EXPECT_NEAR(top, 349389.842, 1e-3);
  double total = 0;
  for (const Body& b : m.bodies) total += b.inertia.mass;
  EXPECT_NEAR(total, 696850.074, 1e-3);
}

struct Pose {
  Vec3 r;
  Mat3 R;
};

Pose poseOf(const Model& m, const Workspace<double>& ws, const std::string& body) {
  const FrameState<double>& f = ws.frames[*m.findBody(body)];
  return {f.r, f.R};
}

TEST(ElastoDynModel, GeometryFollowsElastoDynsFrames) {
  const Model m = readElastoDynModel(fst(), {"BlPitch(1)=10", "NacYaw=0"});
  Workspace<double> ws(m);
  const OperatingPoint op = initialPoint(m);  // undeflected, blade 1 up
  forwardKinematics(m, ws, op.q, op.qd, op.qdd);
  const double tilt = -5 * deg, cone = -2.5 * deg, overhang = -5.0191, twr2shft = 1.96256, tower_ht = 87.6;
  // Rotor apex Q = tower top + Twr2Shft d2 + OverHang c1, c1 = cos(ShftTilt) d1 + sin(ShftTilt) d2;
  // hub height TowerHt + Twr2Shft + OverHang sin(ShftTilt) = 90.0 m (design report).
  const Vec3 c1(std::cos(tilt), 0, std::sin(tilt)), c2(-std::sin(tilt), 0, std::cos(tilt)), Y = Vec3::UnitY();
  const Pose hub = poseOf(m, ws, "hub");
  EXPECT_NEAR((hub.r - Vec3(overhang * std::cos(tilt), 0, tower_ht + twr2shft + overhang * std::sin(tilt))).norm(), 0,
              1e-12);
  EXPECT_NEAR(hub.r.z(), 90.0, 1e-5);
  EXPECT_NEAR((hub.R.col(0) - c1).norm(), 0, 1e-12);
  // Blade k (ElastoDyn, blade 1 up): g3' = −sin γ g2 + cos γ g3 with g2 = Y, g3 = c2, γ = 2π(k−1)/3;
  // i3 = sin β c1 + cos β g3'; root at HubRad i3, tip at TipRad i3 from the apex.
  for (int k = 0; k < 3; ++k) {
    const double g = 2 * pi * k / 3;
    const Vec3 g2p = std::cos(g) * Y + std::sin(g) * c2, g3p = -std::sin(g) * Y + std::cos(g) * c2;
    const Vec3 i1 = std::cos(cone) * c1 - std::sin(cone) * g3p, i3 = std::sin(cone) * c1 + std::cos(cone) * g3p;
    const Pose blade = poseOf(m, ws, "blade " + std::to_string(k + 1));
    EXPECT_NEAR((blade.r - (hub.r + 1.5 * i3)).norm(), 0, 1e-12) << "root of blade " << k + 1;
    const Vec3 tip = blade.r + blade.R * m.bodies[*m.findBody("blade " + std::to_string(k + 1))].points[0].P.col(0);
    EXPECT_NEAR((tip - (hub.r + 63.0 * i3)).norm(), 0, 1e-12) << "tip of blade " << k + 1;
    // Pitch: j1 = cos θ i1 − sin θ i2 (body y), i2 = g2'.
    const double th = k == 0 ? 10 * deg : 0.0;
    EXPECT_NEAR((blade.R.col(1) - (std::cos(th) * i1 - std::sin(th) * g2p)).norm(), 0, 1e-12)
        << "j1 of blade " << k + 1;
  }
  EXPECT_LT(poseOf(m, ws, "blade 1").R.col(0).dot(c1), 0);  // coned upwind of the rotor plane: PreCone < 0
}

TEST(ElastoDynModel, DofDirections) {
  const Model m = readElastoDynModel(fst(), {});
  Workspace<double> ws(m);
  const OperatingPoint op = initialPoint(m);
  forwardKinematics(m, ws, op.q, op.qd, op.qdd);
  const FrameState<double>& nac = ws.frames[*m.findBody("nacelle")];
  // ElastoDyn: TFA along a1 = X, TSS along a3 = −Y, both normalized to unit tower-top deflection.
  EXPECT_NEAR((nac.Jv.col(*m.findDof("tower FA 1")) - Vec3::UnitX()).norm(), 0, 1e-12);
  EXPECT_NEAR((nac.Jv.col(*m.findDof("tower SS 1")) + Vec3::UnitY()).norm(), 0, 1e-12);
  EXPECT_NEAR((nac.Jw.col(*m.findDof("yaw")) - Vec3::UnitZ()).norm(), 0, 1e-12);
  // Blade 1 (up, zero pitch): flap moves the tip downwind (j1), edge along j2 = +Y (towards the trailing edge).
  const int b1 = *m.findBody("blade 1");
  const Mat3& R = ws.frames[b1].R;
  const Mat3X& P = m.bodies[b1].points[0].P;
  EXPECT_GT((R * P.col(1)).x(), 0.95);  // flap 1
  EXPECT_GT((R * P.col(2)).y(), 0.95);  // edge 1
  EXPECT_GT((R * P.col(3)).x(), 0.95);  // flap 2
}

TEST(ElastoDynModel, InputsAndSpringsInTheLinearModel) {
  const Model m = readElastoDynModel(fst(), {"RotSpeed=0", "gravity=0"});
  const LinearModel lin = linearize(m, solveOperatingPoint(m, initialPoint(m)));
  auto row = [&](const char* dof) {
    for (std::size_t i = 0; i < lin.dofs.size(); ++i)
      if (lin.dof_names[i] == dof) return static_cast<Eigen::Index>(i);
    ADD_FAILURE() << dof;
    return Eigen::Index(0);
  };
  auto col = [&](const char* in) { return static_cast<Eigen::Index>(*m.findInput(in)); };
  EXPECT_NEAR(lin.Q(row("generator azimuth"), col("generator torque")), -97.0, 1e-9);  // −GBRatio
  EXPECT_NEAR(lin.Q(row("drivetrain"), col("generator torque")), 0.0, 1e-9);
  EXPECT_NEAR(lin.Q(row("yaw"), col("generator torque")), 0.0, 1e-9);  // reacted inside the nacelle
  EXPECT_NEAR(lin.Q(row("generator azimuth"), col("rotor torque")), 1.0, 1e-12);
  EXPECT_NEAR(lin.Q(row("drivetrain"), col("rotor torque")), 1.0, 1e-12);
  EXPECT_NEAR(lin.Q(row("tower FA 1"), col("tower-top force")), 1.0, 1e-12);
  EXPECT_NEAR(lin.Q(row("tower SS 1"), col("tower-top side force")), -1.0, 1e-12);
  EXPECT_GT(lin.Q(row("tower FA 1"), col("rotor thrust")), 0.99);
  // Without gravity the only stiffness on yaw and drivetrain is the springs'.
  EXPECT_NEAR(lin.K(row("yaw"), row("yaw")), 9.02832e9, 1e-6 * 9.02832e9);
  EXPECT_NEAR(lin.C(row("yaw"), row("yaw")), 1.916e7, 1e-6 * 1.916e7);
  EXPECT_NEAR(lin.K(row("drivetrain"), row("drivetrain")), 8.67637e8, 1e-6 * 8.67637e8);
  // The generator azimuth sees GenIner·GBRatio² (plus the rotor through the drivetrain chain).
  EXPECT_NEAR(lin.M(row("generator azimuth"), row("generator azimuth")) - lin.M(row("drivetrain"), row("drivetrain")),
              534.116 * 97 * 97, 1e-6 * 534.116 * 97 * 97);
}

}  // namespace
}  // namespace whirl

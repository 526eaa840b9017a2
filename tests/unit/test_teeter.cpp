// The teetering hub of a 2-bladed ElastoDyn rotor (src/turbine/elastodyn_teeter.cpp) against paths
// that do not go through it:
//  - a rigid rotor on a rigid support, turning at constant Ω without gravity, teeters at
//    ω² = (k + Ω² (J_xx − J_zz)) / J_yy (Euler's equation about the teeter axis; the products of inertia
//    drop out of the linear equation), J the rotor's inertia about the teeter pin in teeter axes (x shaft,
//    y teeter axis), summed here from ElastoDyn's definitions: blade node masses at the element centres,
//    tip masses, the hub's mass and inertia. A flat rotor (no δ3, undersling or cone) has
//    J_xx − J_zz = J_yy = I: ω² = k/I + Ω², the teeter spring plus centrifugal stiffening;
//  - Floquet analysis sees that teeter in the fixed frame at ω − Ω (the rotor plane precessing), "teeter BW";
//  - on the AWT-27 deck with every DOF on, −∂e/∂q̈ (AD) equals the assembled mass matrix.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "linearize/jacobian.hpp"
#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "modal/rotor_modes.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi;
const std::filesystem::path kAwt = test::openfastDataDir() / "decks" / "certtest" / "AWT27";

// AWT-27's ElastoDyn and tower files, and a uniform blade (40 kg/m from root to tip) in its format.
class RigidTeeter : public testing::Test {
 protected:
  void SetUp() override {
    ed_ = dir_.copy(kAwt / "Test01_ElastoDyn.dat");
    dir_.copy(kAwt / "AWT_Tower.dat");
    std::istringstream in(test::readText(kAwt / "AWT_Blades.dat"));
    std::string line, out;
    for (int n = 1; std::getline(in, line); ++n) {
      if (n == 4) line = "          2   NBlInpSt    - Number of blade input stations (-)";
      if (n == 17) out += "0.0  0.25  0.0  40.0  1.0E+07  1.0E+08\n1.0  0.25  0.0  40.0  1.0E+07  1.0E+08\n";
      if (n >= 17 && n <= 37) continue;  // AWT-27's 21 rows
      out += line + "\n";
    }
    dir_.write("uniform_blade.dat", out);
  }
  // Rigid everything but the teeter, no gravity, a teeter spring k from 0 deg and no damper, Ω = 53.333 rpm.
  std::vector<std::string> overrides(const std::vector<std::string>& extra) const {
    std::vector<std::string> o = {"FlapDOF1=False",
                                  "FlapDOF2=False",
                                  "EdgeDOF=False",
                                  "DrTrDOF=False",
                                  "GenDOF=False",
                                  "TwFADOF1=False",
                                  "TwFADOF2=False",
                                  "TwSSDOF1=False",
                                  "TwSSDOF2=False",
                                  "gravity=0",
                                  "BldFile(1)=uniform_blade.dat",
                                  "BldFile(2)=uniform_blade.dat",
                                  "TeetDmp=0",
                                  "TeetSSSp=" + std::to_string(kSpring)};
    o.insert(o.end(), extra.begin(), extra.end());
    return o;
  }
  // Teeter frequency² [rad²/s²] of the rotor of the ElastoDyn file (after the overrides), from its
  // inertia about the pin (ElastoDyn's definitions, summed here).
  double closedForm(double hub_cm, double undersling, double delta3_deg, double cone_deg, bool teeter_inertia_key,
                    double hub_iner_teeter = 0) const {
    const double R = 13.757, r0 = 1.184, rho = 40, tip = 11.34, Mh = 1330, HubIner = 335.34;
    const int nodes = 10;
    const double d3 = delta3_deg * pi / 180, c = cone_deg * pi / 180, dr = (R - r0) / nodes;
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    auto point = [&](double m, const Eigen::Vector3d& p) {
      J += m * (p.squaredNorm() * Eigen::Matrix3d::Identity() - p * p.transpose());
    };
    for (int k = 0; k < 2; ++k) {
      const double a = d3 + pi * k;  // blade k's angle about the shaft from the teeter frame's z
      const Eigen::Vector3d i3(std::sin(c), -std::sin(a) * std::cos(c), std::cos(a) * std::cos(c));
      const Eigen::Vector3d apex(-undersling, 0, 0);
      for (int j = 1; j <= nodes; ++j) point(rho * dr, apex + (r0 + (j - 0.5) * dr) * i3);
      point(tip, apex + R * i3);
    }
    // Hub: mass at HubCM from the apex; inertia about its centre of mass, per ElastoDyn's convention.
    const Eigen::Vector3d cm(hub_cm - undersling, 0, 0);
    point(Mh, cm);
    const double parallel = Mh * (undersling - hub_cm) * (undersling - hub_cm);
    if (teeter_inertia_key) {
      J += Eigen::Vector3d(HubIner, hub_iner_teeter - parallel, 0).asDiagonal();
    } else {
      const double g = (HubIner - parallel) / (std::cos(d3) * std::cos(d3));
      const Eigen::Vector3d g2(0, std::cos(d3), std::sin(d3));
      J += g * (Eigen::Matrix3d(Eigen::Vector3d(1, 0, 0).asDiagonal()) + g2 * g2.transpose());
    }
    const double W = 53.333 * pi / 30;
    return (kSpring + W * W * (J(0, 0) - J(2, 2))) / J(1, 1);
  }
  // ω² of the model's teeter in the rotating frame: its one coordinate linearized at one azimuth.
  static double teeterFrequency2(const Model& m) {
    const LinearModel l = linearize(m, solveOperatingPoint(m, initialPoint(m)));
    EXPECT_EQ(l.dof_names, std::vector<std::string>{"teeter"});
    return l.K(0, 0) / l.M(0, 0);
  }

  static constexpr double kSpring = 2e5;  // N m/rad
  test::ScratchDir dir_;
  std::filesystem::path ed_;
};

TEST_F(RigidTeeter, FlatRotorIsSpringPlusCentrifugalStiffening) {
  const Model m = readElastoDynModel(ed_.string(),
                                     overrides({"UndSling=0", "Delta3=0", "PreCone(1)=0", "PreCone(2)=0", "HubCM=0"}));
  // I = HubIner + Σ blades (node masses r² + tip mass R²): ElastoDyn's node rule, 10 elements.
  double I = 335.34;
  const double dr = (13.757 - 1.184) / 10;
  for (int j = 1; j <= 10; ++j) I += 2 * 40 * dr * std::pow(1.184 + (j - 0.5) * dr, 2);
  I += 2 * 11.34 * 13.757 * 13.757;
  const double W = 53.333 * pi / 30;
  const double expected = kSpring / I + W * W;
  EXPECT_NEAR(teeterFrequency2(m), expected, 1e-10 * expected);
  EXPECT_NEAR(closedForm(0, 0, 0, 0, false), expected, 1e-12 * expected);  // the general sum agrees
}

TEST_F(RigidTeeter, Delta3UnderslingConeAndHubOffset) {
  const Model m = readElastoDynModel(ed_.string(), overrides({"UndSling=0.3", "Delta3=30", "PreCone(1)=5",
                                                              "PreCone(2)=5", "HubCM=0.1"}));
  const double expected = closedForm(0.1, 0.3, 30, 5, false);
  EXPECT_NEAR(teeterFrequency2(m), expected, 1e-10 * expected);
  // The flat formula would be off by the undersling's and δ3's share: the check can fail.
  EXPECT_GT(std::abs(closedForm(0, 0, 0, 0, false) - expected), 1e-3 * expected);
}

TEST_F(RigidTeeter, HubInertiaAboutTheTeeterAxisWhenTheFileGivesIt) {
  // OpenFAST's newer files add HubIner_Teeter after HubIner (HubIner then about the shaft only).
  dir_.write(ed_.filename().string(),
             test::replaceOnce(
                 test::readText(ed_), "      59.26   GenIner",
                 "        900   HubIner_Teeter - Hub inertia about teeter axis (kg m^2)\n      59.26   GenIner"));
  const Model m = readElastoDynModel(ed_.string(), overrides({"UndSling=0.3", "Delta3=30", "PreCone(1)=5",
                                                              "PreCone(2)=5", "HubCM=0.1"}));
  const double expected = closedForm(0.1, 0.3, 30, 5, true, 900);
  EXPECT_NEAR(teeterFrequency2(m), expected, 1e-10 * expected);
}

// In the fixed frame the rotating-frame teeter ω shows as the tilt of the rotor plane turning at
// ω − Ω (and ω + Ω, equally: a standing pattern of 2 blades); Floquet names the slower one, backward.
TEST_F(RigidTeeter, FloquetSeesTheTeeterInTheFixedFrame) {
  const Model m = readElastoDynModel(ed_.string(),
                                     overrides({"UndSling=0", "Delta3=0", "PreCone(1)=0", "PreCone(2)=0", "HubCM=0"}));
  const double w = std::sqrt(teeterFrequency2(m)), W = 53.333 * pi / 30;
  PeriodicOptions opt;
  opt.azimuths = 8;
  const RotorModes r = rotorModes(m, linearizePeriodic(m, initialPoint(m), opt));
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_EQ(r.modes[0].name, "teeter BW");
  EXPECT_NEAR(r.modes[0].freq_hz, (w - W) / (2 * pi), 1e-8 * w / (2 * pi));
}

// The deck's teeter (TeetDOF, spring from 0 deg, damper) on a model with every AWT-27 DOF on, δ3 and
// undersling, at a general state: the AD mass matrix equals the assembled one.
TEST(Teeter, AdMassEqualsAssembledMassMatrix) {
  const Model m = readElastoDynModel((kAwt / "Test01_ElastoDyn.dat").string(), {"YawDOF=True", "Delta3=20"});
  ASSERT_GE(m.roles.teeter_dof, 0);
  EXPECT_FALSE(m.dofs[m.roles.teeter_dof].frozen);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> d(-1, 1);
  const int n = m.ndof();
  VecX q(n), qd(n), qdd(n);
  for (int i = 0; i < n; ++i) {
    const bool elastic = m.dofs[i].kind == DofKind::Elastic;
    q(i) = (elastic ? 0.2 : 0.3) * d(gen);
    qd(i) = 0.3 * d(gen);
    qdd(i) = d(gen);
  }
  const VecX u = VecX::Zero(m.ninput());
  std::vector<int> all(n);
  for (int i = 0; i < n; ++i) all[i] = i;
  JacobianWorkspace jw(m);
  Workspace<double> ws(m);
  const MatX dedqdd = residualJacobian(m, jw, q, qd, qdd, u, Wrt::Qdd, all);
  MatX M;
  massMatrix(m, ws, q, M);
  const double scale = M.cwiseAbs().maxCoeff();
  EXPECT_LT((M + dedqdd).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_GT(M(m.roles.teeter_dof, m.roles.teeter_dof), 1e4);  // the rotor's teeter inertia is in it
}

}  // namespace
}  // namespace whirl

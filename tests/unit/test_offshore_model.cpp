// The ElastoDyn builder's floating platform on the OC3-Hywind deck (cases/oc3_hywind): platform body,
// DOF names, the tower base on the platform, HydroDyn's matrices and loads, the mooring lines; and
// bad offshore input as one-line InputErrors naming the file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "src/base/error.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/workspace.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kCase = fs::path(WHIRL_SOURCE_DIR) / "cases/oc3_hywind";
const std::vector<std::string> kSets = {"CompAero=0", "RdtnMod=0"};

TEST(OffshoreModel, Oc3HywindPlatform) {
  const Model m = readElastoDynModel((kCase / "Test24.fst").string(), kSets);
  const int p = *m.findBody("platform");
  EXPECT_EQ(m.bodies[p].joint, JointType::Free);
  EXPECT_EQ(m.bodies[p].inertia.mass, 7.46633e6);                         // PtfmMass
  EXPECT_NEAR(m.bodies[p].inertia.m1(2, 0), 7.46633e6 * -89.9155, 1e-3);  // PtfmCMzt below PtfmRefzt = 0
  EXPECT_EQ(m.bodies[*m.findBody("tower")].parent, p);
  EXPECT_EQ(m.bodies[*m.findBody("tower")].offset, Vec3(0, 0, 10));  // TowerBsHt above the reference point
  for (const char* n :
       {"platform surge", "platform sway", "platform heave", "platform roll", "platform pitch", "platform yaw"}) {
    ASSERT_TRUE(m.findDof(n)) << n;
    EXPECT_FALSE(m.dofs[*m.findDof(n)].frozen) << n;
  }
  ASSERT_EQ(m.body_matrices.size(), 1u);
  const double rho = 1025, g = 9.80665;
  EXPECT_DOUBLE_EQ(m.body_matrices[0].K(5, 5), 98340000);              // AddCLin
  EXPECT_DOUBLE_EQ(m.body_matrices[0].K(2, 2), 3.312247e1 * rho * g);  // spar.hst
  EXPECT_DOUBLE_EQ(m.body_matrices[0].C(2, 2), 130000);                // AddBLin
  EXPECT_DOUBLE_EQ(m.body_matrices[0].A(0, 0), 7.569865e3 * rho);      // spar.1, PER = 0
  // Buoyancy ρ g PtfmVol0 along heave.
  ASSERT_EQ(m.dof_loads.size(), 1u);
  EXPECT_EQ(m.dof_loads[0].dof, *m.findDof("platform heave"));
  EXPECT_DOUBLE_EQ(m.dof_loads[0].value, rho * g * 8029.21);
  EXPECT_EQ(m.mooring.size(), 3u);
}

TEST(OffshoreModel, SwitchedOffPlatformDofsAreFrozenAtTheirInitialValue) {
  const Model m = readElastoDynModel((kCase / "Test24.fst").string(),
                                     {"CompAero=0", "RdtnMod=0", "PtfmYDOF=False", "PtfmYaw=2"});
  const Dof& d = m.dofs[*m.findDof("platform yaw")];
  EXPECT_TRUE(d.frozen);
  EXPECT_NEAR(d.value, 2 * std::numbers::pi / 180, 1e-15);
}

// ElastoDyn's platform outputs: the coordinates and their derivatives (PtfmSurge … PtfmYaw, PtfmTVxi …,
// PtfmTAxi …) and the platform's angular velocity about the ground axes (PtfmRVxi …). The angular
// velocity is checked against the closed form of the free joint's yaw–pitch–roll rotation R = Rz(ψ) Ry(θ)
// Rx(φ): ω = ψ̇ z + θ̇ Rz y + φ̇ Rz Ry x, at a platform pitched θ = 0.1 rad: a roll rate gives ωx = cos θ and
// ωz = −sin θ, not the roll rate alone.
TEST(OffshoreModel, PlatformOutputsAreTheCoordinatesAndTheAngularVelocity) {
  const Model m = readElastoDynModel((kCase / "Test24.fst").string(),
                                     {"CompAero=0", "RdtnMod=0", "PtfmPitch=5.729577951308232"});
  const double pitch = 0.1;
  Workspace<double> ws(m);
  VecX q(m.ndof()), qd = VecX::Zero(m.ndof()), qdd = VecX::Zero(m.ndof()), y(m.noutput());
  const VecX u = VecX::Zero(m.ninput());  // the load outputs (RootMFlp …) read the inputs
  for (int i = 0; i < m.ndof(); ++i) q(i) = m.dofs[i].value;
  ASSERT_NEAR(q(*m.findDof("platform pitch")), pitch, 1e-15);
  auto out = [&](const char* name) { return y(*m.findOutput(name)); };
  q(*m.findDof("platform surge")) = 2.5;
  evaluateOutputs(m, ws, q, qd, qdd, y, &u);
  EXPECT_EQ(out("PtfmSurge"), 2.5);
  EXPECT_EQ(out("PtfmPitch"), pitch);
  EXPECT_EQ(m.outputs[*m.findOutput("PtfmPitch")].unit, "rad");
  qd(*m.findDof("platform roll")) = 1.0;
  qd(*m.findDof("platform heave")) = 0.5;
  qdd(*m.findDof("platform sway")) = -3.0;
  evaluateOutputs(m, ws, q, qd, qdd, y, &u);
  EXPECT_EQ(out("PtfmTVzi"), 0.5);
  EXPECT_EQ(out("PtfmTAyi"), -3.0);
  EXPECT_NEAR(out("PtfmRVxi"), std::cos(pitch), 1e-14);
  EXPECT_NEAR(out("PtfmRVyi"), 0.0, 1e-14);
  EXPECT_NEAR(out("PtfmRVzi"), -std::sin(pitch), 1e-14);
  EXPECT_EQ(m.outputs[*m.findOutput("PtfmRVzi")].unit, "rad/s");
  // No platform, no platform outputs.
  const Model land = readElastoDynModel((kCase / "Test24.fst").string(),
                                        {"CompAero=0", "CompHydro=0", "CompMooring=0", "PtfmSgDOF=False",
                                         "PtfmSwDOF=False", "PtfmHvDOF=False", "PtfmRDOF=False", "PtfmPDOF=False",
                                         "PtfmYDOF=False"});
  EXPECT_FALSE(land.findOutput("PtfmSurge"));
}

// A copy of the case with one file edited.
struct EditedCase {
  test::TempDir dir;
  EditedCase(const std::string& file, const std::string& from, const std::string& to) {
    fs::copy(kCase, dir.path, fs::copy_options::recursive);
    fs::permissions(dir.path / file, fs::perms::owner_write, fs::perm_options::add);
    std::string text = test::slurp((dir.path / file).string());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream((dir.path / file).string()) << text;
  }
  std::string error() const {
    try {
      readElastoDynModel((dir.path / "Test24.fst").string(), kSets);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST(OffshoreModel, LineThatCannotReachItsAnchor) {
  const EditedCase c("5MW_Baseline/NRELOffshrBsline5MW_OC3Hywind_MAP.dat", "902.2", "400.0");
  const std::string msg = c.error();
  EXPECT_THAT(msg, HasSubstr("NRELOffshrBsline5MW_OC3Hywind_MAP.dat:13: Line 1: "));
  EXPECT_THAT(msg, HasSubstr("cannot reach its anchor"));
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(OffshoreModel, AddedMassNotPositiveSemiDefinite) {
  const EditedCase c("5MW_Baseline/HydroData/spar.1", "  0.000000E+00     3     3  2.353706E+02",
                     "  0.000000E+00     3     3 -2.353706E+02");
  EXPECT_THAT(c.error(), HasSubstr("HydroDyn.dat:48: PotFile: the added mass at infinite frequency is not positive "
                                   "semi-definite"));
}

// A strip-theory member on a floating (rigid) platform: its buoyancy and added mass are not modelled
// there (they are on a SubDyn substructure), one line naming its row.
TEST(OffshoreModel, StripTheoryMemberOnAFloatingPlatformIsRefused) {
  const EditedCase c("5MW_Baseline/NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat",
                     "    2         2          3           1            2         0.5000      1        TRUE",
                     "    2         2          3           1            2         0.5000      1        FALSE");
  EXPECT_THAT(c.error(), HasSubstr("HydroDyn.dat:124: PropPot: False not supported by whirl on a floating platform "
                                   "(strip-theory member 2"));
}

TEST(OffshoreModel, MissingWamitFile) {
  const EditedCase c("5MW_Baseline/NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat", "\"HydroData/Spar\"",
                     "\"HydroData/Nothing\"");
  EXPECT_THAT(c.error(), HasSubstr("HydroDyn.dat:48: PotFile: WAMIT file not found: "));
}

TEST(OffshoreModel, PlatformWithoutHydroOrMooringIsRefused) {
  try {
    readElastoDynModel((kCase / "Test24.fst").string(), {"CompAero=0", "CompHydro=0", "CompMooring=0"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("ElastoDyn.dat:21: PtfmSgDOF: True not supported by whirl (platform DOFs are "
                                    "not modelled, and PtfmSwDOF, PtfmHvDOF, PtfmRDOF, PtfmPDOF, PtfmYDOF are on "
                                    "too: no hydrostatics or mooring (CompHydro = 0, CompMooring = 0) holds the "
                                    "platform)"));
  }
}

}  // namespace
}  // namespace whirl

// Bad inputs to the ElastoDyn model builder: every error is an InputError naming the file (and the
// line and key where there is one). Scratch copies of the NREL 5MW case (cases/nrel5mw).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

using test::inputErrorMessage;
using testing::HasSubstr;

constexpr const char* kFst = "Main_Onshore.fst";
constexpr const char* kEd = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
constexpr const char* kTower = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
constexpr const char* kBlade = "NRELOffshrBsline5MW_Blade.dat";
constexpr const char* kServo = "NRELOffshrBsline5MW_Onshore_ServoDyn.dat";

class ElastoDynModelErrors : public testing::Test {
 protected:
  void SetUp() override {
    for (const char* f : {kFst, kEd, kTower, kBlade, kServo}) dir_.copy(test::nrel5mwDir() / f);
  }
  std::string path(const char* name) const { return (dir_.path() / name).string(); }
  std::string error(const std::vector<std::string>& overrides, const char* file = kFst) {
    return inputErrorMessage([&] { readElastoDynModel(path(file), overrides); });
  }
  void edit(const char* name, const std::string& from, const std::string& to) {
    dir_.write(name, test::replaceOnce(test::readText(dir_.path() / name), from, to));
  }
  test::ScratchDir dir_;
};

TEST_F(ElastoDynModelErrors, TheCopyBuilds) { EXPECT_NO_THROW(readElastoDynModel(path(kFst), {})); }

TEST_F(ElastoDynModelErrors, MissingServoDynWhenTheYawSpringIsNeeded) {
  std::filesystem::remove(dir_.path() / kServo);
  EXPECT_THAT(error({}), HasSubstr(path(kFst) + ":39: ServoFile: file not found: "));
  // Not needed when the yaw is locked, or when ServoDyn is off (then the yaw has no spring).
  EXPECT_NO_THROW(readElastoDynModel(path(kFst), {"YawDOF=False"}));
  const Model m = readElastoDynModel(path(kFst), {"CompServo=0"});
  EXPECT_EQ(m.springs.size(), 1u);  // drivetrain only
}

TEST_F(ElastoDynModelErrors, UnsupportedOption) {
  const std::string msg = error({"PtfmPDOF=True"});
  EXPECT_THAT(msg, HasSubstr(path(kEd) + ":23: PtfmPDOF: True not supported by whirl (platform DOFs"));
  EXPECT_THAT(error({"CompElast=3"}), HasSubstr(path(kFst) + ":13: CompElast: 3 not supported by whirl"));
}

TEST_F(ElastoDynModelErrors, NaNProperty) {
  EXPECT_EQ(error({"NacMass=nan"}), path(kEd) + ":77: NacMass: value is NaN (value set by override)");
  edit(kBlade, "3.5770000E-02  2.5490000E-01  1.3308000E+01  7.4055000E+02",
       "3.5770000E-02  2.5490000E-01  1.3308000E+01  NaN");
  EXPECT_THAT(error({}), HasSubstr(path(kBlade) + ":"));
  EXPECT_THAT(error({}), HasSubstr("BMassDen: value is NaN"));
}

TEST_F(ElastoDynModelErrors, InconsistentValuesNameTheKey) {
  EXPECT_THAT(error({"NacYIner=1000"}),
              HasSubstr(path(kEd) + ":78: NacYIner: must not be less than NacMass·(NacCMxn² + NacCMyn²)"));
  // Checked by the readers already, with file, line and key.
  EXPECT_THAT(error({"TowerBsHt=90"}), HasSubstr(path(kEd) + ":64: TowerHt: must be above TowerBsHt"));
  EXPECT_THAT(error({"AdjTwMa=-1"}), HasSubstr(path(kTower) + ":14: AdjTwMa: must be positive"));
}

TEST_F(ElastoDynModelErrors, Overrides) {
  EXPECT_THAT(error({"NacMas=1"}), HasSubstr("NacMas: unknown key (not in any file read: "));
  EXPECT_THAT(error({"gravity=abc"}), HasSubstr("--set 'gravity=abc': gravity: not a finite number"));
  EXPECT_THAT(error({"NacMass"}), HasSubstr("--set 'NacMass': expected KEY=VALUE"));
  const Model m = readElastoDynModel(path(kFst), {"gravity=3.7", "NacMass=250000"});
  EXPECT_DOUBLE_EQ(m.gravity.z(), -3.7);
  EXPECT_DOUBLE_EQ(m.bodies[*m.findBody("nacelle")].inertia.mass, 250000.0);
}

// Gravity beyond 100 g is an input error (limits::kMaxGravity): the integrator would otherwise follow
// the structure's collapse step by step (fuzz_simulate found 1e9 m/s² taking 93,707 steps).
TEST_F(ElastoDynModelErrors, GravityIsBounded) {
  EXPECT_THAT(error({"gravity=1e9"}), HasSubstr("--set 'gravity=1e9': gravity: must lie in [0, 1000] m/s²"));
  EXPECT_THAT(error({"gravity=-1"}), HasSubstr("--set 'gravity=-1': gravity: must lie in [0, 1000] m/s²"));
  EXPECT_NO_THROW(readElastoDynModel(path(kFst), {"gravity=1000"}));
  edit(kFst, "9.80665                Gravity", "1.0E4                  Gravity");
  EXPECT_THAT(error({}), HasSubstr(path(kFst) + ":23: Gravity: is 10000 m/s², above the limit of 1000 m/s²"));
}

TEST_F(ElastoDynModelErrors, ElastoDynFileAlone) {
  // No .fst: OpenFAST's default gravity, no ServoDyn (no yaw spring), overrides reach ElastoDyn's files.
  const Model m = readElastoDynModel(path(kEd), {"AdjBlMs=1.0"});
  EXPECT_DOUBLE_EQ(m.gravity.z(), -9.80665);
  EXPECT_EQ(m.springs.size(), 1u);
  EXPECT_NEAR(m.bodies[*m.findBody("blade 1")].inertia.mass, 17536.614 / 1.04536, 1e-3);
  EXPECT_THAT(error({}, "missing.dat"), HasSubstr("missing.dat: cannot open file"));
}

}  // namespace
}  // namespace whirl

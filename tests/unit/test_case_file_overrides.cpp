// `--set key=value` overrides of a case: parsing, each kind of path (top-level scalar, body by
// name, nested map, DOF settings, inputs, list index, flow values), and the errors they report.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_file_test_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using testing::inputErrorOf;
using testing::lineOf;
using testing::smallTurbineCase;
using testing::TempCaseDir;

TEST(CaseOverrides, ParseSplitsAtTheFirstEquals) {
  const CaseOverride o = parseOverride(" bodies.top mass.mass = 2.5e5 ");
  EXPECT_EQ(o.key, "bodies.top mass.mass");
  EXPECT_EQ(o.value, "2.5e5");
  EXPECT_EQ(parseOverride("name=a=b").value, "a=b");
  for (const char* bad : {"gravity", "=1", "gravity=", "bodies..mass=1", "bodies.tower.=1"})
    EXPECT_THAT(inputErrorOf([&] { parseOverride(bad); }), HasSubstr(std::string("--set ") + bad)) << bad;
}

TEST(CaseOverrides, GravityZeroScalarOrVector) {
  TempCaseDir tmp;
  const std::string path = tmp.write("t.yaml", smallTurbineCase());
  EXPECT_TRUE(readCase(path, {parseOverride("gravity=0")}).gravity.isZero(0));
  EXPECT_TRUE(readCase(path, {parseOverride("gravity=[0, 1, -5]")}).gravity.isApprox(Vec3(0, 1, -5)));
  // Also when the case gives no gravity (the key is added, then read like any other).
  const std::string none = tmp.write("n.yaml", testing::replaced(smallTurbineCase(), "gravity: 9.81\n", ""));
  EXPECT_TRUE(readCase(none).gravity.isApprox(Vec3(0, 0, -9.80665)));
  EXPECT_TRUE(readCase(none, {parseOverride("gravity=0")}).gravity.isZero(0));
}

TEST(CaseOverrides, BodyMassNestedUniformDofAndInput) {
  TempCaseDir tmp;
  const std::string path = tmp.write("t.yaml", smallTurbineCase());
  const Model base = readCase(path);
  const Model m = readCase(path,
                           {parseOverride("bodies.nacelle.mass=2.5e5"), parseOverride("bodies.tower.uniform.EIy=3e11"),
                            parseOverride("dofs.azimuth.frozen=true"), parseOverride("inputs.thrust.value=8e5")});
  EXPECT_DOUBLE_EQ(m.bodies[*m.findBody("nacelle")].inertia.mass, 2.5e5);
  // EIy is the stiffness of deflection along y (BeamProperties): tower FA 1 bends along z, so it
  // keeps its stiffness; turned to y by a second override, it takes the new EIy.
  const int t = *m.findBody("tower");
  EXPECT_NEAR(m.bodies[t].elastic.K(0, 0) / base.bodies[t].elastic.K(0, 0), 1.0, 1e-12);
  const Model y = readCase(path, {parseOverride("bodies.tower.shapes.tower FA 1.direction=y"),
                                  parseOverride("bodies.tower.uniform.EIy=3e11")});
  EXPECT_NEAR(y.bodies[t].elastic.K(0, 0) / base.bodies[t].elastic.K(0, 0), 3.0, 1e-12);
  EXPECT_TRUE(m.dofs[*m.findDof("azimuth")].frozen);
  EXPECT_TRUE(m.dofs[*m.findDof("azimuth")].rotating);  // the other settings stay
  EXPECT_DOUBLE_EQ(m.inputs[0].value, 8e5);
}

TEST(CaseOverrides, DofWithoutSettingsAndListIndex) {
  TempCaseDir tmp;
  const std::string path = tmp.write("t.yaml", smallTurbineCase());
  const Model m = readCase(path,
                           {parseOverride("dofs.tower FA 1.value=0.2"), parseOverride("loads.0.force=[2, 0, 0]")});
  EXPECT_DOUBLE_EQ(m.dofs[*m.findDof("tower FA 1")].value, 0.2);
  EXPECT_TRUE(m.point_loads[0].force.isApprox(Vec3(2, 0, 0)));
  const std::string nodofs = tmp.write("n.yaml", smallTurbineCase().substr(0, smallTurbineCase().find("dofs:")));
  const Model f = readCase(nodofs, {parseOverride("dofs.azimuth.frozen=true")});
  EXPECT_TRUE(f.dofs[*f.findDof("azimuth")].frozen);
}

TEST(CaseOverrides, PathThatDoesNotExistIsAnError) {
  TempCaseDir tmp;
  const std::string& text = smallTurbineCase();
  const std::string path = tmp.write("t.yaml", text);
  // A list entry that does not exist: reported at the list, with the names there are.
  std::string msg = inputErrorOf([&] { readCase(path, {parseOverride("bodies.towr.mass=1")}); });
  EXPECT_THAT(msg, HasSubstr("t.yaml:" + std::to_string(lineOf(text, "  - name: tower")) +
                             ": bodies: no entry named 'towr'"));
  EXPECT_THAT(msg, HasSubstr("tower, nacelle, rotor"));
  EXPECT_THAT(msg, HasSubstr("--set bodies.towr.mass=1"));
  // A misspelt key is added, then refused by the reader like a misspelt key in the file.
  msg = inputErrorOf([&] { readCase(path, {parseOverride("gravty=0")}); });
  EXPECT_THAT(msg, HasSubstr("t.yaml:1: gravty: unknown key 'gravty' (allowed: name, description, gravity"));
  EXPECT_THAT(msg, HasSubstr("--set gravty=0"));
  msg = inputErrorOf([&] { readCase(path, {parseOverride("bodies.nacelle.mas=1")}); });
  EXPECT_THAT(msg, HasSubstr("bodies.nacelle.mas: unknown key 'mas'"));
  msg = inputErrorOf([&] { readCase(path, {parseOverride("dofs.azimth.frozen=true")}); });
  EXPECT_THAT(msg, HasSubstr("no DOF named 'azimth'"));
  msg = inputErrorOf([&] { readCase(path, {parseOverride("gravity.z=1")}); });
  EXPECT_THAT(msg, HasSubstr("t.yaml:2: gravity: 'gravity' is a single value"));
}

TEST(CaseOverrides, ValueThatDoesNotParseIsAnError) {
  TempCaseDir tmp;
  const std::string& text = smallTurbineCase();
  const std::string path = tmp.write("t.yaml", text);
  std::string msg = inputErrorOf([&] { readCase(path, {parseOverride("bodies.nacelle.mass=heavy")}); });
  EXPECT_THAT(
      msg,
      HasSubstr("t.yaml:" + std::to_string(lineOf(text, "mass: 2.4e5")) +
                ": bodies.nacelle.mass: expected a number, got 'heavy' (value from --set bodies.nacelle.mass=heavy)"));
  msg = inputErrorOf([&] { readCase(path, {parseOverride("dofs.azimuth.frozen=yes please")}); });
  EXPECT_THAT(msg, HasSubstr("dofs.azimuth.frozen: expected true or false"));
  msg = inputErrorOf([&] { readCase(path, {parseOverride("gravity=[0, 0")}); });
  EXPECT_THAT(msg, HasSubstr("t.yaml: gravity: --set gravity=[0, 0: the value is not valid YAML"));
  msg = inputErrorOf([&] { readCase(path, {parseOverride("bodies.tower.uniform={m: 1}")}); });
  EXPECT_THAT(msg, HasSubstr("t.yaml:" + std::to_string(lineOf(text, "uniform:")) +
                             ": bodies.tower.uniform: missing key 'EIy'"));
}

}  // namespace
}  // namespace whirl

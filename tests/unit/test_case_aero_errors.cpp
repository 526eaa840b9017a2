// Bad `wind:` and `aero:` input in a case file: one InputError line "file:line: key: reason" each —
// unknown keys, missing or malformed airfoil files, stations off the blade or out of order, chords
// that are not positive, airfoil numbers that name no file, the pitch DOF, the blade frame, and the
// blocks that need each other.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_file_test_util.hpp"
#include "tests/unit/aero_case_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using testing::inputErrorOf;
using testing::replaced;

class CaseAeroErrors : public ::testing::Test {
 protected:
  CaseAeroErrors() {
    test::AeroRotorOptions o;
    o.elements = 4;  // stations 0, 13.33…, 26.66…, 40
    base = test::aeroRotorCase(o);
    tmp.write("thin.dat", test::thinAirfoilFile(0.01));
  }
  // The base case with `from` replaced by `to`: the error names the file, the line where `at` (default
  // `to`) starts in the edited case, and contains `what`.
  void expect(const std::string& from, const std::string& to, const std::string& what, const std::string& at = "") {
    const std::string text = replaced(base, from, to);
    const std::string path = tmp.write("bad.yaml", text);
    const std::string msg = inputErrorOf([&] { readCase(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":" + std::to_string(testing::lineOf(text, at.empty() ? to : at)) + ": ")) << msg;
    EXPECT_THAT(msg, HasSubstr(what));
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line";
  }
  std::string base;
  testing::TempCaseDir tmp;
};

TEST_F(CaseAeroErrors, BaseCaseIsValid) {
  const Model m = readCase(tmp.write("ok.yaml", base));
  EXPECT_EQ(m.aero.nstations(), 12);
}

TEST_F(CaseAeroErrors, UnknownKeys) {
  expect("  induction: true", "  inductoin: true",
         "aero.inductoin: unknown key 'inductoin' (allowed: hub, air_density");
  expect("  speed: 8", "  sped: 8", "wind.sped: unknown key 'sped' (allowed: speed, reference_height");
  expect("      pitch: blade 2 pitch", "      pich: blade 2 pitch",
         "bodies.blade 2.aero.pich: unknown key 'pich' (allowed: pitch, stations)");
  expect("        chord: [", "        chrod: [", "bodies.blade 1.aero.stations.chrod: unknown key 'chrod'");
}

TEST_F(CaseAeroErrors, AirfoilFiles) {
  expect("  airfoils: [thin.dat]", "  airfoils: [nope.dat]", "aero.airfoils[0]: cannot open the airfoil file");
  expect("  airfoils: [thin.dat]", "  airfoils: []", "aero.airfoils: at least one airfoil file");
  expect("  airfoils: [thin.dat]", "  airfoils: [../thin.dat]", "outside the case folder");
  // A malformed file: its own file and line (the airfoil reader's message).
  std::string bad = test::thinAirfoilFile(0.01);
  bad = replaced(bad, "          3   NumAlf", "          4   NumAlf");
  const std::string path = tmp.write("bad.dat", bad);
  tmp.write("bad.yaml", replaced(base, "[thin.dat]", "[bad.dat]"));
  const std::string msg = inputErrorOf([&] { readCase((tmp.dir / "bad.yaml").string()); });
  EXPECT_THAT(msg, HasSubstr(path + ":"));
  EXPECT_THAT(msg, HasSubstr("NumAlf"));
  EXPECT_EQ(msg.find('\n'), std::string::npos);
  // A table that does not cover −180° to 180°: refused by the polar, naming the file and its table.
  std::string narrow = replaced(test::thinAirfoilFile(0.01), "    180.0", "     90.0");
  const std::string narrow_path = tmp.write("narrow.dat", narrow);
  tmp.write("narrow.yaml", replaced(base, "[thin.dat]", "[narrow.dat]"));
  EXPECT_THAT(inputErrorOf([&] { readCase((tmp.dir / "narrow.yaml").string()); }), HasSubstr(narrow_path + ":"));
}

TEST_F(CaseAeroErrors, Stations) {
  expect("x: [0, 13.333333333333334, 26.666666666666668, 40]", "x: [0, 13.333333333333334, 26.666666666666668, 41]",
         "bodies.blade 1.aero.stations.x: station 4 at 41 m lies outside the blade (0 to 40 m)");
  expect("x: [0, 13.333333333333334, 26.666666666666668, 40]", "x: [0, 26.666666666666668, 13.333333333333334, 40]",
         "bodies.blade 1.aero.stations.x: stations must increase");
  expect("chord: [3.5,", "chord: [-3.5,", "bodies.blade 1.aero.stations.chord: must be positive, value 1 is -3.5");
  expect("airfoil: [1, 1, 1, 1]", "airfoil: [1, 2, 1, 1]",
         "bodies.blade 1.aero.stations.airfoil: value 2 is 2, not an airfoil of aero.airfoils (1 to 1)");
  expect("airfoil: [1, 1, 1, 1]", "airfoil: [1, 1.5, 1, 1]", "value 2 is 1.5, not an airfoil");
  expect("        airfoil: [1, 1, 1, 1]\n", "", "bodies.blade 1.aero.stations: missing column 'airfoil'",
         "        x: [");
  expect("x: [0, 13.333333333333334, 26.666666666666668, 40]", "x: [0, 40]", "has 4 values, x has 2",
         "        chord: [");
}

TEST_F(CaseAeroErrors, PitchAndFrame) {
  expect("      pitch: blade 1 pitch", "      pitch: azimuth",
         "bodies.blade 1.aero.pitch: DOF 'azimuth' is not the revolute joint of body 'blade 1'");
  expect("{type: revolute, axis: [-1, 0, 0], dof: blade 1 pitch}",
         "{type: revolute, axis: [1, 0, 0], dof: blade 1 pitch}",
         "bodies.blade 1.aero.pitch: the pitch joint must turn the blade about its −x axis",
         "      pitch: blade 1 pitch");
  // Blade 1 turned 180° about its span axis: y upwind, z along the rotation.
  const std::size_t at = base.find("    rotation: [");
  expect(base.substr(at, base.find('\n', at) - at), "    rotation: [[0, -1, 0], [0, 0, -1], [1, 0, 0]]",
         "bodies.blade 1.aero: body 'blade 1' is not in AeroDyn's blade frame", "      pitch: blade 1 pitch");
}

TEST_F(CaseAeroErrors, BlocksThatNeedEachOther) {
  const std::string wind = base.substr(base.find("wind:\n"), base.find("aero:\n  hub") - base.find("wind:\n"));
  expect(wind, "", "aero: aerodynamics need a top-level wind: block", "  hub: hub");
  const std::string rotor = base.substr(base.find("aero:\n  hub"));
  expect(rotor, "", "bodies.blade 1.aero: blade elements need the top-level aero: block", "      pitch: blade 1 pitch");
  expect("  speed: 8", "  speed: -8", "wind.speed: must not be negative");
  expect("  speed: 8", "  speed: 1.0e6", "wind.speed: 1e+06 m/s is above the limit of 100 m/s");
  expect("  reference_height: 90", "  reference_height: 0\n  shear_exponent: 0.2",
         "wind.shear_exponent: a shear exponent needs a positive reference_height", "  shear_exponent");
  expect("  induction: true", "  air_density: 0\n  induction: true", "aero.air_density: must be positive");
  expect("  hub: hub", "  hub: nacelle", "aero.hub: no body named 'nacelle'");
  expect("inputs:\n", "inputs:\n  - {name: wind speed}\n", "wind: the case already has an input named 'wind speed'",
         "  speed: 8");
}

TEST_F(CaseAeroErrors, Generator) {
  base += R"(generator:
  torque_input: generator torque
  speed_output: GenSpeed
  VS_RtGnSp: 14
  VS_RtTq: 1.35e6
  VS_Rgn2K: 3400
  VS_SlPc: 10
)";
  base = replaced(base, "inputs:\n", "inputs:\n  - {name: generator torque}\n");
  base = replaced(base, "dofs:\n  azimuth",
                  "loads:\n  - {type: point, body: hub, moment: [-1, 0, 0], input: generator torque}\n"
                  "outputs:\n  - {name: GenSpeed, type: dof, dof: azimuth, order: rate}\ndofs:\n  azimuth");
  const Model m = readCase(tmp.write("gen.yaml", base));
  ASSERT_TRUE(m.generator.active());
  EXPECT_TRUE(m.findOutput("GenTq") && m.findOutput("GenPwr"));
  expect("  VS_SlPc: 10", "  VS_SlPC: 10",
         "generator.VS_SlPC: unknown key 'VS_SlPC' (allowed: torque_input, speed_output");
  expect("  VS_RtGnSp: 14", "  VS_RtGnSp: 0", "generator.VS_RtGnSp: must be positive");
  expect("  VS_Rgn2K: 3400", "  VS_Rgn2K: -1", "generator.VS_Rgn2K: must not be negative");
  expect("  VS_SlPc: 10", "  VS_SlPc: 10\n  GenEff: 140", "generator.GenEff: must be in (0, 100] %", "  GenEff");
  expect("  speed_output: GenSpeed", "  speed_output: RtAeroPwr",
         "generator.speed_output: output 'RtAeroPwr' must be a dof output of order rate");
  expect("  speed_output: GenSpeed", "  speed_output: speed", "generator.speed_output: no output named 'speed'");
  expect("  torque_input: generator torque", "  torque_input: collective pitch",
         "generator.torque_input: no point load names input 'collective pitch'");
  expect("  torque_input: generator torque", "  torque_input: torque",
         "generator.torque_input: no input named 'torque'");
}

}  // namespace
}  // namespace whirl

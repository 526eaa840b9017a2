// whirl's `.lin` files read as the tools of the field read OpenFAST's (issue 41): a reader written to
// their rules (tests/support/lin_rules_reader.hpp) gets the matrices in memory back, in OpenFAST's
// input order and output units; the header, table and description lines are OpenFAST's own, compared
// with OpenFAST's files for the same DOFs, inputs and outputs (copies in tests/data/openfast-lin/ and
// tests/data/openfast/decks/lin/, sources in tests/data/openfast/README.md).
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "openfast_test_util.hpp"
#include "src/writers/state_space_files.hpp"
#include "state_space_test_util.hpp"
#include "tests/support/lin_rules_reader.hpp"

namespace whirl {
namespace {

constexpr double kRpm = 30 / std::numbers::pi, kDeg = 180 / std::numbers::pi;

std::vector<StateSpaceModel> azimuthModels(const std::vector<std::string>& overrides, double rpm, int azimuths) {
  const Model m = testing::nrel5mw(overrides);
  OperatingCondition at;
  at.rotor_speed = rpm / kRpm;
  ExportOptions opt;
  opt.azimuths = azimuths;
  return exportOperatingPoint(m, at, opt).azimuths;
}

std::string fileText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What each whirl channel is in OpenFAST's files: the description and the factor from whirl's SI value
// to the file's. Texts and units as OpenFAST writes them in tests/data/openfast/decks/lin/Standstill.1.lin
// (ED inputs and outputs, AD RtSpeed) and tests/data/openfast-lin/ua4-dbemt3/states_inputs.txt (IfW);
// NcIMURAys as named in ElastoDyn's output list (issue 41 quotes it), no reference file has it.
struct Expected {
  const char* name;
  const char* description;
  double scale;
};
const Expected kInputs[] = {
    {"blade 1 pitch", "ED Blade 1 pitch command, rad", 1},
    {"blade 2 pitch", "ED Blade 2 pitch command, rad", 1},
    {"blade 3 pitch", "ED Blade 3 pitch command, rad", 1},
    {"generator torque", "ED Generator torque, Nm", 1},
    {"collective pitch", "ED Extended input: collective blade-pitch command, rad", 1},
};
const Expected kOutputs[] = {
    {"GenSpeed", "ED GenSpeed, (rpm)", kRpm},       {"RotSpeed", "ED RotSpeed, (rpm)", kRpm},
    {"NacYaw", "ED NacYaw, (deg)", kDeg},           {"TTDspFA", "ED TTDspFA, (m)", 1},
    {"YawBrTAxp", "ED YawBrTAxp, (m/s^2)", 1},      {"BldPitch1", "ED BldPitch1, (deg)", kDeg},
    {"BldPitch3", "ED BldPitch3, (deg)", kDeg},     {"TwrBsMyt", "ED TwrBsMyt, (kN-m)", 1e-3},
    {"NcIMURAys", "ED NcIMURAys, (deg/s^2)", kDeg},
};

int indexOf(const std::vector<StateSpaceVariable>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}

int rowOf(const std::vector<test::RulesRow>& rows, const std::string& description) {
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].description == description) return static_cast<int>(i);
  return -1;
}

void expectNearRow(const Eigen::RowVectorXd& file, const Eigen::RowVectorXd& expected, const std::string& what) {
  ASSERT_EQ(file.size(), expected.size()) << what;
  // The file prints 17 significant digits: the scaled value back to round-off.
  for (Eigen::Index c = 0; c < file.size(); ++c)
    EXPECT_NEAR(file(c), expected(c), 1e-15 * std::max(1.0, std::abs(expected(c)))) << what << " column " << c + 1;
}

// (a) Every file of a 3-azimuth export at 9 rpm, read by the rules: header, A exactly, B, C, D per
// channel with OpenFAST's order and units. Fails when a matrix block has an empty line (the rules
// reader refuses it), when the wind or an ElastoDyn input moves, or a unit factor is missing.
TEST(LinOpenFastRules, StructuralFilesReadBackInOpenFastsOrderAndUnits) {
  const auto models = azimuthModels({}, 9, 3);
  ASSERT_EQ(models.size(), 3u);
  for (const StateSpaceModel& m : models) {
    const test::RulesLin f = test::readLinByOpenFastRules(linFileText(m, "NREL 5MW"));
    EXPECT_EQ(f.header.at("Rotor Speed"), m.rotor_speed);
    EXPECT_EQ(f.header.at("Azimuth"), m.azimuth);
    EXPECT_EQ(f.header.at("Wind Speed"), 0.0);  // OpenFAST writes 0 without InflowWind
    ASSERT_EQ(f.matrices.count("A"), 1u);
    EXPECT_EQ(f.matrices.at("A"), m.A);
    ASSERT_EQ(f.u.size(), m.u.size());
    ASSERT_EQ(f.y.size(), m.y.size());
    const Eigen::MatrixXd &B = f.matrices.at("B"), &C = f.matrices.at("C"), &D = f.matrices.at("D");
    // ElastoDyn's inputs first, in ElastoDyn's order (pitch commands, generator torque, collective pitch).
    for (size_t k = 0; k < std::size(kInputs); ++k) {
      EXPECT_EQ(f.u[k].description, kInputs[k].description);
      const int j = indexOf(m.u, kInputs[k].name);
      ASSERT_GE(j, 0) << kInputs[k].name;
      EXPECT_EQ(B.col(static_cast<Eigen::Index>(k)), m.B.col(j)) << kInputs[k].name;
      EXPECT_EQ(f.u[k].rotating, m.u[j].blade >= 0) << kInputs[k].name;
    }
    for (const Expected& e : kOutputs) {
      const int i = indexOf(m.y, e.name), r = rowOf(f.y, e.description);
      ASSERT_GE(i, 0) << e.name;
      ASSERT_GE(r, 0) << e.description;
      EXPECT_NEAR(f.y[r].op, e.scale * m.y[i].op, 1e-15 * std::max(1.0, std::abs(e.scale * m.y[i].op))) << e.name;
      expectNearRow(C.row(r), e.scale * m.C.row(i), e.name);
      // D's columns in the file's input order.
      for (size_t k = 0; k < std::size(kInputs); ++k)
        EXPECT_NEAR(D(r, static_cast<Eigen::Index>(k)), e.scale * m.D(i, indexOf(m.u, kInputs[k].name)),
                    1e-15 * std::max(1.0, std::abs(e.scale * m.D(i, indexOf(m.u, kInputs[k].name)))))
            << e.name;
    }
  }
}

// With the generator DOF off the rotor still turns: the headers give its true speed and azimuths (they
// said 0 and 0 in every file, and MBC3 came out up to 11 % wrong, issue 41).
TEST(LinOpenFastRules, HeaderKeepsTheRotorSpeedWithTheGeneratorDofOff) {
  const auto models = azimuthModels({"GenDOF=False"}, 9, 3);
  ASSERT_EQ(models.size(), 3u);
  std::set<double> azimuths;
  for (const StateSpaceModel& m : models) {
    const test::RulesLin f = test::readLinByOpenFastRules(linFileText(m, "NREL 5MW"));
    EXPECT_NEAR(f.header.at("Rotor Speed"), 9 / kRpm, 1e-15);
    azimuths.insert(f.header.at("Azimuth"));
  }
  EXPECT_EQ(azimuths.size(), 3u);
  EXPECT_NEAR(*azimuths.rbegin() - *azimuths.begin(), 4 * std::numbers::pi / 3, 1e-12);
}

std::set<std::string> descriptions(const std::vector<test::RulesRow>& rows) {
  std::set<std::string> s;
  for (const auto& r : rows) s.insert(r.description);
  return s;
}

// (b) whirl's header, table and description lines against OpenFAST's own files for the same DOFs,
// inputs and outputs: states from OpenFAST v3.3 at 9 rpm (rotating-9rpm/Main.1.lin: generator and
// blade DOFs) and v2.5 at 3 m/s (ws03/ws03.0.1.lin: tower "bending mode", yaw, drivetrain), inputs and
// outputs from Standstill.1.lin, the rotating-frame flags of the same rows.
TEST(LinOpenFastRules, DescriptionsAreOpenFastsForTheSameDofsInputsAndOutputs) {
  const auto dir = test::sourceDir() / "tests" / "data";
  const test::RulesLin rot = test::readLinByOpenFastRules(fileText(dir / "openfast-lin/rotating-9rpm/Main.1.lin"));
  const test::RulesLin ws03 = test::readLinByOpenFastRules(fileText(dir / "openfast-lin/ws03/ws03.0.1.lin"));
  const test::RulesLin still = test::readLinByOpenFastRules(fileText(dir / "openfast/decks/lin/Standstill.1.lin"));
  const StateSpaceModel m = azimuthModels({}, 9, 3).front();
  const std::string text = linFileText(m, "NREL 5MW");
  const test::RulesLin own = test::readLinByOpenFastRules(text);

  std::map<std::string, bool> openfast;  // description → rotating frame
  for (const auto* f : {&rot, &ws03, &still})
    for (const auto* rows : {&f->x, &f->xdot, &f->u, &f->y})
      for (const auto& r : *rows) openfast[r.description] = r.rotating;
  int compared = 0;
  for (const auto* rows : {&own.x, &own.xdot, &own.u, &own.y})
    for (const auto& r : *rows) {
      if (r.description.rfind("whirl ", 0) == 0) continue;  // no OpenFAST counterpart
      // None in the files (ElastoDyn's OutListParameters names and units: NcIMURAys (deg/s^2), YawBrTVxp (m/s),
      // NcIMURVys (deg/s)).
      if (r.description == "ED NcIMURAys, (deg/s^2)" || r.description == "ED YawBrTVxp, (m/s)" ||
          r.description == "ED NcIMURVys, (deg/s)" || r.description.rfind("ED RootM", 0) == 0)
        continue;
      const auto it = openfast.find(r.description);
      ASSERT_NE(it, openfast.end()) << "not OpenFAST's text: " << r.description;
      EXPECT_EQ(r.rotating, it->second) << r.description;
      ++compared;
    }
  EXPECT_GE(compared, 2 * 16 + 5 + 8);  // every ElastoDyn state and rate, the 5 inputs, the outputs above
  // Tower DOFs are "bending mode", blade DOFs "bending-mode", as ElastoDyn writes them.
  EXPECT_TRUE(descriptions(own.x).count("ED 1st tower fore-aft bending mode DOF (internal DOF index = DOF_TFA1), m"));
  EXPECT_TRUE(
      descriptions(own.x).count("ED 1st flapwise bending-mode DOF of blade 1 (internal DOF index = DOF_BF(1,1)), m"));
  // The header's labels in OpenFAST's order, the module line, no time stamp (two runs, same bytes).
  auto labels = [](const test::RulesLin& f) {
    std::vector<std::string> l;
    bool on = false;
    for (const auto& line : f.lines) {
      if (line == "Simulation information:") on = true;
      else if (on && line.empty()) break;
      else if (on) l.push_back(line.substr(0, line.find_first_of(":?") + 1));  // "… in this file?    No"
    }
    return l;
  };
  auto trim = [](std::vector<std::string> v) {
    for (auto& s : v) s = s.substr(s.find_first_not_of(' '));
    return v;
  };
  EXPECT_EQ(trim(labels(own)), trim(labels(rot)));
  EXPECT_EQ(own.lines[2].rfind(" linked with  ElastoDyn", 0), 0u) << own.lines[2];
  EXPECT_EQ(own.lines[1].find(" on "), std::string::npos) << "a time stamp: " << own.lines[1];
}

}  // namespace
}  // namespace whirl

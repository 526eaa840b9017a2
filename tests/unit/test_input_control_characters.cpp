// Names and titles with control characters are refused where they are read, with one line
// "file:line: key: reason": YAML cases (every name, units, --set values, the file-name fallback),
// OpenFAST titles, .lin descriptions, tracking overrides and CSV tables (compare, study). A newline
// in a name once ended a quoted string in campbell.gp and ran the next line as a Gnuplot command.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_file_test_util.hpp"
#include "modal/tracking.hpp"
#include "modal/tracking_overrides.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/io/text/csv.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using testing::inputErrorOf;
using testing::lineOf;
using testing::replaced;
using testing::smallTurbineCase;

constexpr const char* kReason = "contains a control character";

/// One line, names file:line and key, says why.
void expectRefused(const std::string& msg, const std::string& file, int line, const std::string& key) {
  EXPECT_THAT(msg, HasSubstr(file + ":" + std::to_string(line) + ": ")) << msg;
  EXPECT_THAT(msg, HasSubstr(key)) << msg;
  EXPECT_THAT(msg, HasSubstr(kReason)) << msg;
  for (char c : msg) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20) << "one printable line: " << msg;
}

class YamlControlCharacters : public ::testing::Test {
 protected:
  /// The small turbine with `from` replaced by `to` (YAML escapes in double quotes): refused at the
  /// line of `to` with `key` in the message.
  void expect(const std::string& from, const std::string& to, const std::string& key) {
    const std::string text = replaced(smallTurbineCase(), from, to);
    const std::string path = tmp.write("bad.yaml", text);
    expectRefused(inputErrorOf([&] { readCase(path); }), path, lineOf(text, to), key);
  }
  testing::TempCaseDir tmp;
};

TEST_F(YamlControlCharacters, EveryKindOfNameIsRefused) {
  expect("name: small turbine", "name: \"a\\n!touch whirl_pwned\\n#\"", "name: ");  // the case (plot title)
  expect("  - name: nacelle", "  - name: \"nac\\nelle\"", ".name: ");               // a body
  expect("dof: azimuth}", "dof: \"azi\\tmuth\"}", "joint.dof: ");                   // a DOF (tab too)
  expect("{name: tower FA 1,", "{name: \"tower\\rFA 1\",", ".name: ");              // a shape = DOF
  expect("{name: thrust, value", "{name: \"thr\\eust\", value", ".name: ");         // an input (escape)
  expect("{name: top, x: 80}", "{name: \"t\\x7fop\", x: 80}", ".name: ");           // a point (delete)
}

TEST_F(YamlControlCharacters, OutputNamesAndUnitsAreRefused) {
  const std::string base = smallTurbineCase() +
                           "outputs:\n  - {name: azimuth angle, type: dof, dof: azimuth, unit: rad}\n";
  for (const auto& [from, to, key] :
       {std::tuple<std::string, std::string, std::string>{"name: azimuth angle", "name: \"azimuth\\nangle\"",
                                                          ".name: "},
        {"unit: rad", "unit: \"rad\\n\"", ".unit: "}}) {
    const std::string text = replaced(base, from, to);
    const std::string path = tmp.write("bad.yaml", text);
    expectRefused(inputErrorOf([&] { readCase(path); }), path, lineOf(text, to), key);
  }
}

TEST_F(YamlControlCharacters, SetOverrideIsRefused) {
  const std::string path = tmp.write("ok.yaml", smallTurbineCase());
  const std::string msg = inputErrorOf([&] { readCase(path, {parseOverride("name=a\n!touch whirl_pwned")}); });
  expectRefused(msg, path, lineOf(smallTurbineCase(), "name: small turbine"), "name: ");
}

TEST_F(YamlControlCharacters, FileNameFallbackIsRefused) {
  // Without `name:` the case is named after its file, which then becomes the plot title.
  const std::string text = replaced(smallTurbineCase(), "name: small turbine\n", "");
  const std::string path = tmp.write("bad\nname.yaml", text);
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }), HasSubstr(kReason));
}

TEST_F(YamlControlCharacters, MultiLineDescriptionStaysAllowed) {
  // `description:` is free text, never written anywhere: a block scalar keeps working.
  const std::string text = replaced(smallTurbineCase(), "gravity: 9.81",
                                    "description: |\n  two\n  lines\ngravity: 9.81");
  EXPECT_EQ(readCase(tmp.write("ok.yaml", text)).ndof(), 2);
}

/// The NREL 5MW deck in a scratch folder.
class OpenFastControlCharacters : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* f : {kFst, kEd, kTower, kBlade, kServo}) dir.copy(test::nrel5mwDir() / f);
  }
  void edit(const char* name, const std::string& from, const std::string& to) {
    dir.write(name, test::replaceOnce(test::readText(dir.path() / name), from, to));
  }
  std::string fst() const { return (dir.path() / kFst).string(); }
  static constexpr const char* kFst = "Main_Onshore.fst";
  static constexpr const char* kEd = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
  static constexpr const char* kTower = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
  static constexpr const char* kBlade = "NRELOffshrBsline5MW_Blade.dat";
  static constexpr const char* kServo = "NRELOffshrBsline5MW_Onshore_ServoDyn.dat";
  test::ScratchDir dir;
};

TEST_F(OpenFastControlCharacters, ElastoDynTitleWithControlCharacterIsRefused) {
  // The ElastoDyn title is the model's name and the Campbell plot's title.
  const std::string ed = test::readText(dir.path() / kEd);
  const std::string title = ed.substr(ed.find('\n') + 1, ed.find('\n', ed.find('\n') + 1) - ed.find('\n') - 1);
  edit(kEd, title, title.substr(0, 10) + "\x1b]0;pwned\x07" + title.substr(10));
  expectRefused(inputErrorOf([&] { readElastoDynModel(fst(), {}); }), (dir.path() / kEd).string(), 2, "title: ");
}

TEST_F(OpenFastControlCharacters, TabsInTheTitleAreSpacing) {
  const std::string ed = test::readText(dir.path() / kEd);
  const std::string title = ed.substr(ed.find('\n') + 1, ed.find('\n', ed.find('\n') + 1) - ed.find('\n') - 1);
  edit(kEd, title, "Tabbed\ttitle");
  EXPECT_EQ(readElastoDynModel(fst(), {}).name, "Tabbed title");
}

TEST(LinControlCharacters, DescriptionWithControlCharacterIsRefused) {
  test::ScratchDir dir;
  const auto src = test::sourceDir() / "tests/data/openfast-lin/ws03/ws03.0.1.lin";
  const std::string text = test::readText(src);
  const std::string key = "ED 1st tower fore-aft bending mode DOF";
  ASSERT_NE(text.find(key), std::string::npos);
  const auto path = dir.write("bad.lin", test::replaceOnce(text, key, "ED 1st\x1b[2J tower fore-aft bending mode DOF"));
  const int line = testing::lineOf(text, key);
  expectRefused(inputErrorOf([&] { readOpenFastLin(path.string()); }), path.string(), line, "description");
  // Tabs are spacing in the free-text column, as in the decks.
  const auto tabbed = dir.write("tab.lin", test::replaceOnce(text, key, "ED 1st\ttower fore-aft bending mode DOF"));
  const OpenFastLin lin = readOpenFastLin(tabbed.string());
  bool found = false;
  for (const auto& v : lin.x) found = found || v.description.find("ED 1st tower fore-aft") == 0;
  EXPECT_TRUE(found);
}

TEST(TrackingControlCharacters, RenameWithControlCharacterIsRefused) {
  CampbellPoint p;
  p.rpm = 1;
  p.coordinates = {"x"};
  Mode m;
  m.freq_hz = 1;
  m.name = "a";
  m.shape = Eigen::VectorXcd::Ones(1);
  m.participation = Eigen::VectorXd::Ones(1);
  p.modes = {m};
  std::vector<CampbellPoint> pts{p, p};
  auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 1u);
  const std::string msg = inputErrorOf(
      [&] { applyTrackingOverridesText("# fixes\nrename,a,b\x1b[31m\n", "fix.csv", pts, lines); });
  expectRefused(msg, "fix.csv", 2, "");
}

TEST(CsvControlCharacters, TableFieldWithControlCharacterIsRefused) {
  // Reference tables of `whirl compare` and parameter sets of `whirl study` are read by readTextCsv.
  test::ScratchDir tmp;
  const std::string path = tmp.write("ref.csv", "mode,freq_hz\ntower FA 1,0.32\ntower\x1b[2J SS 1,0.31\n").string();
  expectRefused(inputErrorOf([&] { readTextCsv(path); }), path, 3, "mode: ");
  const std::string head = tmp.write("head.csv", "mode,freq\tHz\na,1\n").string();
  expectRefused(inputErrorOf([&] { readTextCsv(head); }), head, 1, "");
}

}  // namespace
}  // namespace whirl

// Issue 14, items 4–6 at the command line: counts from files and options are bounded, silently wrong
// results are refused (a repeated .lin, an operating point outside the model's validity, negative
// rotor speeds), and every message names its source, as one "whirl: error:" line with exit 1.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

const std::string kLandbased = "cases/landbased_2dof/landbased_2dof.yaml";
const std::string kLin = "tests/data/openfast-lin/rotating-9rpm/Main.1.lin";

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void expectOneLineError(const test::Run& r, const std::string& what, const std::string& args) {
  EXPECT_EQ(r.code, 1) << args << "\n" << r.err;
  EXPECT_THAT(r.err, HasSubstr("whirl: error: ")) << args;
  EXPECT_THAT(r.err, HasSubstr(what)) << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
}

void expectError(const std::string& args, const std::string& what, const std::string& cwd = WHIRL_SOURCE_DIR) {
  expectOneLineError(test::whirl(args, cwd), what, args);
}

// --- item 4: bounds ---------------------------------------------------------------------------

TEST(CliInputBounds, RpmRangeWithTooManyPointsIsRefusedBeforeAnyAllocation) {
  // (1 − 0)/1e-10 = 1e10 points overflowed an int (undefined behaviour), then std::vector threw.
  expectError("campbell " + kLandbased + " --rpm 0:1e-10:1 --out /tmp/whirl_bounds_unused",
              "--rpm: more than 100000 points in '0:1e-10:1'");
}

TEST(CliInputBounds, LinHeaderClaimingHugeCountsIsRefusedWithFileAndLine) {
  const auto dir = test::freshDir("lin_huge");
  const std::string text = test::slurp(fs::path(WHIRL_SOURCE_DIR) / kLin);
  write(dir / "states.lin",
        replaced(text, "Number of continuous states: ", "Number of continuous states: 2000000000 "));
  expectError("lin states.lin", "states.lin:", dir.string());
  expectError("lin states.lin", "Number of continuous states: 2000000000 is above the limit of 100000", dir.string());
}

TEST(CliInputBounds, LinMatrixSizeBeyondIntIsAnErrorNamingFileAndLineNotStoi) {
  const auto dir = test::freshDir("lin_stoi");
  const std::string text = test::slurp(fs::path(WHIRL_SOURCE_DIR) / kLin);
  const auto at = text.find("\nA: ");
  ASSERT_NE(at, std::string::npos);
  const auto x = text.find(" x ", at);
  std::string bad = text;
  bad.replace(at + 4, x - at - 4, "123456789012");
  write(dir / "big.lin", bad);
  const auto r = test::whirl("lin big.lin", dir.string());
  expectOneLineError(r, "is out of the integer range", "lin big.lin");
  EXPECT_THAT(r.err, HasSubstr("big.lin:"));
  EXPECT_THAT(r.err, Not(HasSubstr("stoi")));
}

// --- item 5: silently wrong results ------------------------------------------------------------

TEST(CliInputBounds, SameLinFileTwiceIsRefused) {
  expectError("lin " + kLin + " " + kLin, "same operating point and azimuth as");
}

TEST(CliInputBounds, NegativeRotorSpeedIsRefusedByRpmAsByASchedule) {
  expectError("modes " + kLandbased + " --rpm -5", "--rpm: rotor speed must be finite and not negative");
  expectError("campbell " + kLandbased + " --rpm -5:5:5 --out /tmp/whirl_bounds_unused", "--rpm: negative rotor speed");
}

TEST(CliInputBounds, AbsurdGravityStopsAtAnInvalidOperatingPointUnlessAllowed) {
  // 100 × Earth's gravity, upwards: the 4-DOF turbine's tower "converges" to a top deflection of 1.5
  // times its length. (The NREL 5MW at such loads has no Newton solution that does not depend on the
  // last bits of the arithmetic, so it makes no test.)
  const std::string fst = "cases/flex_4dof/flex_4dof.yaml";
  const std::string args = "modes " + fst + " --set gravity=-1e3";
  const auto r = test::whirl(args);
  expectOneLineError(r, fst + ": operating point outside the model's range of validity: tower", args);
  EXPECT_THAT(r.err, HasSubstr("elastic deflection"));
  EXPECT_THAT(r.err, HasSubstr("--allow-invalid-point"));
  const auto ok = test::whirl(args + " --allow-invalid-point --format json");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_THAT(ok.err, HasSubstr("whirl: warning: " + fst + ": tower"));
  const auto j = nlohmann::json::parse(ok.out);
  EXPECT_EQ(j["validity"]["valid"], false) << ok.out.substr(0, 400);
  EXPECT_FALSE(j["validity"]["problems"].empty());
}

TEST(CliInputBounds, ValidPointsReportValidityInTheirMetadata) {
  const auto dir = test::freshDir("valid_point");
  const auto r = test::whirl("linearize " + kLandbased + " --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::slurp(dir / "linearization.json"));
  EXPECT_EQ(j["validity"]["valid"], true);
}

// --- item 6: messages with a source ------------------------------------------------------------

TEST(CliInputBounds, LinOnAMissingFileIsAWhirlErrorWithExit1) {
  expectError("lin no_such_file.lin", "no_such_file.lin: cannot open file");
}

TEST(CliInputBounds, LinNaNInTheStateMatrixNamesFileAndLine) {
  const auto dir = test::freshDir("lin_nan");
  std::string text = test::slurp(fs::path(WHIRL_SOURCE_DIR) / kLin);
  const auto at = text.find("\nA: ");
  ASSERT_NE(at, std::string::npos);
  const auto row = text.find('\n', at + 1) + 1;  // first row of A
  const auto first = text.find_first_not_of(' ', row);
  const auto end = text.find(' ', first);
  text.replace(first, end - first, "NaN");
  write(dir / "nan.lin", text);
  int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(row), '\n'));
  // One file is one azimuth of a turning rotor: `whirl lin` warns about that first (issue 41), then the
  // error is one line.
  const test::Run r = test::whirl("lin nan.lin", dir.string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("whirl: warning: nan.lin: only 1 azimuth"));
  EXPECT_THAT(r.err, HasSubstr("whirl: error: nan.lin:" + std::to_string(line) + ": A: value is not finite"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;
}

TEST(CliInputBounds, AFolderGivenAsScheduleSaysSo) {
  expectError("campbell " + kLandbased + " --schedule cases --out /tmp/whirl_bounds_unused",
              "cases: is a folder, not a CSV file");
}

TEST(CliInputBounds, CompareRefusesANaNTolerance) {
  expectError("compare cases/landbased_2dof/reference.csv cases/landbased_2dof/reference.csv --tol-rel nan",
              "--tol-rel: must be a finite number >= 0");
}

TEST(CliInputBounds, CaseFileEntriesStayInTheCaseFolderUnlessAllowed) {
  const auto root = test::freshDir("outside_files");
  fs::create_directories(root / "case");
  const std::string csv = "fraction,m,EIz,EIy\n0,5590.87,6.14343e11,6.14343e11\n1,2536.27,1.1582e11,1.1582e11\n";
  write(root / "outside.csv", csv);
  std::string text = test::slurp(fs::path(WHIRL_SOURCE_DIR) / kLandbased);
  const auto b = text.find("    properties:\n");
  const auto e = text.find("    integration:");
  ASSERT_TRUE(b != std::string::npos && e != std::string::npos);
  text.replace(b, e - b, "    properties: {file: ../outside.csv}\n");
  write(root / "case" / "c.yaml", text);
  const auto r = test::whirl("modes c.yaml", (root / "case").string());
  expectOneLineError(r, "c.yaml:17: bodies.tower.properties.file: the file is outside the case folder", "modes c.yaml");
  const auto ok = test::whirl("modes c.yaml --allow-outside-files", (root / "case").string());
  EXPECT_EQ(ok.code, 0) << ok.err;
  // An absolute path to a foreign file: refused by default, and with the option its content is only
  // quoted as a short excerpt.
  write(root / "case" / "abs.yaml", replaced(text, "../outside.csv", (root / "secret.txt").string()));
  write(root / "secret.txt", "fraction,m,EIz,EIy\n0," + std::string(200, 'S') + ",1,1\n1,1,1,1\n");
  expectError("modes abs.yaml", "the file is outside the case folder", (root / "case").string());
  const auto r2 = test::whirl("modes abs.yaml --allow-outside-files", (root / "case").string());
  EXPECT_EQ(r2.code, 1);
  EXPECT_THAT(r2.err, Not(HasSubstr(std::string(60, 'S')))) << r2.err;
}

TEST(CliInputBounds, SolverErrorsNameTheCaseFile) {
  const auto dir = test::freshDir("solver_error");
  write(dir / "drop.yaml",
        "name: drop\ngravity: 9.81\nbodies:\n  - name: box\n    type: rigid\n"
        "    joint: {type: prismatic, axis: [0, 0, 1], dof: z}\n    mass: 1\n    inertia: [1, 1, 1]\n");
  expectError("modes drop.yaml", "drop.yaml: operating point: a load acts along DOF 'z'", dir.string());
}

}  // namespace
}  // namespace whirl

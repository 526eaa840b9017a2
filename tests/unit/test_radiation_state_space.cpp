// HydroDyn's state-space radiation file (`<PotFile>.ss`, RdtnMod = 2) of the ITI barge deck
// (cases/iti_barge, a copy of OpenFAST's certification Test22): the values read and every malformed
// file as one line "file:line: reason".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/openfast/offshore/wamit_state_space.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

const std::string kSs = std::string(WHIRL_SOURCE_DIR) + "/cases/iti_barge/5MW_Baseline/HydroData/barge.ss";

io::HydroDynInput withPotFile(const std::filesystem::path& root) {
  io::HydroDynInput hd;
  hd.PotFile = root;
  return hd;
}

using test::errorOf;

std::vector<std::string> lines() {
  std::istringstream in(test::slurp(kSs));
  std::vector<std::string> out;
  for (std::string s; std::getline(in, s);) out.push_back(s);
  return out;
}

// The barge file with line `index` (0-based) replaced, written as <dir>/barge.ss.
std::string errorWithLine(const test::TempDir& dir, std::size_t index, const std::string& text,
                          bool cut_after = false) {
  std::vector<std::string> l = lines();
  l.at(index) = text;
  if (cut_after) l.resize(index + 1);
  std::string all;
  for (const std::string& s : l) all += s + "\n";
  dir.write("barge.ss", all);
  return errorOf([&] { io::readRadiationStateSpace(withPotFile(dir.path / "barge")); });
}

TEST(RadiationStateSpace, ReadsTheBargeFit) {
  const io::RadiationStateSpace r = io::readRadiationStateSpace(
      withPotFile(std::filesystem::path(kSs).replace_extension()));
  ASSERT_EQ(r.A.rows(), 30);
  EXPECT_EQ(r.per_dof, (std::array<int, 6>{6, 6, 2, 6, 6, 4}));  // line 4
  // Values as printed in barge.ss (A row 1, B row 1, C row 1).
  EXPECT_EQ(r.A(0, 0), -2.535337);
  EXPECT_EQ(r.A(0, 2), -1.401363);
  EXPECT_EQ(r.A(1, 0), 1.0);
  EXPECT_EQ(r.B(0, 0), 1.0);
  EXPECT_EQ(r.B.rows(), 30);
  EXPECT_EQ(r.B.cols(), 6);
  EXPECT_EQ(r.C(0, 0), -3.099435e6);
  EXPECT_EQ(r.C(0, 1), -1.411424e6);
  EXPECT_EQ(r.C.rows(), 6);
  EXPECT_EQ(r.C.cols(), 30);
}

TEST(RadiationStateSpace, MalformedFilesNameTheLine) {
  const test::TempDir dir;
  EXPECT_THAT(errorWithLine(dir, 1, "1 1 1 0 1 1    %Enabled DoFs"),
              HasSubstr("barge.ss:2: DOF 4 is not enabled (flag 0): HydroDyn's radiation states need all six DOFs"));
  EXPECT_THAT(errorWithLine(dir, 2, "31"), HasSubstr("barge.ss:4: the states per DOF sum to 30, not the 31 states"));
  EXPECT_THAT(errorWithLine(dir, 2, "1e9"), HasSubstr("barge.ss:3: the number of states 1e+09 is not a whole number"));
  EXPECT_THAT(errorWithLine(dir, 2, "2.5"), HasSubstr("barge.ss:3: the number of states 2.5 is not a whole number"));
  EXPECT_THAT(errorWithLine(dir, 4, "1 2 3"), HasSubstr("barge.ss:5: expected 30 numbers"));
  EXPECT_THAT(errorWithLine(dir, 40, "0 0 0 0 0 nan"), HasSubstr("barge.ss:41: 'nan' is not a finite number"));
  EXPECT_THAT(errorWithLine(dir, 40, "0 0 0 0 0 0 0"), HasSubstr("barge.ss:41: expected 6 numbers"));
  EXPECT_THAT(errorWithLine(dir, 40, "0 0 0 0 0 0", true), HasSubstr("barge.ss:42: the file ends early"));
  const std::string tail = test::slurp(kSs) + "1 2 3\n";
  dir.write("barge.ss", tail);
  EXPECT_THAT(errorOf([&] { io::readRadiationStateSpace(withPotFile(dir.path / "barge")); }),
              HasSubstr("barge.ss:71: text after the C matrix (30 states: A, B and C end on line 70)"));
  EXPECT_THAT(errorOf([&] { io::readRadiationStateSpace(withPotFile(dir.path / "none")); }),
              HasSubstr("WAMIT file not found"));
}

}  // namespace
}  // namespace whirl

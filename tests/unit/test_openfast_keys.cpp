// OpenFAST input files with a key given twice or a key their layout does not have are refused with
// file:line (issue 14, item 5): OpenFAST reads them by position, whirl by key, so either would make
// whirl silently read another turbine than OpenFAST does.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "src/io/elastodyn_blade.hpp"
#include "src/io/elastodyn_tower.hpp"
#include "src/io/openfast_turbine.hpp"
#include "tests/unit/nrel5mw_scratch.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::test::input_error_message;
using whirl::test::nrel5mw_dir;
using whirl::test::read_text;
using whirl::test::replace_once;
using whirl::test::ScratchDir;

using whirl::test::nrelEd;
using whirl::test::nrelWith;
using whirl::test::turbineError;
const char* kEd = whirl::test::kNrelEd;
const char* kTower = whirl::test::kNrelTower;
const char* kBlade = whirl::test::kNrelBlade;

// --- duplicate and unknown keys ---------------------------------------------------------------

TEST(OpenFastKeys, ElastoDynKeyGivenTwiceIsRefused) {
  // Whirl took the first NacMass (1 kg); OpenFAST, reading by position, a different line for each value.
  const std::string msg = turbineError(replace_once(
      nrelEd(), "     240000   NacMass", "          1   NacMass     - Nacelle mass (kg)\n     240000   NacMass"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":78: NacMass: given twice (first on line 77)"));
}

TEST(OpenFastKeys, ElastoDynUnknownKeyIsRefused) {
  const std::string msg = turbineError(replace_once(
      nrelEd(), "     240000   NacMass", "        1.5   NacMas2     - typo\n     240000   NacMass"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":77: NacMas2: not a key of an OpenFAST ElastoDyn file"));
}

TEST(OpenFastKeys, TowerAndBladeKeysGivenTwiceAreRefused) {
  ScratchDir dir;
  const std::string tower = read_text(nrel5mw_dir() / kTower);
  const auto t = dir.write("t.dat", replace_once(tower, "AdjTwMa", "AdjTwMa - a\n  1   AdjTwMa"));
  EXPECT_THAT(input_error_message([&] { whirl::io::read_elastodyn_tower(t); }),
              HasSubstr("AdjTwMa: given twice"));
  const std::string blade = read_text(nrel5mw_dir() / kBlade);
  const auto b = dir.write("b.dat", replace_once(blade, "AdjBlMs", "AdjBlMs - a\n  1   AdjEdStt"));
  EXPECT_THAT(input_error_message([&] { whirl::io::read_elastodyn_blade(b); }),
              HasSubstr("AdjEdStt: not a key of an OpenFAST ElastoDyn blade file"));
}

TEST(OpenFastKeys, FstRepeatsEdFileForASecondRotorButNothingElse) {
  ScratchDir dir;
  const std::string fst = read_text(nrel5mw_dir() / "Main_Onshore.fst");
  nrelWith(dir, nrelEd());
  const auto two = dir.write("two.fst", replace_once(fst, "          1   CompElast",
                                                     "          1   CompElast       - again\n          1   CompElast"));
  EXPECT_THAT(input_error_message([&] { whirl::io::read_openfast_turbine(two); }),
              HasSubstr("CompElast: given twice"));
  const std::string ed_line = "\"" + std::string(kEd) + "\"    EDFile - second rotor\n";
  const auto v5 = dir.write("v5.fst", fst + ed_line);
  EXPECT_NO_THROW(whirl::io::read_openfast_turbine(v5));
}

}  // namespace

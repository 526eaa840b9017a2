// OpenFAST input files with a key given twice or a key their layout does not have are refused with
// file:line (issue 14, item 5): OpenFAST reads them by position, whirl by key, so either would make
// whirl silently read another turbine than OpenFAST does.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "tests/unit/nrel5mw_scratch.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::test::inputErrorMessage;
using whirl::test::nrel5mwDir;
using whirl::test::readText;
using whirl::test::replaceOnce;
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
  const std::string msg = turbineError(
      replaceOnce(nrelEd(), "     240000   NacMass",
                  "          1   NacMass     - Nacelle mass (kg)\n     240000   NacMass"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":78: NacMass: given twice (first on line 77)"));
}

TEST(OpenFastKeys, ElastoDynUnknownKeyIsRefused) {
  const std::string msg = turbineError(
      replaceOnce(nrelEd(), "     240000   NacMass", "        1.5   NacMas2     - typo\n     240000   NacMass"));
  EXPECT_THAT(msg, HasSubstr(std::string(kEd) + ":77: NacMas2: not a key of an OpenFAST ElastoDyn file"));
}

TEST(OpenFastKeys, TowerAndBladeKeysGivenTwiceAreRefused) {
  ScratchDir dir;
  const std::string tower = readText(nrel5mwDir() / kTower);
  const auto t = dir.write("t.dat", replaceOnce(tower, "AdjTwMa", "AdjTwMa - a\n  1   AdjTwMa"));
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::readElastoDynTower(t); }), HasSubstr("AdjTwMa: given twice"));
  const std::string blade = readText(nrel5mwDir() / kBlade);
  const auto b = dir.write("b.dat", replaceOnce(blade, "AdjBlMs", "AdjBlMs - a\n  1   AdjEdStt"));
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::readElastoDynBlade(b); }),
              HasSubstr("AdjEdStt: not a key of an OpenFAST ElastoDyn blade file"));
}

TEST(OpenFastKeys, FstRepeatsEdFileForASecondRotorButNothingElse) {
  ScratchDir dir;
  const std::string fst = readText(nrel5mwDir() / "Main_Onshore.fst");
  nrelWith(dir, nrelEd());
  const auto two = dir.write("two.fst", replaceOnce(fst, "          1   CompElast",
                                                    "          1   CompElast       - again\n          1   CompElast"));
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::readOpenFastTurbine(two); }), HasSubstr("CompElast: given twice"));
  const std::string ed_line = "\"" + std::string(kEd) + "\"    EDFile - second rotor\n";
  const auto v5 = dir.write("v5.fst", fst + ed_line);
  EXPECT_NO_THROW(whirl::io::readOpenFastTurbine(v5));
}

}  // namespace

// io::readOpenFastDeck: the whole deck in one pass (the turbine builder reads nothing itself).
#include <gtest/gtest.h>

#include "src/io/openfast/offshore/wamit_input.hpp"
#include "src/io/openfast/openfast_deck.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using whirl::io::OpenFastDeck;
using whirl::io::readOpenFastDeck;
using whirl::test::nrel5mwDir;
using whirl::test::sourceDir;

TEST(OpenFastDeck, StructuralDeckReadsServoDynForTheYawSpringOnly) {
  // Main_Onshore.fst: CompAero = 0, CompServo = 1, YawDOF on (cases/nrel5mw/README.md).
  const OpenFastDeck d = readOpenFastDeck(nrel5mwDir() / "Main_Onshore.fst");
  EXPECT_TRUE(d.turbine.elastodyn.dof.YawDOF);
  EXPECT_TRUE(d.servodyn.has_value());
  EXPECT_FALSE(d.aero.has_value());
  EXPECT_FALSE(d.controller.has_value());
  const OpenFastDeck without = readOpenFastDeck(nrel5mwDir() / "Main_Onshore.fst", nullptr, {false});
  EXPECT_FALSE(without.servodyn.has_value());
}

TEST(OpenFastDeck, AeroelasticDeckCarriesAeroDynServoDynAndTheRoscoController) {
  const OpenFastDeck d = readOpenFastDeck(nrel5mwDir() / "Main_ROSCO.fst");
  ASSERT_TRUE(d.aero.has_value());
  EXPECT_EQ(d.aero->blades.size(), 3u);
  ASSERT_TRUE(d.servodyn.has_value());
  EXPECT_EQ(d.servodyn->VSContrl, 5);  // the ROSCO DISCON.IN of cases/nrel5mw/rosco
  EXPECT_TRUE(d.controller.has_value());
}

TEST(OpenFastDeck, FloatingPlatformCarriesItsWamitCoefficients) {
  // OC3 Hywind: HydroDyn PotMod = 1 with HydroData/spar.{hst,1}; RdtnMod = 1 (convolution: refused, so
  // off here; no .ss file to read).
  whirl::io::OverrideSet set({whirl::io::parseOverride("CompAero=0"), whirl::io::parseOverride("RdtnMod=0")});
  const OpenFastDeck d = readOpenFastDeck(sourceDir() / "cases" / "oc3_hywind" / "Main_ROSCO.fst", &set);
  ASSERT_TRUE(d.turbine.wamit.has_value());
  EXPECT_FALSE(d.turbine.radiation.has_value());
  // spar.hst row "3 3 <C33>": the file's value, redimensionalized as readWamit does.
  const whirl::io::WamitMatrices w = whirl::io::dimensional(*d.turbine.wamit, 1025.0, 9.80665);
  const whirl::io::WamitMatrices ref = whirl::io::readWamit(*d.turbine.hydrodyn, 1025.0, 9.80665);
  EXPECT_EQ(w.hydrostatic, ref.hydrostatic);
  EXPECT_EQ(w.added_mass, ref.added_mass);
  EXPECT_GT(w.hydrostatic(2, 2), 0.0);
}

}  // namespace

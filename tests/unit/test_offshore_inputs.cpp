// HydroDyn, WAMIT and MAP++ inputs of the OC3-Hywind deck (cases/oc3_hywind, a copy of OpenFAST's
// certification Test24): the values read, their redimensionalization, and the refusals, each one
// line "file:line: key: reason".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "src/base/error.hpp"
#include "src/dynamics/catenary.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"
#include "src/io/openfast/offshore/map_input.hpp"
#include "src/io/openfast/offshore/wamit_input.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "tests/unit/test_util.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kDir = std::string(WHIRL_SOURCE_DIR) + "/cases/oc3_hywind/5MW_Baseline/";
const std::string kHydro = kDir + "NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat";
const std::string kMap = kDir + "NRELOffshrBsline5MW_OC3Hywind_MAP.dat";

io::HydroDynInput hydroWithRdtn0() {
  io::OverrideSet set({io::parseOverride("RdtnMod=0")});
  return io::readHydroDyn(kHydro, &set);
}

using test::errorOf;

TEST(HydroDynInput, Oc3HywindValues) {
  const io::HydroDynInput h = hydroWithRdtn0();
  EXPECT_EQ(*h.WtrDens, 1025);
  EXPECT_EQ(*h.WtrDpth, 320);
  EXPECT_EQ(h.PotMod, 1);
  EXPECT_EQ(h.PtfmVol0, 8029.21);
  EXPECT_EQ(h.AddCLin(5, 5), 98340000);  // the delta-line yaw spring (Jonkman 2010, Table 5-1)
  EXPECT_EQ(h.AddBLin(0, 0), 100000);
  EXPECT_EQ(h.AddBLin(2, 2), 130000);
  EXPECT_EQ(h.AddBLin(5, 5), 13000000);
  EXPECT_EQ(h.AddBLin(3, 3), 0);
  EXPECT_TRUE(h.AddBQuad.isZero());
  ASSERT_FALSE(h.notes.empty());  // WaveMod = 2: ignored, with a note
  EXPECT_THAT(h.notes.front(), HasSubstr(":9: WaveMod: incident waves ignored"));
}

TEST(HydroDynInput, RadiationConvolutionIsRefusedAsInOpenFast) {
  const std::string msg = errorOf([] { io::readHydroDyn(kHydro); });
  EXPECT_THAT(msg, StartsWith(kHydro + ":53: RdtnMod: 1 not supported by whirl (the radiation convolution has no "
                                       "linearization (OpenFAST refuses it too)"));
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(HydroDynInput, ForceFlagOffIsRefused) {
  io::OverrideSet set({io::parseOverride("RdtnMod=0"), io::parseOverride("PtfmPF=False")});
  EXPECT_EQ(errorOf([&] { io::readHydroDyn(kHydro, &set); }),
            kHydro +
                ":66: PtfmPF: False not supported by whirl (switching a direction's hydrodynamic loads off is "
                "not modelled; whirl supports only True or DEFAULT) (value set by override)");
}

TEST(HydroDynInput, Oc3HywindWamitMatrices) {
  const io::HydroDynInput h = hydroWithRdtn0();
  const double rho = 1025, g = 9.80665;
  const io::WamitMatrices w = io::readWamit(h, rho, g);  // PotFile "HydroData/Spar" finds spar.hst
  // spar.hst row "3 3 3.312247E+01", L = 1: C33 = 33.12247 ρ g.
  EXPECT_DOUBLE_EQ(w.hydrostatic(2, 2), 3.312247e1 * rho * g);
  EXPECT_DOUBLE_EQ(w.hydrostatic(4, 4), -4.973414e5 * rho * g);
  // spar.1 rows with PER = 0 (zero period: infinite frequency): A11 = 7569.865 ρ, A15 = −471356.7 ρ; not
  // the PER = −1 rows (infinite period: zero frequency, A11 = 7787.967 ρ).
  EXPECT_DOUBLE_EQ(w.added_mass(0, 0), 7.569865e3 * rho);
  EXPECT_DOUBLE_EQ(w.added_mass(0, 4), -4.713567e5 * rho);
  EXPECT_DOUBLE_EQ(w.added_mass(4, 4), 3.701091e7 * rho);
}

TEST(HydroDynInput, MissingWamitFileNamesPotFile) {
  test::TempDir dir;
  std::string text = test::slurp(kHydro);
  const std::string from = "\"HydroData/Spar\"";
  text.replace(text.find(from), from.size(), "\"nowhere/Spar\"");
  const std::string file = dir.write("hd.dat", text);
  io::OverrideSet set({io::parseOverride("RdtnMod=0")});
  const io::HydroDynInput h = io::readHydroDyn(file, &set);
  EXPECT_THAT(errorOf([&] { io::readWamit(h, 1025, 9.80665); }),
              StartsWith(file + ":48: PotFile: WAMIT file not found: "));
}

TEST(MapInput, Oc3HywindThreeLinesByRepeat) {
  const io::MapInput m = io::readMap(kMap);
  ASSERT_EQ(m.lines.size(), 1u);
  ASSERT_EQ(m.repeat_deg.size(), 2u);
  const std::vector<MooringLine> lines = io::mapMooringLines(m, 0, 320, 1025, 9.80665);
  ASSERT_EQ(lines.size(), 3u);
  // Apparent weight in water from the dictionary row: (MassDenInAir − ρ π Diam²/4) g.
  EXPECT_NEAR(lines[0].weight, (77.7066 - 1025 * std::numbers::pi * 0.09 * 0.09 / 4) * 9.80665, 1e-9);
  EXPECT_EQ(lines[0].anchor, Vec3(853.87, 0, -320));
  EXPECT_EQ(lines[0].fairlead, Vec3(5.2, 0, -70));
  EXPECT_TRUE(lines[0].seabed);
  const double c = std::cos(240 * std::numbers::pi / 180), s = std::sin(240 * std::numbers::pi / 180);
  EXPECT_NEAR((lines[1].anchor - Vec3(853.87 * c, 853.87 * s, -320)).norm(), 0, 1e-9);
  EXPECT_THAT(lines[2].name, HasSubstr("MAP.dat:13: Line 1 (repeat 120 deg)"));
}

TEST(MapInput, ConnectNodesAreRefusedOnTheirLine) {
  test::TempDir dir;
  std::string text = test::slurp(kMap);
  text.replace(text.find("fix "), 4, "Connect ");
  const std::string file = dir.write("map.dat", text);
  EXPECT_EQ(
      errorOf([&] { io::readMap(file); }),
      file + ":8: Type: connect nodes (multi-segment lines) are not supported by whirl: only anchor-to-fairlead lines");
}

// An anchor straight below its fairlead is read as a line (a tendon); the OC3 line of 902 m over a
// height of 250 m would hang slack, which the line's force names.
TEST(MapInput, VerticalLineIsReadAndASlackOneRefusedByItsForce) {
  test::TempDir dir;
  std::string text = test::slurp(kMap);
  text.replace(text.find("853.87"), 6, "5.2");
  const std::string file = dir.write("map.dat", text);
  const std::vector<MooringLine> lines = io::mapMooringLines(io::readMap(file), 0, 320, 1025, 9.80665);
  ASSERT_EQ(lines.size(), 3u);
  const Vec3 d = lines[0].fairlead - lines[0].anchor;
  EXPECT_NEAR(std::hypot(d(0), d(1)), 0.0, 1e-12);
  try {
    mooringFairleadForce<double>(lines[0], d);
    ADD_FAILURE() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_THAT(e.what(), HasSubstr("the line straight below its fairlead is slack"));
  }
}

TEST(MapInput, FloatingLineIsAnInputError) {
  const io::MapInput m = io::readMap(kMap);
  EXPECT_THAT(errorOf([&] { io::mapMooringLines(m, 0, 320, 20000, 9.80665); }),
              StartsWith(kMap + ":4: MassDenInAir: the line floats"));
}

}  // namespace
}  // namespace whirl

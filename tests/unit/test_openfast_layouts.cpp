// OpenFAST layouts whirl reads: the three real cases (NREL 5MW OpenFAST v3+, ws03 ElastoDyn v1.03 with
// Gravity in ElastoDyn, rotating-9rpm OpenFAST v3.2), and variants generated at test time from the
// NREL 5MW files: an ElastoDyn v1.00/v1.01 layout, an OpenFAST v5 layout, blade and tower tables with
// more or fewer columns, a FAST 8.0x `.fst` with True/False switches, and ServoDyn.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/openfast_support.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::ElementsAre;
using testing::HasSubstr;
using whirl::io::OpenFastTurbine;
using whirl::io::readOpenFastTurbine;
using whirl::test::inputErrorMessage;
using whirl::test::nrel5mwDir;
using whirl::test::openfastDataDir;
using whirl::test::readText;
using whirl::test::removeLine;
using whirl::test::replaceOnce;
using whirl::test::ScratchDir;

const char* kEd = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
const char* kTower = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
const char* kBlade = "NRELOffshrBsline5MW_Blade.dat";

/// The NREL 5MW case copied into a scratch folder, with the ElastoDyn main file replaced by `ed_text`.
std::filesystem::path writeCase(const ScratchDir& dir, const std::string& ed_text) {
  dir.copy(nrel5mwDir() / kTower);
  dir.copy(nrel5mwDir() / kBlade);
  dir.write(kEd, ed_text);
  return dir.copy(nrel5mwDir() / "Main_Onshore.fst");
}

std::string nrelEd() { return readText(nrel5mwDir() / kEd); }

TEST(OpenFastLayouts, Ws03ElastoDynV103GravityInElastoDyn) {
  const OpenFastTurbine t = readOpenFastTurbine(openfastDataDir() / "ws03" / "ws03.0.fst");
  EXPECT_FALSE(t.fst.Gravity.has_value());
  ASSERT_TRUE(t.elastodyn.Gravity.has_value());
  EXPECT_DOUBLE_EQ(whirl::io::gravity(t), 9.80665);
  EXPECT_EQ(t.fst.CompServo, 0);
  EXPECT_FALSE(whirl::io::readServoDynIfEnabled(t.fst).has_value());  // ServoDyn off: not read
  EXPECT_DOUBLE_EQ(t.elastodyn.init.RotSpeed, 6.972);
  EXPECT_FALSE(t.elastodyn.dof.GenDOF);
  EXPECT_TRUE(t.elastodyn.dof.YawDOF);
  EXPECT_EQ(t.elastodyn.TwrFile,
            (openfastDataDir() / "5MW_Baseline" / kTower).lexically_normal());  // "../5MW_Baseline/…"
  EXPECT_EQ(t.elastodyn.source.getDoubles("TwrGagNd"), (std::vector<double>{10, 19, 28}));
  EXPECT_DOUBLE_EQ(t.elastodyn.tower.TwFAM1Sh[0], 0.7004);
  EXPECT_EQ(t.elastodyn.blades.size(), 3u);
  EXPECT_NO_THROW(whirl::io::requireSupported(t));
}

TEST(OpenFastLayouts, Rotating9rpmOpenFast32) {
  const OpenFastTurbine t = readOpenFastTurbine(openfastDataDir() / "rotating-9rpm" / "Main.fst");
  EXPECT_DOUBLE_EQ(whirl::io::gravity(t), 9.80665);
  EXPECT_FALSE(t.elastodyn.Gravity.has_value());
  EXPECT_EQ(t.fst.MHK, 0);
  EXPECT_DOUBLE_EQ(t.elastodyn.init.RotSpeed, 9.0);
  EXPECT_TRUE(t.elastodyn.dof.GenDOF);
  EXPECT_FALSE(t.elastodyn.dof.DrTrDOF || t.elastodyn.dof.YawDOF || t.elastodyn.dof.TwFADOF1);
  EXPECT_EQ(t.elastodyn.source.getDoubles("BldGagNd"), (std::vector<double>{5}));  // "5,"
  EXPECT_EQ(t.elastodyn.blades[2].NBlInpSt, 49);
  EXPECT_NO_THROW(whirl::io::requireSupported(t));
  // ServoDyn is on, but its file was not copied: the error names the .fst line, and only when asked.
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::readServoDynIfEnabled(t.fst); }),
              HasSubstr("Main.fst:39: ServoFile: file not found: "));
}

TEST(OpenFastLayouts, ElastoDynV100) {
  // FAST 8.0x ElastoDyn: Gravity here, no BldNodes, TwrRBHt/TwrDraft/PtfmRef instead of TowerBsHt and
  // PtfmRefzt, no PtfmCMxt/PtfmCMyt.
  std::string ed = nrelEd();
  ed = replaceOnce(ed, "---------------------- DEGREES OF FREEDOM",
                   "---------------------- ENVIRONMENTAL CONDITION ---\n"
                   "    9.80665   Gravity     - Gravitational acceleration (m/s^2)\n"
                   "---------------------- DEGREES OF FREEDOM");
  ed = replaceOnce(ed, "          0   TowerBsHt   - Height",
                   "          0   TwrRBHt     - Tower rigid base height (meters)\n"
                   "          0   TwrDraft    - Height");
  ed = removeLine(ed, "PtfmCMxt");
  ed = removeLine(ed, "PtfmCMyt");
  ed = replaceOnce(ed, "PtfmRefzt   - Vertical", "PtfmRef     - Downward");
  ed = removeLine(ed, "BldNodes");
  ScratchDir dir;
  const OpenFastTurbine t = readOpenFastTurbine(writeCase(dir, ed));
  EXPECT_EQ(t.elastodyn.Gravity, 9.80665);
  EXPECT_DOUBLE_EQ(whirl::io::gravity(t), 9.80665);  // the .fst value wins when both have one
  EXPECT_FALSE(t.elastodyn.BldNodes.has_value());
  EXPECT_FALSE(t.elastodyn.config.TowerBsHt.has_value());
  EXPECT_EQ(t.elastodyn.config.TwrRBHt, 0.0);
  EXPECT_EQ(t.elastodyn.config.TwrDraft, 0.0);
  EXPECT_EQ(t.elastodyn.config.PtfmRef, 0.0);
  EXPECT_FALSE(t.elastodyn.config.PtfmCMxt.has_value());
  EXPECT_FALSE(t.elastodyn.config.PtfmRefzt.has_value());
  EXPECT_DOUBLE_EQ(t.elastodyn.config.TowerHt, 87.6);
  EXPECT_NO_THROW(whirl::io::requireSupported(t));
}

TEST(OpenFastLayouts, OpenFastV5) {
  // v4/v5 additions: PitchDOF, PtfmRefxt/yt, PBrIner/BlPIner, HubIner_Teeter, products of inertia,
  // YAW-FRICTION section; blade table without PitchAxis; .fst with NRotors.
  std::string ed = nrelEd();
  ed = replaceOnce(ed, "False         TeetDOF",
                   "False         PitchDOF    - Blade pitch DOF (flag)\n"
                   "False         TeetDOF");
  ed = replaceOnce(ed, "          0   PtfmRefzt",
                   "          0   PtfmRefxt   - x\n          0   PtfmRefyt   - y\n"
                   "          0   PtfmRefzt");
  ed = replaceOnce(ed, "      56780   HubMass",
                   "        200   PBrIner(1)  - a\n        200   PBrIner(2)  - a\n"
                   "        200   PBrIner(3)  - a\n      28578   BlPIner(1)  - b\n"
                   "      28578   BlPIner(2)  - b\n      28578   BlPIner(3)  - b\n"
                   "      56780   HubMass");
  ed = replaceOnce(ed, "    534.116   GenIner", "          0   HubIner_Teeter - t\n    534.116   GenIner");
  ed = replaceOnce(ed, "---------------------- BLADE ----",
                   "          0   PtfmXYIner  - xy\n          0   PtfmYZIner  - yz\n"
                   "          0   PtfmXZIner  - xz\n---------------------- BLADE ----");
  ed = replaceOnce(ed, "---------------------- FURLING",
                   "---------------------- YAW-FRICTION ---\n"
                   "          0   YawFrctMod  - Yaw-friction model\n"
                   "        300   M_CSmax     - Maximum static Coulomb friction torque (N-m)\n"
                   "---------------------- FURLING");
  std::string blade = readText(nrel5mwDir() / kBlade);
  blade = replaceOnce(blade, "BlFract      PitchAxis      StrcTwst", "BlFract      StrcTwst");
  blade = replaceOnce(blade, "(-)           (-)          (deg)", "(-)          (deg)");
  std::string stripped;  // drop the second number of every table row
  for (std::size_t b = 0, e; b < blade.size(); b = e + 1) {
    e = blade.find('\n', b);
    std::string line = blade.substr(b, e - b);
    if (line.size() > 30 && line[1] == '.' && line[9] == 'E') line.erase(13, 15);
    stripped += line + "\n";
    if (e == std::string::npos) break;
  }
  std::string fst = readText(nrel5mwDir() / "Main_Onshore.fst");
  fst = replaceOnce(fst, "          1   CompElast",
                    "          1   NRotors         - Number of rotors (-)\n"
                    "          1   CompElast");
  ScratchDir dir;
  writeCase(dir, ed);
  dir.write(kBlade, stripped);
  const OpenFastTurbine t = readOpenFastTurbine(dir.write("Main_Onshore.fst", fst));
  EXPECT_EQ(t.fst.NRotors, 1);
  EXPECT_EQ(t.elastodyn.dof.PitchDOF, false);
  EXPECT_EQ(t.elastodyn.config.PtfmRefxt, 0.0);
  ASSERT_TRUE(t.elastodyn.mass.PBrIner.has_value());
  EXPECT_THAT(*t.elastodyn.mass.BlPIner, ElementsAre(28578.0, 28578.0, 28578.0));
  EXPECT_EQ(t.elastodyn.mass.HubIner_Teeter, 0.0);
  EXPECT_EQ(t.elastodyn.mass.PtfmXZIner, 0.0);
  EXPECT_EQ(t.elastodyn.YawFrctMod, 0);
  const whirl::io::ElastoDynBlade& b = t.elastodyn.blades[0];
  EXPECT_EQ(b.pitchAxis(), nullptr);
  EXPECT_THAT(b.distributed.names, ElementsAre("BlFract", "StrcTwst", "BMassDen", "FlpStff", "EdgStff"));
  EXPECT_DOUBLE_EQ(b.distributed.column("StrcTwst")[0], 13.308);
  EXPECT_DOUBLE_EQ(b.distributed.column("EdgStff")[48], 5.01e6);
  EXPECT_NO_THROW(whirl::io::requireSupported(t));
}

TEST(OpenFastLayouts, WideTablesOfOlderFiles) {
  // FAST 7 / ElastoDyn-Adams tables: AeroCent instead of PitchAxis and 17 blade columns; 10 tower columns.
  const std::string blade =
      "------- ELASTODYN V1.00.* INDIVIDUAL BLADE INPUT FILE ---\nsmall blade\n--- BLADE PARAMETERS ---\n"
      "  3   NBlInpSt    - n\n  1   BldFlDmp(1) - d\n  1   BldFlDmp(2) - d\n  1   BldEdDmp(1) - d\n"
      "--- ADJUSTMENT ---\n  1   FlStTunr(1) - t\n  1   FlStTunr(2) - t\n  1   AdjBlMs - a\n  1   AdjFlSt - a\n"
      "  1   AdjEdSt - a\n--- DISTRIBUTED BLADE PROPERTIES ---\n"
      "BlFract AeroCent StrcTwst BMassDen FlpStff EdgStff GJStff EAStff Alpha FlpIner EdgIner PrecrvRef "
      "PreswpRef FlpcgOf EdgcgOf FlpEAOf EdgEAOf\n"
      "(-) (-) (deg) (kg/m) (Nm^2) (Nm^2) (Nm^2) (N) (-) (kg m) (kg m) (m) (m) (m) (m) (m) (m)\n"
      "0.0 0.25 10 100 1e9 2e9 1e8 1e10 0 1 1 0 0 0 0 0 0\n"
      "0.5 0.25  5  50 1e8 2e8 1e7 1e9  0 1 1 0 0 0 0 0 0\n"
      "1.0 0.25  0  10 1e7 2e7 1e6 1e8  0 1 1 0 0 0 0 0 0\n"
      "--- BLADE MODE SHAPES ---\n"
      "  0.5 BldFl1Sh(2) - c\n  0.5 BldFl1Sh(3) - c\n  0 BldFl1Sh(4) - c\n  0 BldFl1Sh(5) - c\n  0 BldFl1Sh(6) - c\n"
      "  1 BldFl2Sh(2) - c\n  0 BldFl2Sh(3) - c\n  0 BldFl2Sh(4) - c\n  0 BldFl2Sh(5) - c\n  0 BldFl2Sh(6) - c\n"
      "  1 BldEdgSh(2) - c\n  0 BldEdgSh(3) - c\n  0 BldEdgSh(4) - c\n  0 BldEdgSh(5) - c\n  0 BldEdgSh(6) - c\n";
  ScratchDir dir;
  const whirl::io::ElastoDynBlade b = whirl::io::readElastoDynBlade(dir.write("b.dat", blade));
  ASSERT_NE(b.pitchAxis(), nullptr);
  EXPECT_THAT(*b.pitchAxis(), ElementsAre(0.25, 0.25, 0.25));
  EXPECT_EQ(b.distributed.names.size(), 17u);
  EXPECT_THAT(b.distributed.column("EAStff"), ElementsAre(1e10, 1e9, 1e8));
  EXPECT_EQ(b.distributed.units[7], "(N)");

  std::string tower = readText(nrel5mwDir() / kTower);
  tower = replaceOnce(tower, "TwSSStif\n", "TwSSStif TwGJStif TwEAStif TwFAIner TwSSIner TwFAcgOf TwSScgOf\n");
  tower = replaceOnce(tower, "(Nm^2)         (Nm^2)\n", "(Nm^2) (Nm^2) (Nm^2) (N) (kg m) (kg m) (m) (m)\n");
  std::string wide;
  for (std::size_t b0 = 0, e; b0 < tower.size(); b0 = e + 1) {
    e = tower.find('\n', b0);
    std::string line = tower.substr(b0, e - b0);
    if (line.size() > 30 && line[1] == '.' && line[9] == 'E') line += " 1e11 1e12 100 100 0 0";
    wide += line + "\n";
    if (e == std::string::npos) break;
  }
  const whirl::io::ElastoDynTower t = whirl::io::readElastoDynTower(dir.write("t.dat", wide));
  EXPECT_EQ(t.distributed.names.size(), 10u);
  EXPECT_EQ(t.distributed.rows(), 11u);
  EXPECT_DOUBLE_EQ(t.distributed.column("TwGJStif")[3], 1e11);
  EXPECT_DOUBLE_EQ(t.distributed.column("TwSSStif")[10], 1.1582e11);
}

TEST(OpenFastLayouts, Fast8FstWithFlagSwitchesAndServoDyn) {
  // FAST 8.0x: CompAero/CompServo as True/False, SrvDFile/ADFile names, no Gravity, no CompElast.
  const std::string fst =
      "------- FAST V8.02.* INPUT FILE ---\nold layout\n--- FEATURE FLAGS ---\n"
      "True          CompAero        - Compute aerodynamic forces (flag)\n"
      "True          CompServo       - Compute servodynamics (flag)\n"
      "False         CompHydro       - Compute hydrodynamics forces (flag)\n"
      "--- INPUT FILES ---\n"
      "\"" +
      std::string(kEd) +
      "\"    EDFile      - ElastoDyn\n"
      "\"ad.ipt\"    ADFile          - AeroDyn\n"
      "\"srvd/ServoDyn.dat\"    SrvDFile        - ServoDyn\n";
  const std::string servo =
      "------- SERVODYN v1.05.* INPUT FILE ---\nyaw section only matters\n"
      "--- NACELLE-YAW CONTROL ---\n"
      "          0   YCMode       - Yaw control mode (switch)\n"
      "     9999.9   TYCOn        - Time to enable active yaw control (s)\n"
      "          0   YawNeut      - Neutral yaw position (degrees)\n"
      "9.02832E+09   YawSpr       - Nacelle-yaw spring constant (N-m/rad)\n"
      "  1.916E+07   YawDamp      - Nacelle-yaw damping constant (N-m/(rad/s))\n";
  ScratchDir dir;
  writeCase(dir, nrelEd());
  dir.write("srvd/ServoDyn.dat", servo);
  const OpenFastTurbine t = readOpenFastTurbine(dir.write("old.fst", fst));
  EXPECT_EQ(t.fst.CompElast, 1);
  EXPECT_EQ(t.fst.CompAero, 1);
  EXPECT_EQ(t.fst.CompServo, 1);
  EXPECT_EQ(t.fst.CompHydro, 0);
  EXPECT_EQ(t.fst.AeroFile, dir.path() / "ad.ipt");
  EXPECT_THAT(inputErrorMessage([&] { whirl::io::gravity(t); }),
              HasSubstr("old.fst: Gravity: not in this file nor in "));
  const std::optional<whirl::io::ServoDynInput> s = whirl::io::readServoDynIfEnabled(t.fst);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->YCMode, 0);
  EXPECT_DOUBLE_EQ(s->YawNeut, 0.0);
  EXPECT_DOUBLE_EQ(s->YawSpr, 9.02832e9);
  EXPECT_DOUBLE_EQ(s->YawDamp, 1.916e7);
}

}  // namespace

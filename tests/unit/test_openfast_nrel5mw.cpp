// Every field whirl reads from the NREL 5MW onshore OpenFAST files (cases/nrel5mw), checked against
// the values printed in those files (source: the files themselves; exact decimal values, compared as
// doubles parsed from the same text, so EXPECT_DOUBLE_EQ).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/openfast_support.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::DoubleEq;
using testing::ElementsAre;
using testing::HasSubstr;
using whirl::io::OpenFastTurbine;
using whirl::test::nrel5mwDir;

const OpenFastTurbine& nrel5mw() {
  static const OpenFastTurbine t = whirl::io::readOpenFastTurbine(nrel5mwDir() / "Main_Onshore.fst");
  return t;
}

std::filesystem::path inCase(const char* name) { return (nrel5mwDir() / name).lexically_normal(); }

TEST(OpenFastNrel5mw, Fst) {
  const whirl::io::FstInput& f = nrel5mw().fst;
  ASSERT_TRUE(f.Gravity.has_value());
  EXPECT_DOUBLE_EQ(*f.Gravity, 9.80665);
  EXPECT_EQ(f.CompElast, 1);
  // The structural case: InflowWind and AeroDyn are switched off in this copy (cases/nrel5mw/README.md);
  // Main_Aero.fst beside it is the aeroelastic deck.
  EXPECT_EQ(f.CompInflow, 0);
  EXPECT_EQ(f.CompAero, 0);
  EXPECT_EQ(f.CompServo, 1);
  EXPECT_EQ(f.CompHydro, 0);
  EXPECT_EQ(f.CompSub, 0);
  EXPECT_EQ(f.CompMooring, 0);
  EXPECT_EQ(f.MHK, 0);
  EXPECT_FALSE(f.NRotors.has_value());
  EXPECT_EQ(f.EDFile, inCase("NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"));
  EXPECT_EQ(f.ServoFile, inCase("NRELOffshrBsline5MW_Onshore_ServoDyn.dat"));
  EXPECT_EQ(f.AeroFile, inCase("onshore/AeroDyn.dat"));
  EXPECT_DOUBLE_EQ(whirl::io::gravity(nrel5mw()), 9.80665);
}

TEST(OpenFastNrel5mw, DegreesOfFreedom) {
  const whirl::io::ElastoDynInput& ed = nrel5mw().elastodyn;
  EXPECT_FALSE(ed.Gravity.has_value());  // in the .fst from OpenFAST v3 on
  const whirl::io::ElastoDynDofs& d = ed.dof;
  EXPECT_TRUE(d.FlapDOF1);
  EXPECT_TRUE(d.FlapDOF2);
  EXPECT_TRUE(d.EdgeDOF);
  EXPECT_FALSE(d.PitchDOF.has_value());
  EXPECT_FALSE(d.TeetDOF);
  EXPECT_TRUE(d.DrTrDOF);
  EXPECT_TRUE(d.GenDOF);
  EXPECT_TRUE(d.YawDOF);
  EXPECT_TRUE(d.TwFADOF1);
  EXPECT_TRUE(d.TwFADOF2);
  EXPECT_TRUE(d.TwSSDOF1);
  EXPECT_TRUE(d.TwSSDOF2);
  EXPECT_FALSE(d.PtfmSgDOF || d.PtfmSwDOF || d.PtfmHvDOF || d.PtfmRDOF || d.PtfmPDOF || d.PtfmYDOF);
}

TEST(OpenFastNrel5mw, InitialConditions) {
  const whirl::io::ElastoDynInitialConditions& c = nrel5mw().elastodyn.init;
  EXPECT_DOUBLE_EQ(c.OoPDefl, 0.0);
  EXPECT_DOUBLE_EQ(c.IPDefl, 0.0);
  EXPECT_THAT(c.BlPitch, ElementsAre(0.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(c.TeetDefl, 0.0);
  EXPECT_DOUBLE_EQ(c.Azimuth, 0.0);
  EXPECT_DOUBLE_EQ(c.RotSpeed, 10.0);  // rpm
  EXPECT_DOUBLE_EQ(c.NacYaw, 0.0);
  EXPECT_DOUBLE_EQ(c.TTDspFA, 0.0);
  EXPECT_DOUBLE_EQ(c.TTDspSS, 0.0);
  for (double v : {c.PtfmSurge, c.PtfmSway, c.PtfmHeave, c.PtfmRoll, c.PtfmPitch, c.PtfmYaw}) EXPECT_EQ(v, 0.0);
}

TEST(OpenFastNrel5mw, TurbineConfiguration) {
  const whirl::io::ElastoDynConfiguration& c = nrel5mw().elastodyn.config;
  EXPECT_EQ(c.NumBl, 3);
  EXPECT_DOUBLE_EQ(c.TipRad, 63.0);
  EXPECT_DOUBLE_EQ(c.HubRad, 1.5);
  EXPECT_THAT(c.PreCone, ElementsAre(-2.5, -2.5, -2.5));  // deg
  EXPECT_DOUBLE_EQ(c.HubCM, 0.0);
  EXPECT_DOUBLE_EQ(c.UndSling, 0.0);
  EXPECT_DOUBLE_EQ(c.Delta3, 0.0);
  EXPECT_DOUBLE_EQ(c.AzimB1Up, 0.0);
  EXPECT_DOUBLE_EQ(c.OverHang, -5.0191);
  EXPECT_DOUBLE_EQ(c.ShftGagL, 1.912);
  EXPECT_DOUBLE_EQ(c.ShftTilt, -5.0);  // deg
  EXPECT_DOUBLE_EQ(c.NacCMxn, 1.9);
  EXPECT_DOUBLE_EQ(c.NacCMyn, 0.0);
  EXPECT_DOUBLE_EQ(c.NacCMzn, 1.75);
  EXPECT_DOUBLE_EQ(c.NcIMUxn, -3.09528);
  EXPECT_DOUBLE_EQ(c.NcIMUyn, 0.0);
  EXPECT_DOUBLE_EQ(c.NcIMUzn, 2.23336);
  EXPECT_DOUBLE_EQ(c.Twr2Shft, 1.96256);
  EXPECT_DOUBLE_EQ(c.TowerHt, 87.6);
  EXPECT_EQ(c.TowerBsHt, 0.0);
  EXPECT_EQ(c.PtfmCMxt, 0.0);
  EXPECT_EQ(c.PtfmCMyt, 0.0);
  EXPECT_EQ(c.PtfmCMzt, 0.0);
  EXPECT_EQ(c.PtfmRefzt, 0.0);
  EXPECT_FALSE(c.PtfmRefxt.has_value());
  EXPECT_FALSE(c.TwrRBHt.has_value());
}

TEST(OpenFastNrel5mw, MassAndInertia) {
  const whirl::io::ElastoDynMassInertia& m = nrel5mw().elastodyn.mass;
  EXPECT_THAT(m.TipMass, ElementsAre(0.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(m.HubMass, 56780.0);
  EXPECT_DOUBLE_EQ(m.HubIner, 115926.0);
  EXPECT_DOUBLE_EQ(m.GenIner, 534.116);
  EXPECT_DOUBLE_EQ(m.NacMass, 240000.0);
  EXPECT_DOUBLE_EQ(m.NacYIner, 2.60789e6);
  EXPECT_DOUBLE_EQ(m.YawBrMass, 0.0);
  EXPECT_DOUBLE_EQ(m.PtfmMass, 7.46633e6);
  EXPECT_DOUBLE_EQ(m.PtfmRIner, 4.22923e9);
  EXPECT_DOUBLE_EQ(m.PtfmPIner, 4.22923e9);
  EXPECT_DOUBLE_EQ(m.PtfmYIner, 1.6423e8);
  EXPECT_FALSE(m.PBrIner.has_value());
  EXPECT_FALSE(m.HubIner_Teeter.has_value());
  EXPECT_FALSE(m.PtfmXYIner.has_value());
}

TEST(OpenFastNrel5mw, BladeTeeterDrivetrainFurlingTower) {
  const whirl::io::ElastoDynInput& ed = nrel5mw().elastodyn;
  EXPECT_EQ(ed.BldNodes, 17);
  ASSERT_EQ(ed.BldFile.size(), 3u);
  for (const auto& p : ed.BldFile) EXPECT_EQ(p, inCase("NRELOffshrBsline5MW_Blade.dat"));
  EXPECT_EQ(ed.teeter.TeetMod, 0);
  for (const auto& v : {ed.teeter.TeetDmpP, ed.teeter.TeetDmp, ed.teeter.TeetCDmp, ed.teeter.TeetSStP,
                        ed.teeter.TeetHStP, ed.teeter.TeetSSSp, ed.teeter.TeetHSSp})
    EXPECT_EQ(v, 0.0);
  EXPECT_DOUBLE_EQ(ed.drivetrain.GBoxEff, 100.0);  // %
  EXPECT_DOUBLE_EQ(ed.drivetrain.GBRatio, 97.0);
  EXPECT_DOUBLE_EQ(ed.drivetrain.DTTorSpr, 867637000.0);
  EXPECT_DOUBLE_EQ(ed.drivetrain.DTTorDmp, 6.215e6);
  EXPECT_FALSE(ed.YawFrctMod.has_value());
  EXPECT_FALSE(ed.Furling);
  EXPECT_EQ(ed.FurlFile, inCase("unused"));
  EXPECT_EQ(ed.TwrNodes, 20);
  EXPECT_EQ(ed.TwrFile, inCase("NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"));
}

TEST(OpenFastNrel5mw, Tower) {
  const whirl::io::ElastoDynTower& t = nrel5mw().elastodyn.tower;
  EXPECT_EQ(t.NTwInpSt, 11);
  EXPECT_THAT(t.TwrFADmp, ElementsAre(1.0, 1.0));
  EXPECT_THAT(t.TwrSSDmp, ElementsAre(1.0, 1.0));
  EXPECT_THAT(t.FAStTunr, ElementsAre(1.0, 1.0));
  EXPECT_THAT(t.SSStTunr, ElementsAre(1.0, 1.0));
  EXPECT_DOUBLE_EQ(t.AdjTwMa, 1.0);
  EXPECT_DOUBLE_EQ(t.AdjFASt, 1.0);
  EXPECT_DOUBLE_EQ(t.AdjSSSt, 1.0);
  const whirl::io::DistributedTable& d = t.distributed;
  EXPECT_EQ(d.rows(), 11u);
  EXPECT_THAT(d.names, ElementsAre("HtFract", "TMassDen", "TwFAStif", "TwSSStif"));
  EXPECT_THAT(d.units, ElementsAre("(-)", "(kg/m)", "(Nm^2)", "(Nm^2)"));
  EXPECT_DOUBLE_EQ(d.column("HtFract")[0], 0.0);
  EXPECT_DOUBLE_EQ(d.column("htfract")[5], 0.5);  // case-insensitive
  EXPECT_DOUBLE_EQ(d.column("HtFract")[10], 1.0);
  EXPECT_DOUBLE_EQ(d.column("TMassDen")[0], 5590.87);
  EXPECT_DOUBLE_EQ(d.column("TMassDen")[10], 2536.27);
  EXPECT_DOUBLE_EQ(d.column("TwFAStif")[0], 6.14343e11);
  EXPECT_DOUBLE_EQ(d.column("TwSSStif")[10], 1.1582e11);
  EXPECT_EQ(d.row_lines.front(), 20);
  EXPECT_THAT(t.TwFAM1Sh, ElementsAre(0.7004, 2.1963, -5.6202, 6.2275, -2.504));
  EXPECT_THAT(t.TwFAM2Sh, ElementsAre(-70.5319, -63.7623, 289.737, -176.513, 22.0706));
  EXPECT_THAT(t.TwSSM1Sh, ElementsAre(1.385, -1.7684, 3.0871, -2.2395, 0.5357));
  EXPECT_THAT(t.TwSSM2Sh, ElementsAre(-121.21, 184.415, -224.904, 298.536, -135.838));
}

TEST(OpenFastNrel5mw, Blades) {
  const whirl::io::ElastoDynInput& ed = nrel5mw().elastodyn;
  ASSERT_EQ(ed.blades.size(), 3u);
  const whirl::io::ElastoDynBlade& b = ed.blades[1];
  EXPECT_EQ(b.NBlInpSt, 49);
  EXPECT_THAT(b.BldFlDmp, ElementsAre(0.477465, 0.477465));
  EXPECT_DOUBLE_EQ(b.BldEdDmp, 0.477465);
  EXPECT_THAT(b.FlStTunr, ElementsAre(1.0, 1.0));
  EXPECT_DOUBLE_EQ(b.AdjBlMs, 1.04536);
  EXPECT_DOUBLE_EQ(b.AdjFlSt, 1.0);
  EXPECT_DOUBLE_EQ(b.AdjEdSt, 1.0);
  const whirl::io::DistributedTable& d = b.distributed;
  EXPECT_EQ(d.rows(), 49u);
  EXPECT_THAT(d.names, ElementsAre("BlFract", "PitchAxis", "StrcTwst", "BMassDen", "FlpStff", "EdgStff"));
  EXPECT_DOUBLE_EQ(d.column("BlFract")[0], 0.0);
  EXPECT_DOUBLE_EQ(d.column("BlFract")[48], 1.0);
  ASSERT_NE(b.pitchAxis(), nullptr);
  EXPECT_DOUBLE_EQ((*b.pitchAxis())[0], 0.25);
  EXPECT_DOUBLE_EQ(d.column("StrcTwst")[0], 13.308);   // deg
  EXPECT_DOUBLE_EQ(d.column("BMassDen")[0], 678.935);  // as in the file: AdjBlMs not applied
  EXPECT_DOUBLE_EQ(d.column("FlpStff")[0], 1.811e10);
  EXPECT_DOUBLE_EQ(d.column("EdgStff")[48], 5.01e6);
  EXPECT_THAT(b.BldFl1Sh, ElementsAre(0.0622, 1.7254, -3.2452, 4.7131, -2.2555));
  EXPECT_THAT(b.BldFl2Sh, ElementsAre(-0.5809, 1.2067, -15.5349, 29.7347, -13.8255));
  EXPECT_THAT(b.BldEdgSh, ElementsAre(0.3627, 2.5337, -3.5772, 2.376, -0.6952));
  EXPECT_EQ(ed.blades[0].distributed.values, ed.blades[2].distributed.values);
}

TEST(OpenFastNrel5mw, SupportedAndServoDynYawSpring) {
  EXPECT_NO_THROW(whirl::io::requireSupported(nrel5mw()));
  // CompServo = 1: the minimal ServoDyn file written for whirl (r-test NREL 5MW yaw spring and damper).
  const std::optional<whirl::io::ServoDynInput> s = whirl::io::readServoDynIfEnabled(nrel5mw().fst);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->YCMode, 0);
  EXPECT_DOUBLE_EQ(s->YawNeut, 0.0);
  EXPECT_DOUBLE_EQ(s->YawSpr, 9.02832e9);
  EXPECT_DOUBLE_EQ(s->YawDamp, 1.916e7);
}

TEST(OpenFastNrel5mw, OverridesReachEveryFile) {
  whirl::io::OverrideSet set(std::vector<whirl::io::KeyOverride>{{"NacMass", "250000"},
                                                                 {"TwFAM1Sh(2)", "0.7104"},
                                                                 {"TwFAM1Sh(3)", "2.1863"},
                                                                 {"AdjBlMs", "1.0"},
                                                                 {"Gravity", "9.81"}});
  const OpenFastTurbine t = whirl::io::readOpenFastTurbine(nrel5mwDir() / "Main_Onshore.fst", &set);
  EXPECT_NO_THROW(set.requireAllUsed());
  EXPECT_DOUBLE_EQ(t.elastodyn.mass.NacMass, 250000.0);
  EXPECT_DOUBLE_EQ(t.elastodyn.tower.TwFAM1Sh[0], 0.7104);
  for (const auto& b : t.elastodyn.blades) EXPECT_DOUBLE_EQ(b.AdjBlMs, 1.0);
  EXPECT_DOUBLE_EQ(whirl::io::gravity(t), 9.81);

  whirl::io::OverrideSet unknown(std::vector<whirl::io::KeyOverride>{{"NacMas", "1"}});
  whirl::io::readOpenFastTurbine(nrel5mwDir() / "Main_Onshore.fst", &unknown);
  const std::string msg = whirl::test::inputErrorMessage([&] { unknown.requireAllUsed(); });
  EXPECT_THAT(msg, HasSubstr("NacMas: unknown key (not in any file read: "));
  EXPECT_THAT(msg, HasSubstr("NRELOffshrBsline5MW_Blade.dat"));
}

}  // namespace

// InflowWind (toolbox v3 and v5 files, an InflowWind v3.01 layout without VFlowAng), the ServoDyn
// generator-torque law of the toolbox deck (simple variable-speed control) and its refusals, and the
// aero-related keys of the .fst (InflowFile, environment).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/inflowwind_input.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
#include "tests/unit/aero_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::io::InflowWindInput;
using whirl::io::readInflowWind;
using whirl::io::readServoDyn;
using whirl::io::ServoDynInput;
using whirl::test::aeroDir;
using whirl::test::AeroScratch;
using whirl::test::inputErrorMessage;

TEST(InflowWindInput, ToolboxAndV5SteadyWind) {
  for (const char* rel : {"toolbox/InflowWind.dat", "v5/InflowWind.dat"}) {
    SCOPED_TRACE(rel);
    const InflowWindInput w = readInflowWind(aeroDir() / rel);
    EXPECT_EQ(w.WindType, 1);
    EXPECT_DOUBLE_EQ(w.PropagationDir, 0.0);
    EXPECT_TRUE(w.has_VFlowAng);
    EXPECT_DOUBLE_EQ(w.VFlowAng, 0.0);
    EXPECT_DOUBLE_EQ(w.HWindSpeed, 8.0);
    EXPECT_DOUBLE_EQ(w.RefHt, 90.0);
    EXPECT_DOUBLE_EQ(w.PLExp, 0.0);
    EXPECT_TRUE(whirl::io::unsupportedOptions(w).empty());
  }
}

TEST(InflowWindInput, OldLayoutWithoutVFlowAng) {
  // InflowWind v3.01 as in the FAST 8 certification tests: no VFlowAng, `PLexp`.
  const std::string text =
      "------- InflowWind v3.01.* INPUT FILE ---------------------------------------\n"
      "Steady 12 m/s winds with shear\n"
      "---------------------------------------------------------------------------------\n"
      "False         Echo           - Echo input data to <RootName>.ech (flag)\n"
      "          1   WindType       - switch for wind file type (1=steady; 2=uniform; ...)\n"
      "         10   PropagationDir - Direction of wind propagation (degrees)\n"
      "          1   NWindVel       - Number of points to output the wind velocity    (0 to 9)\n"
      "          0   WindVxiList    - List of coordinates in the inertial X direction (m)\n"
      "          0   WindVyiList    - List of coordinates in the inertial Y direction (m)\n"
      "         90   WindVziList    - List of coordinates in the inertial Z direction (m)\n"
      "================== Parameters for Steady Wind Conditions [used only for WindType = 1] ====\n"
      "         12   HWindSpeed     - Horizontal windspeed                            (m/s)\n"
      "         90   RefHt          - Reference height for horizontal wind speed      (m)\n"
      "        0.2   PLexp          - Power law exponent                              (-)\n";
  whirl::test::ScratchDir dir;
  const InflowWindInput w = readInflowWind(dir.write("ifw.dat", text));
  EXPECT_FALSE(w.has_VFlowAng);
  EXPECT_DOUBLE_EQ(w.VFlowAng, 0.0);
  EXPECT_DOUBLE_EQ(w.PropagationDir, 10.0);
  EXPECT_DOUBLE_EQ(w.HWindSpeed, 12.0);
  EXPECT_DOUBLE_EQ(w.PLExp, 0.2);
}

TEST(InflowWindInput, RefusalsAndErrors) {
  AeroScratch s;
  const std::string rel = "toolbox/InflowWind.dat";
  const std::string p = s.path(rel).string();
  EXPECT_TRUE(whirl::io::steadySubstitutes(readInflowWind(s.path(rel))).empty());
  // A wind file: linearized in the steady wind of the file's steady-wind section, said in a note.
  s.edit(rel, "          1   WindType", "          3   WindType");
  const InflowWindInput w = readInflowWind(s.path(rel));  // reads; refusing is aero_support's job
  EXPECT_NO_THROW(whirl::io::requireSupported(w));
  const std::vector<std::string> notes = whirl::io::steadySubstitutes(w);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], testing::StartsWith(p + ":5: WindType: 3: TurbSim full field wind: whirl linearizes in the "
                                                "steady wind of the file's steady-wind section, HWindSpeed = 8 m/s "
                                                "at RefHt = 90 m with PLExp = 0"));
  s.edit(rel, "          3   WindType", "          9   WindType");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::requireSupported(readInflowWind(s.path(rel))); }),
            p + ":5: WindType: 9 not supported by whirl (unknown wind type; whirl supports only WindType = 1 to 7)");
  s.edit(rel, "          9   WindType", "          1   WindType");
  s.edit(rel, "         90   RefHt ", "          0   RefHt ");
  EXPECT_EQ(inputErrorMessage([&] { readInflowWind(s.path(rel)); }), p + ":15: RefHt: must be positive (is 0)");
  s.edit(rel, "          0   RefHt ", "         90   RefHt ");
  s.edit(rel, "          8   HWindSpeed", "         -8   HWindSpeed");
  EXPECT_EQ(inputErrorMessage([&] { readInflowWind(s.path(rel)); }),
            p + ":14: HWindSpeed: must not be negative (is -8)");
  s.edit(rel, "         -8   HWindSpeed", "        101   HWindSpeed");
  EXPECT_EQ(inputErrorMessage([&] { readInflowWind(s.path(rel)); }),
            p + ":14: HWindSpeed: is 101 m/s, above the limit of 100 m/s (the aerodynamics are incompressible)");
}

TEST(ServoDynInput, ToolboxSimpleVariableSpeedLaw) {
  const ServoDynInput s = readServoDyn(aeroDir() / "toolbox" / "ServoDyn.dat");
  EXPECT_EQ(s.PCMode, std::optional<int>(0));
  EXPECT_EQ(s.VSContrl, std::optional<int>(1));
  EXPECT_EQ(s.GenModel, std::optional<int>(1));
  EXPECT_EQ(s.GenEff, std::optional<double>(94.4));
  EXPECT_EQ(s.VS_Rgn2K, std::optional<double>(0.025576));
  // The yaw fields are unchanged.
  EXPECT_EQ(s.YCMode, 0);
  EXPECT_DOUBLE_EQ(s.YawSpr, 9.02832e9);
  EXPECT_DOUBLE_EQ(s.YawDamp, 1.916e7);

  const whirl::io::GeneratorTorqueLaw law = whirl::io::generatorTorqueLaw(s);
  EXPECT_EQ(law.mode, whirl::io::TorqueControl::SimpleVariableSpeed);
  EXPECT_DOUBLE_EQ(law.GenEff, 94.4);
  EXPECT_DOUBLE_EQ(law.VS_RtGnSp, 1162.0);
  EXPECT_DOUBLE_EQ(law.VS_RtTq, 47403.0);
  EXPECT_DOUBLE_EQ(law.VS_Rgn2K, 0.025576);
  EXPECT_DOUBLE_EQ(law.VS_SlPc, 10.0);
}

TEST(ServoDynInput, ControllersInUserCodeRefusedOnlyForTheTorqueLaw) {
  const std::pair<const char*, std::string> cases[] = {{"3", "torque from the user routine UserVSCont"},
                                                       {"4", "torque from Simulink/LabVIEW"},
                                                       {"5", "torque from a Bladed-style controller DLL"}};
  for (const auto& [value, what] : cases) {
    SCOPED_TRACE(value);
    AeroScratch s;
    s.edit("toolbox/ServoDyn.dat", "          1   VSContrl", std::string("          ") + value + "   VSContrl");
    const ServoDynInput servo = readServoDyn(s.path("toolbox/ServoDyn.dat"));  // structural users: fine
    EXPECT_DOUBLE_EQ(servo.YawSpr, 9.02832e9);
    EXPECT_EQ(inputErrorMessage([&] { whirl::io::generatorTorqueLaw(servo); }),
              s.path("toolbox/ServoDyn.dat").string() + ":19: VSContrl: " + value + " not supported by whirl (" + what +
                  "; whirl supports only VSContrl = 1 (simple variable-speed law) or 0 with GenModel = 1 or 2 "
                  "(induction generator))");
    // An aerodynamic model is built open loop instead, with this note.
    const std::optional<std::string> note = whirl::io::externalTorqueController(servo);
    ASSERT_TRUE(note.has_value());
    EXPECT_EQ(*note, s.path("toolbox/ServoDyn.dat").string() + ":19: VSContrl: " + value + ": " + what +
                         ", which whirl does not run: the linear model is open loop (the generator torque is an "
                         "input, its speed feedback left out); trimming along the wind needs a torque law "
                         "(VSContrl = 1)");
  }
  EXPECT_FALSE(whirl::io::externalTorqueController(readServoDyn(aeroDir() / "toolbox" / "ServoDyn.dat")));
}

TEST(ServoDynInput, GeneratorModelsWithoutVariableSpeedControl) {
  AeroScratch s;
  const std::string rel = "toolbox/ServoDyn.dat";
  s.edit(rel, "          1   VSContrl", "          0   VSContrl");
  const whirl::io::GeneratorTorqueLaw law = whirl::io::generatorTorqueLaw(readServoDyn(s.path(rel)));
  EXPECT_EQ(law.mode, whirl::io::TorqueControl::SimpleInductionGenerator);
  EXPECT_DOUBLE_EQ(law.SIG_SySp, 9999.9);
  s.edit(rel, "          1   GenModel", "          2   GenModel");
  const whirl::io::GeneratorTorqueLaw thevenin = whirl::io::generatorTorqueLaw(readServoDyn(s.path(rel)));
  EXPECT_EQ(thevenin.mode, whirl::io::TorqueControl::TheveninInductionGenerator);
  EXPECT_DOUBLE_EQ(thevenin.TEC_Freq, 9999.9);
  EXPECT_EQ(thevenin.TEC_NPol, 9998);
  EXPECT_DOUBLE_EQ(thevenin.TEC_MR, 9999.9);
  s.edit(rel, "       9998   TEC_NPol", "          3   TEC_NPol");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::generatorTorqueLaw(readServoDyn(s.path(rel))); }),
            s.path(rel).string() + ":39: TEC_NPol: must be a positive even number of poles (is 3)");
  s.edit(rel, "          2   GenModel", "          3   GenModel");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::generatorTorqueLaw(readServoDyn(s.path(rel))); }),
            s.path(rel).string() +
                ":20: GenModel: 3 not supported by whirl (generator from the user routine UserGen; "
                "whirl supports only GenModel = 1 (simple induction generator) or 2 (Thevenin) when VSContrl = 0)");
}

TEST(ServoDynInput, TorqueLawValuesChecked) {
  AeroScratch s;
  const std::string rel = "toolbox/ServoDyn.dat";
  s.edit(rel, "       94.4   GenEff", "      104.4   GenEff");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::generatorTorqueLaw(readServoDyn(s.path(rel))); }),
            s.path(rel).string() + ":21: GenEff: must be in (0, 100] % (is 104.4)");
  s.edit(rel, "      104.4   GenEff", "       94.4   GenEff");
  s.edit(rel, "   0.025576   VS_Rgn2K", "  -0.025576   VS_Rgn2K");
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::generatorTorqueLaw(readServoDyn(s.path(rel))); }),
            s.path(rel).string() + ":30: VS_Rgn2K: must not be negative (is -0.025576)");
  // A file cut down to its yaw section reads, but has no torque law.
  const std::string yaw_only =
      "------- SERVODYN INPUT FILE ---\nyaw only\n--- NACELLE-YAW CONTROL ---\n"
      "          0   YCMode       - Yaw control mode (switch)\n"
      "          0   YawNeut      - Neutral yaw position (degrees)\n"
      "9.02832E+09   YawSpr       - Nacelle-yaw spring constant (N-m/rad)\n"
      "  1.916E+07   YawDamp      - Nacelle-yaw damping constant (N-m/(rad/s))\n";
  const ServoDynInput y = readServoDyn(s.write("yaw.dat", yaw_only));
  EXPECT_FALSE(y.VSContrl.has_value());
  EXPECT_EQ(inputErrorMessage([&] { whirl::io::generatorTorqueLaw(y); }),
            s.path("yaw.dat").string() + ": VSContrl: key not found in this file");
}

TEST(FstInput, InflowFileAndEnvironment) {
  const whirl::io::FstInput f = whirl::io::readFst(aeroDir() / "toolbox" / "Main.fst");
  EXPECT_EQ(f.CompAero, 2);
  EXPECT_EQ(f.CompInflow, 1);
  EXPECT_EQ(f.InflowFile, aeroDir() / "toolbox" / "InflowWind.dat");
  EXPECT_EQ(f.AeroFile, aeroDir() / "toolbox" / "AeroDyn.dat");
  EXPECT_EQ(f.AirDens, std::optional<double>(1.225));
  EXPECT_EQ(f.KinVisc, std::optional<double>(1.464e-5));
  EXPECT_EQ(f.SpdSound, std::optional<double>(335.0));
  EXPECT_EQ(f.Patm, std::optional<double>(103500.0));
  EXPECT_EQ(f.Pvap, std::optional<double>(1700.0));
  const whirl::io::AeroDynEnvironment env = whirl::io::aerodynEnvironment(f);
  EXPECT_DOUBLE_EQ(env.AirDens, 1.225);
  EXPECT_DOUBLE_EQ(env.KinVisc, 1.464e-5);
  const whirl::io::FstInput v5 = whirl::io::readFst(aeroDir() / "v5" / "main.fst");
  EXPECT_EQ(v5.InflowFile, aeroDir() / "v5" / "InflowWind.dat");
  EXPECT_EQ(v5.AirDens, std::optional<double>(1.225));
  EXPECT_TRUE(whirl::io::unsupportedAeroOptions(v5).empty());
}

TEST(FstInput, OlderLayoutsHaveNoEnvironment) {
  const whirl::io::FstInput f = whirl::io::readFst(whirl::test::openfastDataDir() / "ws03" / "ws03.0.fst");
  EXPECT_FALSE(f.AirDens.has_value());
  const whirl::io::AeroDynEnvironment env = whirl::io::aerodynEnvironment(f);
  EXPECT_DOUBLE_EQ(env.AirDens, 1.225);  // OpenFAST's defaults
  EXPECT_DOUBLE_EQ(env.KinVisc, 1.464e-5);
  EXPECT_DOUBLE_EQ(env.SpdSound, 335.0);
}

}  // namespace

// ROSCO's DISCON.IN reader (src/io/openfast/servodyn/discon_input.hpp) on the NREL 5MW file ROSCO ships
// (cases/nrel5mw/rosco/DISCON.IN, ROSCO v2.10.3), its bad-input messages, ROSCO's table look-ups
// (src/model/rosco_controller.hpp) and the ROSCO deck cases/nrel5mw/Main_ROSCO.fst.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>

#include "src/io/openfast/servodyn/discon_input.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace {

using testing::HasSubstr;
using whirl::InputError;
using whirl::RoscoController;
using whirl::io::parseDiscon;
using whirl::io::readDiscon;
using whirl::test::nrel5mwDir;
using whirl::test::readText;
using whirl::test::removeLine;
using whirl::test::replaceOnce;

std::filesystem::path disconFile() { return nrel5mwDir() / "rosco" / "DISCON.IN"; }

// The message parseDiscon throws for `text` (empty when it reads).
std::string errorOf(const std::string& text) {
  try {
    parseDiscon(text, "DISCON.IN");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DisconInput, Nrel5mwShippedFile) {
  const RoscoController c = readDiscon(disconFile());
  // Values as printed in cases/nrel5mw/rosco/DISCON.IN (ROSCO v2.10.3, Examples/Test_Cases/NREL-5MW).
  EXPECT_EQ(c.F_LPFType, 1);
  EXPECT_EQ(c.VS_ControlMode, 2);
  EXPECT_EQ(c.VS_ConstPower, 1);
  EXPECT_EQ(c.PC_ControlMode, 1);
  EXPECT_EQ(c.SS_Mode, 1);
  EXPECT_EQ(c.PS_Mode, 1);
  EXPECT_EQ(c.Fl_Mode, 0);
  EXPECT_EQ(c.PA_Mode, 0);
  EXPECT_DOUBLE_EQ(c.F_LPFCornerFreq, 1.5708);
  EXPECT_TRUE(c.gen_speed_notches.empty());
  EXPECT_DOUBLE_EQ(c.F_SSCornerFreq, 0.6283);
  ASSERT_EQ(c.PC_GS_angles.size(), 30u);
  EXPECT_DOUBLE_EQ(c.PC_GS_angles.front(), 0.057);
  EXPECT_DOUBLE_EQ(c.PC_GS_angles.back(), 0.402);
  EXPECT_DOUBLE_EQ(c.PC_GS_KP.front(), -2.075e-2);
  EXPECT_DOUBLE_EQ(c.PC_GS_KI.back(), -1.917e-3);
  EXPECT_DOUBLE_EQ(c.PC_RefSpd, 122.90967);
  EXPECT_DOUBLE_EQ(c.PC_FinePit, 0.0);
  EXPECT_DOUBLE_EQ(c.PC_MaxPit, 1.57);
  EXPECT_DOUBLE_EQ(c.PC_MinRat, -0.1745);
  EXPECT_DOUBLE_EQ(c.VS_GenEff, 0.944);  // 94.4 %
  EXPECT_DOUBLE_EQ(c.VS_RtPwr, 5e6);
  EXPECT_DOUBLE_EQ(c.VS_RtTq, 43093.5);
  EXPECT_DOUBLE_EQ(c.VS_MaxTq, 47402.9);
  EXPECT_DOUBLE_EQ(c.VS_MinOMSpd, 34.64286);
  EXPECT_DOUBLE_EQ(c.VS_RefSpd, 122.90967);
  EXPECT_DOUBLE_EQ(c.VS_TSRopt, 7.5);
  EXPECT_DOUBLE_EQ(c.VS_KP.front(), -697.771);
  EXPECT_DOUBLE_EQ(c.VS_KI.front(), -104.507);
  EXPECT_DOUBLE_EQ(c.SS_VSGain, 1.0);
  EXPECT_DOUBLE_EQ(c.SS_PCGain, 0.05);
  EXPECT_DOUBLE_EQ(c.WE_BladeRadius, 63.0);
  EXPECT_DOUBLE_EQ(c.WE_GearboxRatio, 97.0);
  ASSERT_EQ(c.PS_WindSpeeds.size(), 60u);
  EXPECT_DOUBLE_EQ(c.PS_BldPitchMin[25], 0.0145);
  // Where each key was written (file lines of the shipped file).
  EXPECT_EQ(c.at("PC_GS_KP").line, 59);
  EXPECT_EQ(c.at("VS_TSRopt").line, 94);
  EXPECT_EQ(c.at("F_LPFCornerFreq").line, 38);
  // The wind-speed estimator (WE_Mode = 2) is the one active mode whirl replaces by an assumption.
  ASSERT_EQ(c.notes.size(), 1u);
  EXPECT_EQ(c.notes[0], disconFile().string() +
                            ":20: WE_Mode: 2: the wind-speed estimator's dynamics are not "
                            "modelled: its estimate is taken equal to the hub-height wind (its "
                            "steady state)");
}

TEST(DisconInput, RoscoLookups) {
  const RoscoController c = readDiscon(disconFile());
  // PS_BldPitchMin at 10.5310 m/s is 0.0272 rad (table entry 27); halfway to 10.8207 m/s, 0.0320.
  EXPECT_NEAR(whirl::roscoMinimumPitch(c, 10.5310), 0.0272, 1e-12);
  EXPECT_NEAR(whirl::roscoMinimumPitch(c, 0.5 * (10.5310 + 10.8207)), 0.5 * (0.0272 + 0.0368), 1e-12);
  EXPECT_DOUBLE_EQ(whirl::roscoMinimumPitch(c, 2.0), 0.0);      // below the table: its first value
  EXPECT_DOUBLE_EQ(whirl::roscoMinimumPitch(c, 30.0), 0.3265);  // above: its last
  const whirl::RoscoPitchGains g = whirl::roscoPitchGains(c, 0.5 * (0.057 + 0.084));
  EXPECT_NEAR(g.kp, 0.5 * (-2.075e-2 - 1.823e-2), 1e-15);
  EXPECT_NEAR(g.ki, 0.5 * (-8.417e-3 - 7.536e-3), 1e-15);
  // Constant power: 5 MW / 0.944 / 122.90967 rad/s = 43093.5 N m (VS_RtTq, which ROSCO's tuning derives so).
  EXPECT_NEAR(whirl::roscoAboveRatedTorque(c, 122.90967), 43093.5, 0.5);
  EXPECT_NEAR(whirl::roscoAboveRatedTorque(c, 100.0), 47402.9, 1e-9);  // capped at VS_MaxTq
}

TEST(DisconInput, ToleratesOrderAndMissingOptionalKeys) {
  std::string text = readText(disconFile());
  // ROSCO finds keys by name: a key moved to the top reads the same; a key its modes do not need (the
  // yaw controller's, IPC's) may be missing.
  text = removeLine(text, "! VS_TSRopt");
  text = "7.5 ! VS_TSRopt - moved\n" + removeLine(removeLine(text, "! Y_Rate"), "! IPC_KP");
  const RoscoController c = parseDiscon(text, "DISCON.IN");
  EXPECT_DOUBLE_EQ(c.VS_TSRopt, 7.5);
  EXPECT_EQ(c.at("VS_TSRopt").line, 1);
}

TEST(DisconInput, OverridesReplaceTheValuesOfTheKeysWritten) {
  // --set KEY=VALUE on a ROSCO deck: the value as if written on the key's line (case-insensitive key),
  // used up; a key the file does not write stays unused (the caller reports it unknown).
  const std::string text = readText(disconFile());
  whirl::io::OverrideSet set(std::vector<whirl::io::KeyOverride>{{"vs_tsropt", "8.25"}, {"NotAKey", "1"}});
  const RoscoController c = parseDiscon(text, "DISCON.IN", &set);
  EXPECT_DOUBLE_EQ(c.VS_TSRopt, 8.25);
  EXPECT_EQ(c.at("VS_TSRopt").line, parseDiscon(text, "DISCON.IN").at("VS_TSRopt").line);
  EXPECT_THROW(set.requireAllUsed(), InputError);
  whirl::io::OverrideSet bad(std::vector<whirl::io::KeyOverride>{{"PC_GS_KP", "-0.01 -0.02"}});
  try {
    parseDiscon(text, "DISCON.IN", &bad);
    FAIL() << "a gain table of the wrong length was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("PC_GS_KP: 2 values"), std::string::npos) << e.what();
  }
}

TEST(DisconInputErrors, MissingNeededKey) {
  const std::string text = readText(disconFile());
  EXPECT_EQ(errorOf(removeLine(text, "! VS_RtPwr")), "DISCON.IN: VS_RtPwr: missing (the torque controller needs it)");
  EXPECT_EQ(errorOf(removeLine(text, "! PC_GS_KI")),
            "DISCON.IN: PC_GS_KI: missing (PC_ControlMode = 1 needs the pitch controller's schedule)");
  EXPECT_EQ(errorOf(removeLine(text, "! VS_TSRopt")),
            "DISCON.IN: VS_TSRopt: missing (TSR tracking (VS_ControlMode >= 2) needs the optimal tip-speed ratio)");
}

TEST(DisconInputErrors, TableLengthsMustMatchTheirCount) {
  const std::string text = readText(disconFile());
  // PC_GS_KP with its first value removed: 29 values for PC_GS_n = 30.
  EXPECT_EQ(errorOf(replaceOnce(text, "-2.075e-02   -1.823e-02", "-1.823e-02")),
            "DISCON.IN:59: PC_GS_KP: 29 values, but PC_GS_n = 30 expects 30");
  EXPECT_EQ(errorOf(replaceOnce(text, "60                  ! PS_BldPitchMin_N", "59 ! PS_BldPitchMin_N")),
            "DISCON.IN:152: PS_WindSpeeds: 60 values, but PS_BldPitchMin_N = 59 expects 59");
}

TEST(DisconInputErrors, ChecksOfRosco) {
  const std::string text = readText(disconFile());
  // Two pitch angles swapped: ROSCO's CheckInputs "PC_GS_angles must be non-decreasing".
  EXPECT_EQ(errorOf(replaceOnce(text, "0.057        0.084", "0.084        0.057")),
            "DISCON.IN:58: PC_GS_angles: must be non-decreasing");
  EXPECT_EQ(errorOf(replaceOnce(text, "1.57080             ! F_LPFCornerFreq", "0 ! F_LPFCornerFreq")),
            "DISCON.IN:38: F_LPFCornerFreq: must be greater than zero");
  EXPECT_EQ(errorOf(replaceOnce(text, "-6.97771e+02        ! VS_KP", "697.771 ! VS_KP")),
            "DISCON.IN:92: VS_KP: must be less than zero");
  EXPECT_EQ(errorOf(replaceOnce(text, "2                   ! VS_ControlMode", "7 ! VS_ControlMode")),
            "DISCON.IN:13: VS_ControlMode: must be 0 to 4 (is 7)");
}

TEST(DisconInputErrors, MalformedLines) {
  const std::string text = readText(disconFile());
  EXPECT_EQ(errorOf(replaceOnce(text, "122.9096700000      ! PC_RefSpd", "12x.9 ! PC_RefSpd")),
            "DISCON.IN:67: PC_RefSpd: '12x.9' is not a number");
  EXPECT_EQ(errorOf(replaceOnce(text, "! PC_RefSpd", "! PC_RefSpeed")),
            "DISCON.IN:67: PC_RefSpeed: not a key of ROSCO's DISCON.IN (ROSCO 2.10 or earlier): check the spelling");
  EXPECT_EQ(errorOf(replaceOnce(text, "7.50000             ! VS_TSRopt", "7.5 8.0 ! VS_TSRopt")),
            "DISCON.IN:94: VS_TSRopt: 2 values, expected one");
  EXPECT_EQ(errorOf(text + "8.0 ! VS_TSRopt\n"),
            "DISCON.IN:" + std::to_string(1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'))) +
                ": VS_TSRopt: given twice (first on line 94; ROSCO would take the last silently): keep one");
  EXPECT_EQ(errorOf(replaceOnce(text, "1                   ! PC_ControlMode", "1.5 ! PC_ControlMode")),
            "DISCON.IN:16: PC_ControlMode: '1.5' is not an integer");
  EXPECT_THAT(errorOf(""), HasSubstr("VS_ControlMode: missing"));
}

TEST(DisconInput, RoscoDeckNamesTheController) {
  // cases/nrel5mw/Main_ROSCO.fst: ServoDyn PCMode = VSContrl = 5, DLL_InFile = DISCON.IN.
  const std::optional<RoscoController> c = whirl::io::readDeckController(nrel5mwDir() / "Main_ROSCO.fst",
                                                                         {"HWindSpeed=9"});
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->VS_ControlMode, 2);
  EXPECT_EQ(c->file, (nrel5mwDir() / "rosco" / "DISCON.IN").string());
  // The same ServoDyn with VSContrl = 1 (an override): no controller; the simple-VS deck has none either.
  EXPECT_FALSE(whirl::io::readDeckController(nrel5mwDir() / "Main_ROSCO.fst", {"VSContrl=1"}));
  EXPECT_FALSE(whirl::io::readDeckController(nrel5mwDir() / "Main_Aero.fst", {}));
  // PCMode = 0: the pitch is not the library's.
  const std::optional<RoscoController> torque_only = whirl::io::readDeckController(nrel5mwDir() / "Main_ROSCO.fst",
                                                                                   {"PCMode=0"});
  ASSERT_TRUE(torque_only.has_value());
  EXPECT_EQ(torque_only->PC_ControlMode, 0);
  EXPECT_THAT(torque_only->notes.back(), HasSubstr(":7: PCMode: 0: the pitch is not the controller's"));
}

}  // namespace

// The aeroelastic commands end to end: steady (trimmed) and campbell along the wind on the NREL 5MW
// aeroelastic deck; a broken aerodynamic input stops with the file and line.
#include <gtest/gtest.h>

#include "tests/cli/cli_support.hpp"

namespace whirl::test {
namespace {

const std::string kAero = "cases/nrel5mw/Main_Aero.fst";

TEST(CliAero, SteadyTrimsAndWritesTheTable) {
  const auto dir = freshDir("aero_steady");
  const auto r = whirl("steady " + kAero + " --wind 8:10:18 --no-plot --out '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(dir / "steady.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "wind_speed_m_s,rotor_speed_rpm,pitch_deg,aero_power_kw,generator_power_kw,aero_torque_knm,thrust_kn,cp,ct,"
            "tsr,tip_deflection_m,tower_top_fa_m,generator_torque_knm,region");
  EXPECT_NE(csv.find(",below rated\n"), std::string::npos);
  EXPECT_NE(csv.find(",above rated\n"), std::string::npos);
}

TEST(CliAero, CampbellAlongTheWind) {
  const auto dir = freshDir("aero_campbell");
  const auto r = whirl("campbell " + kAero + " --wind 8:4:12 --azimuths 8 --no-plot --out '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(dir / "campbell.csv");
  EXPECT_NE(csv.find("flap 1 collective"), std::string::npos);
  EXPECT_NE(csv.find(",8,"), std::string::npos);  // the wind-speed column is filled
}

TEST(CliAero, ParkedAndFeatheredRotorsInWind) {
  // 0 rpm in 8 m/s: the elements see the wind alone (BEM's Vy ≈ 0 cases), fine pitch and feathered.
  const auto parked = whirl("modes " + kAero + " --rpm 0 --format csv");
  ASSERT_EQ(parked.code, 0) << parked.err;
  EXPECT_NE(parked.out.find("tower FA 1"), std::string::npos);
  const auto feathered = whirl("modes " + kAero + " --rpm 0 --set 'BlPitch(1)=90' --set 'BlPitch(2)=90' --set 'BlPitch(3)=90'");
  EXPECT_EQ(feathered.code, 0) << feathered.err;
}

TEST(CliAero, BrokenAirfoilListNamesTheFileAndLine) {
  const auto r = whirl("modes " + kAero + " --set NumAFfiles=9");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("AeroDyn.dat:"), std::string::npos) << r.err;
}

TEST(CliAero, SteadyNeedsAerodynamics) {
  const auto r = whirl("steady cases/nrel5mw/Main_Onshore.fst --wind 8:1:8 --no-plot --out /tmp");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("no aerodynamics"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace whirl::test

namespace whirl::test {
namespace {

// Aerodynamics from a YAML case (cases/aero_rotor): modes at its rotor speed and wind, a Campbell
// diagram over the rotor speed with the aeroelastic damping, and `--set` on the wind block.
const std::string kYamlAero = "cases/aero_rotor/aero_rotor.yaml";

TEST(CliAero, YamlCaseModesAndCampbellInWind) {
  const auto modes = whirl("modes " + kYamlAero + " --format csv");
  ASSERT_EQ(modes.code, 0) << modes.err;
  EXPECT_NE(modes.out.find("flap"), std::string::npos) << modes.out;
  const auto dir = freshDir("yaml_aero_campbell");
  const auto r = whirl("campbell " + kYamlAero + " --rpm 4:4:12 --no-plot --out '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(dir / "campbell.csv");
  EXPECT_NE(csv.find("flap"), std::string::npos) << csv;
  const auto gust = whirl("modes " + kYamlAero + " --set wind.speed=11 --format csv");
  EXPECT_EQ(gust.code, 0) << gust.err;
  EXPECT_NE(gust.out, modes.out);  // the wind reaches the aeroelastic damping
}

TEST(CliAero, YamlCaseSteadyAndCampbellAlongTheWind) {
  // The case's `generator:` (ServoDyn's law): trimmed below and above rated as an OpenFAST deck.
  const auto dir = freshDir("yaml_aero_steady");
  const auto r = whirl("steady " + kYamlAero + " --wind 6:6:18 --no-plot --out '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(dir / "steady.csv");
  EXPECT_NE(csv.find(",below rated\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",above rated\n"), std::string::npos) << csv;
  const auto c = whirl("campbell " + kYamlAero + " --wind 6:4:14 --no-plot --out '" + dir.string() + "'");
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(slurp(dir / "campbell.csv").find(",10,blade"), std::string::npos);  // the wind-speed column
}

TEST(CliAero, YamlCaseMissingAirfoilNamesTheKey) {
  const auto r = whirl("modes " + kYamlAero + " --set 'aero.airfoils=[nope.dat]'");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("aero_rotor.yaml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("aero.airfoils[0]: cannot open the airfoil file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace whirl::test

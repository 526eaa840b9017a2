// The files of `whirl export` as the field's tools read them, and `whirl lin` on sets of files (issue
// 41): deterministic `.lin` bytes, the aeroelastic NREL 5MW's `.lin` with InflowWind's wind first and
// OpenFAST's channel texts, grouping by root name, the warning below 3 azimuths, --out and --format
// honoured, and errors that name the failing operating point.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "tests/cli/cli_support.hpp"
#include "tests/support/lin_rules_reader.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

const std::string kFst = "cases/nrel5mw/Main_Onshore.fst";
const std::string kAero = "cases/nrel5mw/Main_Aero.fst";

// Two runs write the same bytes: no time stamp in the header (issue 48, item 6).
TEST(CliInterop, LinFilesAreTheSameBytesTwice) {
  const auto a = test::freshDir("interop_det_a"), b = test::freshDir("interop_det_b");
  for (const auto& d : {a, b}) {
    const auto r = test::whirl("export " + kFst + " --rpm 9 --azimuths 3 --format lin --out " + d.string());
    ASSERT_EQ(r.code, 0) << r.err;
  }
  for (int k = 1; k <= 3; ++k) {
    const std::string name = "statespace." + std::to_string(k) + ".lin";
    EXPECT_EQ(test::slurp(a / name), test::slurp(b / name)) << name;
  }
}

// A failing point of a sweep names its rotor speed, wind speed, pitch and azimuth (issue 41): schedule
// row 2 asks for 1e200 rpm.
TEST(CliInterop, ErrorsNameTheOperatingPoint) {
  const auto dir = test::freshDir("interop_errors");
  const std::string bad = "tests/mpi/export_schedule_bad.csv";
  for (const std::string& cmd : {"export " + kFst + " --format mat --azimuths 4 --schedule " + bad,
                                 "campbell " + kFst + " --azimuths 4 --no-plot --schedule " + bad}) {
    const auto r = test::whirl(cmd + " --out " + dir.string());
    EXPECT_NE(r.code, 0) << cmd;
    EXPECT_THAT(r.err, HasSubstr("operating point 2 (1e+200 rpm, pitch 0 deg, azimuth 0 deg): ")) << cmd;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// `whirl lin`: the files of two operating points in one call (their root names keep them apart), the
// Campbell table in --format on stdout, the files where --out says; one point's modes to --out too;
// fewer than 3 azimuths of a turning rotor warned about.
TEST(CliInterop, LinGroupsByRootNameAndHonoursOutAndFormat) {
  const auto dir = test::freshDir("interop_lin");
  const auto ex = test::whirl("export " + kFst +
                              " --schedule tests/mpi/export_schedule.csv --azimuths 3 --format lin "
                              "--out " +
                              (dir / "lin").string());
  ASSERT_EQ(ex.code, 0) << ex.err;
  std::string files;
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir / "lin"))
    if (e.path().extension() == ".lin") files += " " + e.path().string(), ++n;
  ASSERT_GE(n, 6);
  const auto r = test::whirl("lin" + files + " --format csv --no-plot --out " + (dir / "campbell").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr(std::to_string(n / 3) + " operating points from " + std::to_string(n) + " files"));
  EXPECT_TRUE(fs::exists(dir / "campbell" / "campbell.csv"));
  EXPECT_EQ(r.out, test::slurp(dir / "campbell" / "campbell.csv"));

  const std::string one = " " + (dir / "lin" / "statespace_01.1.lin").string() + " " +
                          (dir / "lin" / "statespace_01.2.lin").string();
  const auto two = test::whirl("lin" + one + " --format json --out " + (dir / "one").string());
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_THAT(two.err, HasSubstr("only 2 azimuths"));
  EXPECT_TRUE(fs::exists(dir / "one" / "modes.json"));
  const auto modes = nlohmann::json::parse(test::slurp(dir / "one" / "modes.json"));
  EXPECT_FALSE(modes.at("modes").empty());
}

// The aeroelastic NREL 5MW at 12 to 16 m/s (trimmed): every file readable by the rules of the field's
// readers, InflowWind's wind speed the first input with the point's value, the header's wind speed and
// module list, ROSCO's channels among the outputs with OpenFAST's texts (tests/data/openfast/decks/lin/
// Standstill.1.lin, tests/data/openfast-lin/ua4-dbemt3/states_inputs.txt).
TEST(CliInteropSlow, AeroelasticLinFilesHaveOpenFastsChannels) {
  const auto dir = test::freshDir("interop_aero");
  const auto r = test::whirl("export " + kAero + " --wind 12:2:16 --azimuths 3 --format lin --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const double winds[] = {12, 14, 16};
  for (int j = 1; j <= 3; ++j)
    for (int k = 1; k <= 3; ++k) {
      const auto path = dir / ("statespace_0" + std::to_string(j) + "." + std::to_string(k) + ".lin");
      const test::RulesLin f = test::readLinByOpenFastRules(test::slurp(path));
      EXPECT_EQ(f.header.at("Wind Speed"), winds[j - 1]) << path;
      EXPECT_GT(f.header.at("Rotor Speed"), 1.0) << path;  // trimmed near rated, 12.1 rpm
      ASSERT_FALSE(f.u.empty());
      EXPECT_EQ(f.u[0].description, "IfW Extended input: horizontal wind speed (steady/uniform wind), m/s");
      EXPECT_EQ(f.u[0].op, winds[j - 1]);
      EXPECT_EQ(f.lines[2], " linked with  ElastoDyn; InflowWind; AeroDyn; ServoDyn");
      std::set<std::string> y;
      for (const auto& row : f.y) y.insert(row.description);
      for (const char* d : {"AD RtSpeed, (rpm)", "ED BldPitch1, (deg)", "ED BldPitch2, (deg)", "ED BldPitch3, (deg)",
                            "ED TwrBsMyt, (kN-m)", "ED NcIMURAys, (deg/s^2)", "ED GenSpeed, (rpm)"})
        EXPECT_TRUE(y.count(d)) << d << " in " << path;
      EXPECT_EQ(f.matrices.count("D"), 1u);
    }
}

}  // namespace
}  // namespace whirl

// Campbell diagrams side by side (src/writers/campbell_side_by_side.hpp) and the campbell.csv reader they
// draw from (src/writers/campbell_csv_input.hpp): points and gaps read back, the script's columns, shared
// axes, styles and quoting, the models' table, and bad labels refused before anything is written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "src/base/error.hpp"
#include "src/writers/campbell_side_by_side.hpp"
#include "test_util.hpp"

namespace whirl {
namespace {

namespace fs = std::filesystem;

// Two wind speeds; "edge 1 BW" skips the first point, and "flap 1 BW" has a quote in no name but the
// second result's extra line "it's" has one.
const char* const kQuasiSteady =
    "rpm,wind_speed,mode,freq_hz,damping_ratio\n"
    "6,8,flap 1 BW,0.6,0.5\n"
    "6,8,tower FA 1,0.32,0.05\n"
    "9,12,flap 1 BW,0.62,0.8\n"
    "9,12,tower FA 1,0.33,0.06\n"
    "9,12,edge 1 BW,1.1,0.02\n";
const char* const kUnsteady =
    "rpm,wind_speed,mode,freq_hz,damping_ratio\n"
    "6,8,flap 1 BW,0.7,0.3\n"
    "6,8,it's,2.5,-0.01\n"
    "9,12,flap 1 BW,0.9,0.7\n"
    "9,12,edge 1 BW,1.1,0.015\n";

std::vector<SideBySideColumn> twoColumns(const test::TempDir& tmp) {
  return {{"quasi-steady", readCampbellCsv(tmp.write("qs.csv", kQuasiSteady))},
          {"UA 'HGM'", readCampbellCsv(tmp.write("ua.csv", kUnsteady))}};
}

TEST(CampbellCsvInput, ReadsPointsLinesAndGaps) {
  test::TempDir tmp;
  const CampbellCsvResult r = readCampbellCsv(tmp.write("c.csv", kQuasiSteady));
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[1].rpm, 9);
  EXPECT_EQ(r.points[1].wind_speed, 12);
  ASSERT_EQ(r.lines.size(), 3u);
  EXPECT_EQ(r.lines[2].name, "edge 1 BW");
  ASSERT_EQ(r.lines[2].modes.size(), 1u);
  EXPECT_FALSE(r.lines[2].at(0).has_value());  // the line skips the first point
  EXPECT_EQ(r.lines[2].at(1)->damping_ratio, 0.02);
  EXPECT_EQ(r.lines[0].at(0)->freq_hz, 0.6);
}

TEST(CampbellCsvInput, RepeatedLineStartsANewPointAtTheSameSpeeds) {
  test::TempDir tmp;
  const CampbellCsvResult r = readCampbellCsv(
      tmp.write("c.csv", "rpm,wind_speed,mode,freq_hz,damping_ratio\n5,,a,1,0\n5,,a,2,0\n5,,b,3,0\n"));
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_FALSE(r.points[0].wind_speed.has_value());
  EXPECT_EQ(r.lines[0].at(1)->freq_hz, 2);
  EXPECT_FALSE(r.lines[1].at(0).has_value());
}

// Every row a new point and a new line: storage and work follow the rows, not points × lines (20000² modes
// held densely would be 9.6 GB).
TEST(CampbellCsvInput, ManyPointsAndLinesStayLinear) {
  test::TempDir tmp;
  std::string text = "rpm,wind_speed,mode,freq_hz,damping_ratio\n";
  for (int i = 0; i < 20000; ++i) text += std::to_string(i) + ",8,line " + std::to_string(i) + ",1,0.01\n";
  const CampbellCsvResult r = readCampbellCsv(tmp.write("many.csv", text));
  ASSERT_EQ(r.points.size(), 20000u);
  ASSERT_EQ(r.lines.size(), 20000u);
  EXPECT_EQ(r.lines[19999].at(19999)->freq_hz, 1);
  const std::vector<SideBySideColumn> columns = {{"many", r}};
  SideBySideOptions opt;
  opt.versus_wind_speed = false;
  EXPECT_EQ(aeroModelsCsv(columns, false), "rpm,mode,freq_hz many,damping_ratio many\n");
  EXPECT_NE(sideBySideGnuplotScript(columns, opt).find("index 19999 "), std::string::npos);
}

TEST(CampbellCsvInput, BadFilesNameFileLineAndColumn) {
  test::TempDir tmp;
  auto message = [&](const std::string& text) {
    try {
      readCampbellCsv(tmp.write("bad.csv", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("rpm,wind_speed,mode,freq_hz\n1,,a,1\n").find("bad.csv:1: damping_ratio: column missing"),
            std::string::npos);
  EXPECT_NE(message("rpm,wind_speed,mode,freq_hz,damping_ratio\n1,,a,1,0\nx,,a,1,0\n")
                .find("bad.csv:3: rpm: expected a finite number"),
            std::string::npos);
  EXPECT_NE(message("rpm,wind_speed,mode,freq_hz,damping_ratio\n1,inf,a,1,0\n").find("bad.csv:2: wind_speed:"),
            std::string::npos);
  EXPECT_NE(message("rpm,wind_speed,mode,freq_hz,damping_ratio\n1,,a,1,zero\n").find("bad.csv:2: damping_ratio:"),
            std::string::npos);
  EXPECT_NE(message("rpm,wind_speed,mode,freq_hz,damping_ratio\n1,,a\x01,1,0\n").find("bad.csv:2: mode:"),
            std::string::npos);
  EXPECT_NE(message("rpm,wind_speed,mode,freq_hz,damping_ratio\n").find("bad.csv: no Campbell rows"),
            std::string::npos);
  EXPECT_THROW(readCampbellCsv((tmp.path / "missing.csv").string()), InputError);
}

TEST(CampbellSideBySide, DataBlocksPerLineWithGaps) {
  test::TempDir tmp;
  const std::string dat = sideBySideData(twoColumns(tmp)[0].result);
  EXPECT_NE(dat.find("# index 0: flap 1 BW\n6 8 0.6 0.5\n9 12 0.62 0.8\n\n\n# index 1: tower FA 1\n"),
            std::string::npos)
      << dat;
  EXPECT_NE(dat.find("# index 2: edge 1 BW\n9 12 1.1 0.02\n"), std::string::npos) << dat;
}

TEST(CampbellSideBySide, ScriptHasOneColumnPerResultWithSharedAxesAndOneKey) {
  test::TempDir tmp;
  const auto columns = twoColumns(tmp);
  const std::string g = sideBySideGnuplotScript(columns);
  // Labels and line names reach Gnuplot single-quoted only ('' for a quote).
  EXPECT_NE(g.find("set title 'quasi-steady'\n"), std::string::npos) << g;
  EXPECT_NE(g.find("set title 'UA ''HGM'''\n"), std::string::npos) << g;
  EXPECT_NE(g.find("title 'it''s'"), std::string::npos) << g;
  // The same axes everywhere: ranges as variables, set once from every column's data (the highest line
  // 2.5 Hz x 1.05 rounded up; damping -1 % below 0, 80 % x 1.05 rounded up).
  EXPECT_NE(g.find("xmin = 8; xmax = 12\n"), std::string::npos) << g;
  EXPECT_NE(g.find("fmax = 2.8 "), std::string::npos) << g;
  EXPECT_NE(g.find("dmin = -1.1; dmax = 85 "), std::string::npos) << g;
  auto count = [&](const std::string& s) {
    std::size_t n = 0;
    for (std::size_t at = g.find(s); at != std::string::npos; at = g.find(s, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("set yrange [0:fmax]"), 2u);
  EXPECT_EQ(count("set yrange [dmin:dmax]"), 2u);
  EXPECT_EQ(count("'campbell_side_by_side_1.dat' index"), 6u);  // 3 lines, 2 panels
  EXPECT_EQ(count("'campbell_side_by_side_2.dat' index"), 6u);
  // One style per name, the same in both columns: flap 1 BW is style 1 in column 2 too.
  EXPECT_NE(g.find("'campbell_side_by_side_2.dat' index 0 using xcol:3 with linespoints ls 1 title 'flap 1 BW'"),
            std::string::npos)
      << g;
  EXPECT_EQ(count("set style line "), 4u);
  // The one key (last column) lists the line drawn in column 1 only as an empty entry.
  EXPECT_NE(g.find("NaN with linespoints ls 2 title 'tower FA 1'"), std::string::npos) << g;
  EXPECT_EQ(count("title 'tower FA 1'"), 1u);
  EXPECT_EQ(count("set key at screen"), 1u);
  EXPECT_NE(g.find("xcol = 2 "), std::string::npos);
}

TEST(CampbellSideBySide, MaxFrequencyLeavesHigherLinesOut) {
  test::TempDir tmp;
  SideBySideOptions opt;
  opt.max_freq_hz = 2;
  opt.max_damping_percent = 20;
  const std::string g = sideBySideGnuplotScript(twoColumns(tmp), opt);
  EXPECT_EQ(g.find("it''s"), std::string::npos) << g;
  EXPECT_NE(g.find("fmax = 2 "), std::string::npos) << g;
  EXPECT_NE(g.find("dmax = 20 "), std::string::npos) << g;
}

TEST(CampbellSideBySide, ModelsTableSideBySide) {
  test::TempDir tmp;
  EXPECT_EQ(aeroModelsCsv(twoColumns(tmp)),
            "wind_speed_m_s,mode,freq_hz quasi-steady,damping_ratio quasi-steady,freq_hz UA 'HGM',"
            "damping_ratio UA 'HGM'\n"
            "8,tower FA 1,0.32,0.05,,\n"
            "8,flap 1 BW,0.6,0.5,0.7,0.3\n"
            "12,tower FA 1,0.33,0.06,,\n"
            "12,flap 1 BW,0.62,0.8,0.9,0.7\n"
            "12,edge 1 BW,1.1,0.02,1.1,0.015\n");
}

TEST(CampbellSideBySide, WritesTheSetAndTheScriptRuns) {
  test::TempDir tmp;
  const std::string dir = (tmp.path / "out").string();
  SideBySideOptions opt;
  opt.render = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  const auto files = writeCampbellSideBySide(twoColumns(tmp), dir, opt);
  for (const char* name :
       {"campbell_side_by_side_1.dat", "campbell_side_by_side_2.dat", "campbell_side_by_side.gp", "aero_models.csv"})
    EXPECT_TRUE(fs::exists(fs::path(dir) / name)) << name;
  if (!opt.render) GTEST_SKIP() << "gnuplot is not installed: the script was not run";
  ASSERT_EQ(files.size(), 6u);
  EXPECT_EQ(test::slurp(dir + "/campbell_side_by_side.png").substr(1, 3), "PNG");
  EXPECT_NE(test::slurp(dir + "/campbell_side_by_side.svg").find("<svg"), std::string::npos);
}

TEST(CampbellSideBySide, BadLabelsWriteNothing) {
  test::TempDir tmp;
  const std::string dir = (tmp.path / "out").string();
  SideBySideOptions opt;
  opt.render = false;
  for (const std::string& label :
       {std::string("two\nlines"), std::string("bad \xff byte"), std::string(""), std::string("quasi-steady")}) {
    auto columns = twoColumns(tmp);
    columns[1].label = label;
    try {
      writeCampbellSideBySide(columns, dir, opt);
      ADD_FAILURE() << "no error for the label '" << label << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--label: ", 0), 0u) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir)) << label;
  }
}

TEST(CampbellSideBySide, VersusWindNeedsEveryWindSpeed) {
  test::TempDir tmp;
  std::vector<SideBySideColumn> columns = {
      {"rpm sweep", readCampbellCsv(tmp.write("c.csv", "rpm,wind_speed,mode,freq_hz,damping_ratio\n5,,a,1,0\n"))}};
  SideBySideOptions opt;
  opt.render = false;
  EXPECT_THROW(writeCampbellSideBySide(columns, (tmp.path / "out").string(), opt), InputError);
  opt.versus_wind_speed = false;
  EXPECT_NO_THROW(writeCampbellSideBySide(columns, (tmp.path / "out").string(), opt));
  EXPECT_EQ(aeroModelsCsv(columns, false), "rpm,mode,freq_hz rpm sweep,damping_ratio rpm sweep\n");
}

}  // namespace
}  // namespace whirl

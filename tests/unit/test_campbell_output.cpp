// Campbell output: exact CSV, JSON with every mode, Gnuplot data and a standalone script, atomic
// and all-or-nothing writes; tracking on a realistic synthetic turbine.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "src/base/error.hpp"
#include "src/writers/campbell_output.hpp"
#include "test_util.hpp"
#include "tests/support/synthetic_campbell.hpp"

namespace whirl {
namespace {

namespace fs = std::filesystem;

Mode mode(double f, double zeta, const std::string& name, Eigen::Vector2cd shape) {
  Mode m;
  m.freq_hz = f;
  m.damping_ratio = zeta;
  m.damped_freq_hz = f * std::sqrt(1 - zeta * zeta);
  m.name = name;
  m.shape = shape;
  m.participation = shape.cwiseAbs2() / shape.squaredNorm();
  return m;
}

/// Two points (the second without wind speed or pitch), two lines; "b, c" is absent at point 1.
CampbellDiagram small() {
  CampbellDiagram d;
  d.title = "small \"quoted\" case";
  CampbellPoint p0, p1;
  p0.rpm = 5;
  p0.wind_speed = 8.5;
  p0.pitch_deg = 0.25;
  p0.coordinates = p1.coordinates = {"x", "y"};
  p0.modes = {mode(0.1, 0.01, "a", {1, 0}), mode(1.0 / 3, 0.02, "b, c", {0, 1})};
  p1.rpm = 10;
  p1.modes = {mode(0.2, 0.03, "a", {1, 0.1})};
  d.points = {p0, p1};
  d.lines = {{"a", {0, 0}}, {"b, c", {1, -1}}};
  return d;
}

bool haveGnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

TEST(CampbellOutput, CsvHeaderAndRowsExactly) {
  EXPECT_EQ(campbellCsv(small()),
            "rpm,wind_speed,mode,freq_hz,damping_ratio\n"
            "5,8.5,a,0.1,0.01\n"
            "5,8.5,\"b, c\",0.3333333333333333,0.02\n"
            "10,,a,0.2,0.03\n");
}

TEST(CampbellOutput, JsonParsesAndHasEveryMode) {
  const auto d = small();
  const auto j = nlohmann::json::parse(campbellModesJson(d));
  EXPECT_EQ(j["title"], d.title);
  EXPECT_EQ(j["lines"], (nlohmann::json{"a", "b, c"}));
  ASSERT_EQ(j["points"].size(), 2u);
  EXPECT_EQ(j["points"][0]["wind_speed"], 8.5);
  EXPECT_EQ(j["points"][0]["pitch_deg"], 0.25);
  EXPECT_TRUE(j["points"][1]["wind_speed"].is_null());
  EXPECT_TRUE(j["points"][1]["pitch_deg"].is_null());
  for (std::size_t p = 0; p < 2; ++p) {
    const auto& modes = j["points"][p]["modes"];
    ASSERT_EQ(modes.size(), d.points[p].modes.size());
    for (std::size_t k = 0; k < modes.size(); ++k) {
      const Mode& m = d.points[p].modes[k];
      EXPECT_EQ(modes[k]["index"], k);
      EXPECT_EQ(modes[k]["freq_hz"].get<double>(), m.freq_hz);  // full precision round trip
      EXPECT_EQ(modes[k]["damped_freq_hz"].get<double>(), m.damped_freq_hz);
      EXPECT_EQ(modes[k]["damping_ratio"].get<double>(), m.damping_ratio);
      EXPECT_EQ(modes[k]["name"], m.name);
      EXPECT_EQ(modes[k]["participation"]["x"].get<double>(), m.participation[0]);
      EXPECT_EQ(modes[k]["participation"]["y"].get<double>(), m.participation[1]);
    }
  }
  EXPECT_EQ(j["points"][0]["modes"][1]["line"], "b, c");
}

TEST(CampbellOutput, GnuplotDataHasOneBlockPerLineAndBreaksAtGaps) {
  auto d = small();
  d.points.push_back(d.points[1]);
  d.points[2].rpm = 15;
  d.lines = {{"a", {0, -1, 0}}};
  EXPECT_EQ(campbellGnuplotData(d).substr(campbellGnuplotData(d).find("# index 0")),
            "# index 0: a\n5 8.5 0.1 0.01\n\n15 nan 0.2 0.03\n");
  d.lines = {{"a", {0, 0, 0}}, {"b", {-1, -1, 0}}};
  EXPECT_NE(campbellGnuplotData(d).find("0.03\n\n\n# index 1: b\n15 nan 0.2 0.03\n"), std::string::npos);
}

TEST(CampbellOutput, ScriptLabelsTheExcitationLines) {
  const auto d = test::syntheticTurbineCampbell(false);  // 0–14 rpm, up to 1.33 Hz → axis to 1.4 Hz
  const auto gp = campbellGnuplotScript(d);
  EXPECT_NE(gp.find("fmax = 1.4 "), std::string::npos);
  EXPECT_NE(gp.find("'1P' at graph 1, first 0.23333333333333334 left"), std::string::npos);  // right end
  EXPECT_NE(gp.find("'9P' at first 9.333333333333332, graph 1 center"), std::string::npos);  // top: 9·rpm/60 = 1.4
  for (const auto& l : d.lines) EXPECT_NE(gp.find("title '" + l.name + "'"), std::string::npos) << l.name;
  // Single-quoted Gnuplot strings are read verbatim: a double quote is itself, a single one doubled.
  EXPECT_NE(campbellGnuplotScript(small()).find("title = 'small \"quoted\" case'"), std::string::npos);
}

TEST(CampbellOutput, SyntheticTurbineIsTrackedThroughItsCrossings) {
  for (bool wind : {false, true}) {
    const auto d = test::syntheticTurbineCampbell(wind);
    ASSERT_EQ(d.lines.size(), 8u);
    for (const auto& l : d.lines)
      for (std::size_t p = 0; p < d.points.size(); ++p) {
        ASSERT_GE(l.mode[p], 0) << l.name;
        const std::string& n = d.points[p].modes[l.mode[p]].name;
        EXPECT_EQ(n.substr(0, l.name.size()), l.name) << "point " << p;  // "flap 1 BW / drivetrain" too
      }
  }
}

TEST(CampbellOutput, WritesAllFilesAndTheScriptRunsStandalone) {
  test::TempDir tmp;
  const std::string dir = (tmp.path / "out").string();
  const auto d = test::syntheticTurbineCampbell(true);
  CampbellPlotOptions opt;
  opt.versus_wind_speed = true;
  opt.render = false;
  const auto files = writeCampbell(d, dir, opt);
  ASSERT_EQ(files.size(), 4u);
  for (const auto& name : {"campbell.csv", "campbell_modes.json", "campbell.dat", "campbell.gp"})
    EXPECT_TRUE(fs::exists(fs::path(dir) / name)) << name;
  EXPECT_EQ(test::slurp(dir + "/campbell.csv"), campbellCsv(d));
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos);
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed: the script was not run";
  // From another working directory: the script finds campbell.dat next to itself.
  const std::string cmd = "cd / && gnuplot '" + dir + "/campbell.gp' 2>'" + (tmp.path / "gp.err").string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::slurp((tmp.path / "gp.err").string());
  for (const auto& name : {"campbell.png", "campbell.svg"}) {
    ASSERT_TRUE(fs::exists(fs::path(dir) / name)) << name;
    EXPECT_GT(fs::file_size(fs::path(dir) / name), 1000u) << name;
  }
  EXPECT_EQ(test::slurp(dir + "/campbell.png").substr(1, 3), "PNG");
  EXPECT_NE(test::slurp(dir + "/campbell.svg").find("<svg"), std::string::npos);
}

TEST(CampbellOutput, RenderReturnsTheImages) {
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  test::TempDir tmp;
  const auto files = writeCampbell(test::syntheticTurbineCampbell(false), tmp.path.string());
  ASSERT_EQ(files.size(), 6u);
  EXPECT_EQ(fs::path(files[4]).filename(), "campbell.png");
  EXPECT_EQ(fs::path(files[5]).filename(), "campbell.svg");
  for (const auto& e : fs::directory_iterator(tmp.path)) EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos);
}

TEST(CampbellOutput, FailingGnuplotIsAWarningAndTheTablesAreComplete) {
  test::TempDir tmp;
  CampbellPlotOptions opt;
  opt.gnuplot = "false";  // exits 1 like a Gnuplot that chokes on the script
  testing::internal::CaptureStderr();
  const auto files = writeCampbell(small(), tmp.path.string(), opt);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(files.size(), 4u);
  EXPECT_NE(err.find("warning"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(tmp.path / "campbell.png"));
  EXPECT_EQ(test::slurp((tmp.path / "campbell.csv").string()), campbellCsv(small()));
}

TEST(CampbellOutput, UnwritableFolderIsAnInputErrorAndWritesNothing) {
  test::TempDir tmp;
  const std::string blocker = tmp.write("not_a_folder", "x");
  EXPECT_THROW(writeCampbell(small(), blocker + "/out"), InputError);
  EXPECT_THROW(writeCampbell(small(), blocker), InputError);
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(tmp.path)) ++n;
  EXPECT_EQ(n, 1u);  // only the blocking file
}

TEST(CampbellOutput, InconsistentDiagramIsAnInputError) {
  test::TempDir tmp;
  auto d = small();
  CampbellPlotOptions opt;
  opt.versus_wind_speed = true;  // point 1 has no wind speed
  EXPECT_THROW(writeCampbell(d, tmp.path.string(), opt), InputError);
  d.lines[0].mode = {0};
  EXPECT_THROW(writeCampbell(d, tmp.path.string()), InputError);
  d.lines[0].mode = {0, 1};  // point 1 has one mode
  EXPECT_THROW(writeCampbell(d, tmp.path.string()), InputError);
  EXPECT_TRUE(fs::is_empty(tmp.path));
}

}  // namespace
}  // namespace whirl

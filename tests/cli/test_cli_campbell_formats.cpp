// `whirl campbell --format`: the NREL 5MW's openfast_toolbox tables and VTK animations written beside
// campbell.csv and agreeing with it; an unknown format refused before anything is computed or written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream ls(line);
    for (std::string f; std::getline(ls, f, ',');) rows.back().push_back(f);
    if (!line.empty() && line.back() == ',') rows.back().push_back("");
  }
  return rows;
}

// cases/nrel5mw/Main_Onshore.fst at 6 and 12 rpm: every line of campbell.csv is a row of
// Campbell_ModesID.csv (in the same order), and its frequency at each point is the one the toolbox's
// reader takes from Campbell_PointNN.csv (row 1, column 1 + 5 (ID − 1)); one .pvd per drawn line and point
// (with --max-freq 0.8 only the lines with a point at or below 0.8 Hz are drawn: fewer files, a fast test).
TEST(CliCampbellFormats, Nrel5mwToolboxTablesAndVtkAgreeWithCampbellCsv) {
  const fs::path out = test::freshDir("campbell_formats");
  const auto r = test::whirl(
      "campbell cases/nrel5mw/Main_Onshore.fst --rpm 6:6:12 --azimuths 4 --no-plot --max-freq 0.8 "
      "--format openfast,vtk --format hawcstab2 --out '" +
      out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  // campbell.csv: rpm,wind_speed,mode,freq_hz,damping_ratio; lines in order of first appearance.
  std::vector<std::string> lines;
  std::map<std::pair<std::string, std::string>, double> freq;  // (line, rpm) → Hz
  const auto csv = csvRows(test::slurp(out / "campbell.csv"));
  for (std::size_t i = 1; i < csv.size(); ++i) {
    if (std::find(lines.begin(), lines.end(), csv[i][2]) == lines.end()) lines.push_back(csv[i][2]);
    freq[{csv[i][2], csv[i][0]}] = std::stod(csv[i][3]);
  }
  const auto id = csvRows(test::slurp(out / "Campbell_ModesID.csv"));
  ASSERT_EQ(id.size(), 2 + lines.size());
  ASSERT_EQ(id[1], (std::vector<std::string>{"Rotor Speed (rpm)", "6", "12"}));
  std::vector<std::vector<std::vector<std::string>>> points;
  for (const char* p : {"Campbell_Point01.csv", "Campbell_Point02.csv"})
    points.push_back(csvRows(test::slurp(out / p)));
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (std::size_t p = 0; p < 2; ++p) {
      const int k = std::stoi(id[2 + l][1 + p]);
      const auto it = freq.find({lines[l], p == 0 ? "6" : "12"});
      ASSERT_EQ(k > 0, it != freq.end()) << lines[l];
      if (k > 0) {
        EXPECT_EQ(std::stod(points[p][1][1 + 5 * static_cast<std::size_t>(k - 1)]), it->second) << lines[l];
      }
    }
  EXPECT_TRUE(fs::exists(out / "Campbell_OP.csv"));
  EXPECT_TRUE(fs::exists(out / "Campbell_Summary.txt"));
  EXPECT_TRUE(fs::exists(out / "campbell.cmb"));
  int pvd = 0, vtp = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    pvd += e.path().extension() == ".pvd";
    vtp += e.path().extension() == ".vtp";
  }
  std::map<std::string, int> shown;  // line → its points, for the lines with a point at or below 0.8 Hz
  for (const auto& line : lines) {
    bool below = false;
    int count = 0;
    for (const char* rpm : {"6", "12"})
      if (const auto it = freq.find({line, rpm}); it != freq.end()) ++count, below = below || it->second <= 0.8;
    shown[line] = below ? count : 0;
  }
  int expected = 0;
  for (const auto& [line, n] : shown) expected += n;
  EXPECT_GE(expected, 8);  // tower SS/FA 1, flap 1 BW/collective/FW at both speeds
  EXPECT_EQ(pvd, expected);
  EXPECT_EQ(vtp, 16 * pvd);
  EXPECT_TRUE(fs::exists(out / "mode_tower_FA_1_p0.pvd"));
  EXPECT_TRUE(fs::exists(out / "mode_flap_1_BW_p1_15.vtp"));
  EXPECT_FALSE(fs::exists(out / "mode_tower_FA_2_p0.pvd"));  // 2.9 Hz: not drawn
}

// campbell.amp (HAWCStab2's mode amplitudes: per line 15 DOFs as magnitude and phase, normalized to the
// largest): the tower columns of the first tower modes carry their motion. The tower and the shaft are found
// by their bodies' roles, which the sweep's result once lost on its way through CBOR (modal/
// campbell_serialize.cpp): every tower and shaft column was 0 while the blade columns were right.
TEST(CliCampbellFormats, HawcStab2AmplitudesCarryTheTowerMotion) {
  const fs::path out = test::freshDir("campbell_amp");
  const auto r = test::whirl(
      "campbell cases/nrel5mw/Main_Onshore.fst --rpm 0:6:12 --azimuths 4 --no-plot "
      "--format hawcstab2 --out '" +
      out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> lines;  // in campbell.csv's order of first appearance, as the .amp's modes
  for (const auto& row : csvRows(test::slurp(out / "campbell.csv")))
    if (row.size() > 2 && row[2] != "mode" && std::find(lines.begin(), lines.end(), row[2]) == lines.end())
      lines.push_back(row[2]);
  std::istringstream amp(test::slurp(out / "campbell.amp"));
  int points = 0;
  for (std::string line; std::getline(amp, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> v;
    for (double x; ls >> x;) v.push_back(x);
    ASSERT_EQ(v.size(), 1 + 30 * lines.size()) << line;
    for (const char* name : {"tower FA 1", "tower SS 1"}) {
      const auto k = static_cast<std::size_t>(std::find(lines.begin(), lines.end(), name) - lines.begin());
      ASSERT_LT(k, lines.size()) << name;
      // TWR x and TWR y magnitudes (side-side, fore-aft); the rest of the turbine moves less in these modes.
      EXPECT_GT(std::max(v[1 + 30 * k], v[1 + 30 * k + 2]), 0.5) << name << " at " << v[0] << " rpm";
    }
    ++points;
  }
  EXPECT_EQ(points, 3);
  // The roles reach the mode-shape table of campbell_modes.json too.
  const std::string modes = test::slurp(out / "campbell_modes.json");
  EXPECT_THAT(modes, HasSubstr("\"role\": \"tower\""));
  EXPECT_THAT(modes, HasSubstr("\"role\": \"blade\""));
}

TEST(CliCampbellFormats, UnknownFormatIsRefusedAndNothingIsWritten) {
  const fs::path out = test::freshDir("campbell_bad_format") / "out";
  const auto r = test::whirl("campbell cases/nrel5mw/Main_Onshore.fst --rpm 6 --format paraview --out '" +
                             out.string() + "'");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("--format"));
  EXPECT_THAT(r.err, HasSubstr("paraview"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace whirl

// openfast_toolbox's Campbell files of a Campbell diagram (src/writers/openfast_campbell_files.hpp), read
// back by the rules of the toolbox's reader, postproMBC(csvModesIDFile=…) in
// openfast_toolbox/linearization/campbell.py (OpenFAST/openfast_toolbox): Campbell_OP.csv by
// pd.read_csv(sep=','), its first line the header, wind speeds OP.iloc[0,1:], rotor speeds OP.iloc[1,1:];
// Campbell_ModesID.csv and Campbell_PointNN.csv by pd.read_csv(sep=',', header=None), where a row with more
// fields than the first is an error ("Expected N fields"); mode names ID.iloc[2:,0], mode numbers
// ID.iloc[2:,1:] (one per point, 1-based, 0 = none); per point Fnat = P.iloc[1,1::5], Fdmp =
// P.iloc[2,1::5], Damps = P.iloc[3,1::5]; the table column of a name is name.split('-')[0].strip() with
// spaces as '_'. The state rows follow campbell_diagram_data_oneOP (campbell_data.py).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "src/writers/campbell_output.hpp"
#include "src/writers/openfast_campbell_files.hpp"
#include "test_util.hpp"

namespace whirl {
namespace {

using Table = std::vector<std::vector<std::string>>;

// pd.read_csv(sep=',', header=None) on files without quotes: split on every comma; every row at most as
// many fields as the first (pandas refuses more).
Table readCsv(const std::string& text) {
  EXPECT_EQ(text.find('"'), std::string::npos) << "the toolbox's files are not quoted";
  Table t;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::size_t start = 0;
    for (std::size_t c = line.find(','); c != std::string::npos; c = line.find(',', start)) {
      row.push_back(line.substr(start, c - start));
      start = c + 1;
    }
    row.push_back(line.substr(start));
    if (!t.empty()) {
      EXPECT_LE(row.size(), t.front().size()) << "pandas: Expected " << t.front().size() << " fields: " << line;
    }
    t.push_back(row);
  }
  return t;
}

// pandas' float parse (blanks around allowed): "nan" is NaN, anything else must be a whole number.
double number(const std::string& s) {
  std::size_t used = 0;
  const std::size_t first = s.find_first_not_of(' ');
  const std::string v = first == std::string::npos ? "" : s.substr(first, s.find_last_not_of(' ') - first + 1);
  const double x = std::stod(v, &used);
  EXPECT_EQ(used, v.size()) << "not a number: '" << s << "'";
  return x;
}

// Columns start, start + 5, … of a row (iloc[r, start::5]).
std::vector<double> every5th(const std::vector<std::string>& row, std::size_t start) {
  std::vector<double> v;
  for (std::size_t c = start; c < row.size(); c += 5) v.push_back(number(row[c]));
  return v;
}

Mode mode(double f, double zeta, Eigen::VectorXcd shape, const std::string& name) {
  Mode m;
  m.freq_hz = f;
  m.damped_freq_hz = f * std::sqrt(1 - zeta * zeta);
  m.damping_ratio = zeta;
  m.shape = std::move(shape);
  m.name = name;
  return m;
}

// Two points; the second has no mode on the line "flap 1 BW". Mode 1 is a rigid-body root (ζ = 0).
CampbellDiagram diagram(bool wind) {
  CampbellDiagram d;
  for (int p = 0; p < 2; ++p) {
    CampbellPoint pt;
    pt.rpm = 6 + 3 * p;
    if (wind) pt.wind_speed = 5 + 2 * p;
    pt.coordinates = {"tower FA 1", "flap 1 cos", "flap 1 sin"};
    Eigen::VectorXcd a(3), b(3), z(3);
    a << 1.0, -0.5, std::polar(0.3, 2 * std::numbers::pi / 3);
    b << 0.1, 1.0, 0.2;
    z << 0.0, 0.0, 1.0;
    pt.modes = {mode(0, 0, z, "rotor azimuth"), mode(0.32 + 0.001 * p, 0.02, a, "tower FA 1"),
                mode(0.7, -0.004, b, "flap 1 BW")};
    d.points.push_back(pt);
  }
  d.lines = {{"tower FA 1", {1, 1}}, {"flap 1 BW", {2, -1}}, {"rotor, azimuth - free", {0, 0}}};
  return d;
}

TEST(OpenfastCampbellFiles, ReadBackByTheToolboxRulesEqualWhirlsValues) {
  for (const bool wind : {true, false}) {
    const CampbellDiagram d = diagram(wind);
    test::TempDir tmp;
    const std::string dir = (tmp.path / "out").string();
    CampbellPlotOptions opt;
    opt.render = false;
    opt.formats = {"openfast"};
    writeCampbell(d, dir, opt);
    const auto file = [&](const std::string& name) { return test::slurp(dir + "/" + name); };

    // Campbell_OP.csv: a header row (P + 1 columns), wind speeds, rotor speeds.
    const Table op = readCsv(file("Campbell_OP.csv"));
    ASSERT_EQ(op.size(), 3u);
    ASSERT_EQ(op[0].size(), d.points.size() + 1);
    EXPECT_EQ(op[0][0], "Operating Points");
    for (std::size_t p = 0; p < d.points.size(); ++p) {
      const double ws = number(op[1][p + 1]);
      if (wind) {
        EXPECT_EQ(ws, *d.points[p].wind_speed);
      } else {
        EXPECT_TRUE(std::isnan(ws));  // the toolbox warns and numbers the points
      }
      EXPECT_EQ(number(op[2][p + 1]), d.points[p].rpm);
    }

    // Campbell_ModesID.csv: names from row 2, one mode number per point.
    const Table id = readCsv(file("Campbell_ModesID.csv"));
    ASSERT_EQ(id.size(), 2 + d.lines.size());
    EXPECT_EQ(id[1][0], wind ? "Wind Speed (mps)" : "Rotor Speed (rpm)");
    EXPECT_EQ(id[2][0], "1st Tower FA");
    EXPECT_EQ(id[3][0], "1st Blade Flap (Regressive)");
    EXPECT_EQ(id[4][0], "rotor  azimuth - free");  // the comma a space; the toolbox's column: "rotor__azimuth"
    std::set<std::string> columns;
    for (std::size_t l = 0; l < d.lines.size(); ++l) {
      const std::vector<std::string>& row = id[2 + l];
      ASSERT_EQ(row.size() - 1, d.points.size()) << "ModeIDs.shape[1] != len(WS)";
      std::string col = row[0].substr(0, row[0].find('-'));
      col = col.substr(0, col.find_last_not_of(' ') + 1);
      EXPECT_FALSE(col.empty());
      columns.insert(col);
      // Per point the line's mode read from its Point file as the toolbox does: Fnat[ID − 1].
      for (std::size_t p = 0; p < d.points.size(); ++p) {
        const Table pt = readCsv(file(openfastCampbellPointName(p)));
        const std::vector<double> fnat = every5th(pt[1], 1), fdmp = every5th(pt[2], 1), damp = every5th(pt[3], 1);
        ASSERT_EQ(fnat.size(), d.points[p].modes.size());
        const int k = std::stoi(row[p + 1]) - 1;
        EXPECT_EQ(k, d.lines[l].mode[p]) << row[0] << " at point " << p;
        if (k < 0) continue;
        const Mode& m = d.points[p].modes[static_cast<std::size_t>(k)];
        EXPECT_EQ(fnat[static_cast<std::size_t>(k)], m.freq_hz);  // full precision: equal
        EXPECT_EQ(fdmp[static_cast<std::size_t>(k)], m.damped_freq_hz);
        EXPECT_EQ(damp[static_cast<std::size_t>(k)], m.damping_ratio);
      }
    }
    EXPECT_EQ(columns.size(), d.lines.size());
  }
}

// The state rows of a mode (campbell_diagram_data_oneOP): coordinates by magnitude, largest 1; the phase
// to the leading coordinate folded into (−90°, 90°] with the magnitude's sign flipped; "has max" where
// this mode's unit-norm shape is the largest of the point's modes.
TEST(OpenfastCampbellFiles, StateRowsFollowTheToolboxsSignAndPhaseRules) {
  const CampbellDiagram d = diagram(true);
  const Table pt = readCsv(openfastCampbellPoint(d, 0));
  ASSERT_EQ(pt.size(), 5 + d.points[0].coordinates.size());
  for (const auto& row : pt) EXPECT_EQ(row.size(), 5 * d.points[0].modes.size());
  EXPECT_EQ(pt[0][0], "Mode Number:");
  EXPECT_EQ(pt[0][6], "2");
  EXPECT_EQ(pt[4][5], "Mode 2 state description");
  // Mode 2, shape (1, −0.5, 0.3 at 120°): tower FA 1 (1, 0°), flap 1 cos (0.5 at 180° → −0.5, 0°),
  // flap 1 sin (0.3 at 120° → −0.3, −60°).
  const std::size_t c = 5;
  const std::vector<std::tuple<std::string, int, double, double>> expected = {{"tower FA 1", 1, 1.0, 0.0},
                                                                              {"flap 1 cos", 0, -0.5, 0.0},
                                                                              {"flap 1 sin", 0, -0.3, -60.0}};
  for (std::size_t r = 0; r < expected.size(); ++r) {
    const auto& [name, has_max, mag, phase] = expected[r];
    EXPECT_EQ(pt[5 + r][c], name);
    EXPECT_EQ(std::stoi(pt[5 + r][c + 1]), has_max) << name;
    EXPECT_NEAR(number(pt[5 + r][c + 2]), mag, 1e-15) << name;
    EXPECT_NEAR(number(pt[5 + r][c + 3]), phase, 1e-12) << name;
  }
  // Mode 3, shape (0.1, 1, 0.2): flap 1 cos has its largest unit-norm magnitude here (0.976 vs 0.432).
  EXPECT_EQ(pt[5][10], "flap 1 cos");
  EXPECT_EQ(pt[5][11], "1");
  // Mode 1 (0, 0, 1): flap 1 sin is 1/1 here against 0.259 in mode 2.
  EXPECT_EQ(pt[5][0], "flap 1 sin");
  EXPECT_EQ(pt[5][1], "1");
}

// Campbell_Summary.txt (campbellData2TXT): '#' comment lines, then `ID ; freq ; zeta ; content` with 4 ';' fields,
// every mode of a point once; the rigid-body root (ζ = 0) under the skipped section.
TEST(OpenfastCampbellFiles, SummaryListsEveryModeOnceWithFourFields) {
  const CampbellDiagram d = diagram(true);
  std::istringstream in(openfastCampbellSummary(d));
  std::string line;
  int op = 0;
  std::set<int> ids;
  bool skipped = false;
  while (std::getline(in, line)) {
    if (line.rfind("# --- OP ", 0) == 0) {
      if (op > 0) {
        EXPECT_EQ(ids.size(), d.points[0].modes.size());
      }
      ++op, ids.clear(), skipped = false;
      EXPECT_NE(line.find(op == 1 ? "WS 5.0 - RPM 6.00" : "WS 7.0 - RPM 9.00"), std::string::npos) << line;
      continue;
    }
    if (line.rfind("# --- Skipped", 0) == 0) skipped = true;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::istringstream ls(line);
    for (std::string s; std::getline(ls, s, ';');) f.push_back(s);
    ASSERT_EQ(f.size(), 4u) << line;
    const int id = std::stoi(f[0]);
    EXPECT_TRUE(ids.insert(id).second) << line;
    const Mode& m = d.points[static_cast<std::size_t>(op - 1)].modes[static_cast<std::size_t>(id - 1)];
    EXPECT_NEAR(number(f[1]), m.freq_hz, 5e-4) << line;        // {:8.3f}
    EXPECT_NEAR(number(f[2]), m.damping_ratio, 5e-5) << line;  // {:7.4f}
    EXPECT_EQ(skipped, id == 1) << line;
    EXPECT_EQ(f[3].substr(1, m.name.size()), m.name) << line;
  }
  EXPECT_EQ(op, 2);
  EXPECT_EQ(ids.size(), d.points[1].modes.size());
}

TEST(OpenfastCampbellFiles, WhirlNamesMapToTheToolboxsNames) {
  EXPECT_EQ(campbellToolboxName("tower SS 2"), "2nd Tower SS");
  EXPECT_EQ(campbellToolboxName("edge 1 FW"), "1st Blade Edge (Progressive)");
  EXPECT_EQ(campbellToolboxName("flap 3 collective"), "3rd Blade Flap (Collective)");
  EXPECT_EQ(campbellToolboxName("drivetrain (2)"), "1st Drivetrain Torsion (2)");
  EXPECT_EQ(campbellToolboxName("platform pitch"), "Platform pitch");
  EXPECT_EQ(campbellToolboxName("yaw"), "Nacelle Yaw");
  EXPECT_EQ(campbellToolboxName("tower FA 1 / flap 1 BW"), "tower FA 1 / flap 1 BW");
}

}  // namespace
}  // namespace whirl

// Mode tracking across Campbell points: crossings follow shapes, veering follows continuity,
// lines start and end, names, and the user override file.
#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <numbers>

#include "modal/tracking.hpp"
#include "modal/tracking_overrides.hpp"
#include "src/base/error.hpp"
#include "test_util.hpp"

namespace whirl {
namespace {

using cd = std::complex<double>;

Mode mode(double f, std::vector<cd> shape, std::string name) {
  Mode m;
  m.freq_hz = m.damped_freq_hz = f;
  m.damping_ratio = 0.01;
  m.name = std::move(name);
  m.shape = Eigen::Map<Eigen::VectorXcd>(shape.data(), static_cast<Eigen::Index>(shape.size()));
  m.participation = m.shape.cwiseAbs2() / m.shape.squaredNorm();
  return m;
}

CampbellPoint point(double rpm, std::vector<Mode> modes) {
  std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  CampbellPoint p;
  p.rpm = rpm;
  for (Eigen::Index k = 0; k < (modes.empty() ? 0 : modes[0].shape.size()); ++k)
    p.coordinates.push_back("q" + std::to_string(k));
  p.modes = std::move(modes);
  return p;
}

const CampbellLine& line(const std::vector<CampbellLine>& lines, const std::string& name) {
  for (const auto& l : lines)
    if (l.name == name) return l;
  ADD_FAILURE() << "no line " << name;
  return lines.front();
}

/// Two modes with orthogonal shapes; a rises 1 → 2 Hz, b falls 2 → 1 Hz (they cross between points).
std::vector<CampbellPoint> crossing(std::vector<cd> sa = {1, 0}, std::vector<cd> sb = {0, 1}) {
  std::vector<CampbellPoint> pts;
  for (int p = 0; p < 6; ++p) pts.push_back(point(2.0 * p, {mode(1 + 0.2 * p, sa, "a"), mode(2 - 0.2 * p, sb, "b")}));
  return pts;
}

TEST(Tracking, MacOfComplexShapes) {
  Eigen::VectorXcd bw(2), fw(2);
  bw << 1, cd(0, 1);
  fw << 1, cd(0, -1);
  EXPECT_NEAR(modalAssurance(bw, fw), 0.0, 1e-15);  // a real-valued MAC would say 1
  EXPECT_NEAR(modalAssurance(bw, cd(0.3, -2) * bw), 1.0, 1e-15);
  EXPECT_EQ(modalAssurance(bw, Eigen::VectorXcd::Zero(2)), 0.0);
}

TEST(Tracking, CrossingFollowsShapesNotFrequencyOrder) {
  const auto pts = crossing();
  const auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 2u);
  for (const auto& l : lines)
    for (std::size_t p = 0; p < pts.size(); ++p) {
      ASSERT_GE(l.mode[p], 0);
      EXPECT_EQ(pts[p].modes[l.mode[p]].name, l.name) << "point " << p;
    }
  EXPECT_EQ(line(lines, "a").mode, (std::vector<int>{0, 0, 0, 1, 1, 1}));  // below b, then above
}

TEST(Tracking, CrossingWhirlModesWithComplexShapes) {
  const auto pts = crossing({1, cd(0, 1)}, {1, cd(0, -1)});  // BW and FW: |shapes| identical
  const auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(line(lines, "a").mode, (std::vector<int>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(line(lines, "b").mode, (std::vector<int>{1, 1, 1, 0, 0, 0}));
}

TEST(Tracking, VeeringFollowsShapeContinuity) {
  // Shapes rotate by 90° over the sweep while the frequencies approach and part again: the lower
  // line starts as x and ends as y. Names follow the dominant coordinate (x / y at 45°).
  std::vector<CampbellPoint> pts;
  const int n = 11;
  for (int p = 0; p < n; ++p) {
    const double t = std::numbers::pi / 2 * p / (n - 1), c = std::cos(t), s = std::sin(t);
    const double gap = 0.05 + 0.2 * std::abs(p - 5) / 5.0;
    const std::string lo = p < 5 ? "x" : p > 5 ? "y" : "x / y", hi = p < 5 ? "y" : p > 5 ? "x" : "y / x";
    pts.push_back(point(p, {mode(1.0, {c, s}, lo), mode(1.0 + gap, {-s, c}, hi)}));
  }
  const auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].mode, std::vector<int>(n, 0));
  EXPECT_EQ(lines[1].mode, std::vector<int>(n, 1));
  EXPECT_EQ(lines[0].name, "y");  // 5 × x, 5 × y: the tie goes to the name at the highest rpm
  EXPECT_EQ(lines[1].name, "x");
}

TEST(Tracking, ModeAppearingAndDisappearingStartsAndEndsALine) {
  std::vector<CampbellPoint> pts;
  for (int p = 0; p < 5; ++p) {
    std::vector<Mode> m{mode(1.0, {1, 0, 0}, "low"), mode(3.0, {0, 1, 0}, "high")};
    if (p >= 1 && p <= 3) m.push_back(mode(2.0 + 0.01 * p, {0, 0.1, 1}, "middle"));
    pts.push_back(point(p, m));
  }
  const auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].name, "low");
  EXPECT_EQ(lines[1].name, "middle");
  EXPECT_EQ(lines[2].name, "high");
  EXPECT_EQ(lines[1].mode, (std::vector<int>{-1, 1, 1, 1, -1}));
  EXPECT_EQ(lines[2].mode, (std::vector<int>{1, 2, 2, 2, 1}));
}

TEST(Tracking, UnrelatedShapesAreNotLinkedAndRigidBodyModesAreSkipped) {
  auto pts = std::vector<CampbellPoint>{point(0, {mode(1.0, {1, 0}, "a")}), point(1, {mode(1.0, {0, 1}, "a")})};
  Mode rb = mode(0, {1, 1}, "azimuth");
  rb.rigid_body = true;
  pts[0].modes.insert(pts[0].modes.begin(), rb);
  auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 2u);  // orthogonal shapes at the same frequency: two lines, same name
  EXPECT_EQ(lines[0].name, "a");
  EXPECT_EQ(lines[1].name, "a (2)");
  EXPECT_EQ(lines[0].mode, (std::vector<int>{1, -1}));
  TrackingOptions opt;
  opt.include_rigid_body = true;
  lines = trackModes(pts, opt);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].name, "azimuth");
}

// The blade elements' aerodynamic states are left out of the shapes the tracking compares (as out of the
// structural modes' names): a flap mode whose unsteady-airfoil entry grows from 0.1 to the largest of the
// shape (the tip element near a kink of its polar; the NREL 5MW with UA between 12 and 13 m/s) keeps its
// line. With the state in the MAC: 0.044, a cost of 1.0 with the frequency step, no link.
TEST(Tracking, AerodynamicStatesAreLeftOutOfTheShapes) {
  auto pts = std::vector<CampbellPoint>{point(0, {mode(1.0, {1, cd(0, 1), 0.1}, "flap 1 BW")}),
                                        point(1, {mode(1.1, {0.1, cd(0, 0.1), 1}, "flap 1 BW")})};
  for (CampbellPoint& p : pts) p.coordinates = {"flap 1 cos", "flap 1 sin", "UA x4 element 19 sin"};
  const double with_state = trackingCost(pts[0].modes[0], pts[1].modes[0]);
  EXPECT_GE(with_state, 1.0);
  const auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].name, "flap 1 BW");
  EXPECT_EQ(lines[0].mode, (std::vector<int>{0, 0}));
  pts[1].coordinates[2] = "flap 2 sin";  // a structural coordinate counts
  EXPECT_EQ(trackModes(pts).size(), 2u);
}

TEST(Tracking, ShapesOfDifferentDimensionsAreAnInputError) {
  const std::vector<CampbellPoint> pts{point(0, {mode(1.0, {1, 0}, "a")}), point(1, {mode(1.0, {1, 0, 0}, "a")})};
  EXPECT_THROW(trackModes(pts), InputError);
}

TEST(Tracking, OverrideFileRenamesAndReassigns) {
  const auto pts = crossing();
  test::TempDir tmp;
  TrackingOptions opt;
  opt.overrides_file = tmp.write("overrides.csv",
                                 "# user corrections\n"
                                 "\n"
                                 "rename, a ,\"tower, FA\"\n"
                                 "assign,4,0,tower, FA\n"  // unquoted trailing fields: see below
                                 "rename,b,edge\n");
  EXPECT_THROW(trackModes(pts, opt), InputError);  // 5 fields: the comma needs quotes
  opt.overrides_file = tmp.write("overrides.csv",
                                 "rename, a ,\"tower, FA\"\n"
                                 "assign,4,0,\"tower, FA\"\n"
                                 "rename,b,edge\n");
  const auto lines = trackModes(pts, opt);
  ASSERT_EQ(lines.size(), 2u);
  // From point 4 on the lines are exchanged: "tower, FA" takes mode 0 there (b's mode) and b's tail.
  EXPECT_EQ(line(lines, "tower, FA").mode, (std::vector<int>{0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(line(lines, "edge").mode, (std::vector<int>{1, 1, 1, 0, 1, 1}));
}

TEST(Tracking, AssignJoiningALineThatEndedRemovesTheEmptyLine) {
  // "a" exists at points 0–1, "c" (an orthogonal shape, so not linked) at 2–3.
  std::vector<CampbellPoint> pts{point(0, {mode(1.0, {1, 0}, "a")}), point(1, {mode(1.0, {1, 0}, "a")}),
                                 point(2, {mode(1.0, {0, 1}, "c")}), point(3, {mode(1.0, {0, 1}, "c")})};
  auto lines = trackModes(pts);
  ASSERT_EQ(lines.size(), 2u);
  applyTrackingOverridesText("assign,2,0,a\n", "mem.csv", pts, lines);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].name, "a");
  EXPECT_EQ(lines[0].mode, (std::vector<int>{0, 0, 0, 0}));
}

TEST(Tracking, BadOverrideRowsNameFileAndLine) {
  const auto pts = crossing();
  const auto expectError = [&](const std::string& row, const std::string& reason) {
    auto lines = trackModes(pts);
    try {
      applyTrackingOverridesText("# header\nrename,a,a\n" + row + "\n", "fix.csv", pts, lines);
      ADD_FAILURE() << "no error for: " << row;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("fix.csv:3: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  };
  expectError("swap,1,2", "unknown keyword 'swap'");
  expectError("rename,a", "expected 'rename");
  expectError("rename,nope,x", "no line named 'nope'");
  expectError("rename,a,b", "already named 'b'");
  expectError("rename,a,", "new name is empty");
  expectError("assign,1,0", "expected 'assign");
  expectError("assign,x,0,a", "point index 'x'");
  expectError("assign,-1,0,a", "point index '-1'");
  expectError("assign,1,1.5,a", "mode index '1.5'");
  expectError("assign,6,0,a", "point index 6 out of range");
  expectError("assign,1,2,a", "mode index 2 out of range");
  expectError("assign,1,0,zz", "no line named 'zz'");
  expectError("rename,\"a,b", "unterminated quote");
  TrackingOptions opt;
  opt.overrides_file = "/nonexistent/overrides.csv";
  EXPECT_THROW(trackModes(pts, opt), InputError);
}

}  // namespace
}  // namespace whirl

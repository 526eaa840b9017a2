// HAWCStab2 .cmb/.amp/.opt files of a Campbell diagram (src/writers/hawcstab2_files.hpp), read back by
// the rules of the public readers: DLR-AE CampbellViewer (campbellviewer/interfaces/hawcstab2.py:
// np.loadtxt after 1 header line for .cmb and .opt, 5 for .amp; .amp columns 1 + 30 per mode, amplitude
// then phase of 15 DOFs; .opt 5 columns) and DTU's wetb (wetb/prepost/hawcstab2.py, load_cmb: the mode
// count is the largest integer after the first ']' of the header; the operating name before the first
// '1').
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "src/writers/hawcstab2_files.hpp"
#include "src/writers/mode_shape_tables.hpp"

namespace whirl {
namespace {

using Rows = std::vector<std::vector<double>>;

// np.loadtxt: skip `header` lines, then whitespace-separated numbers ("nan" included), every row alike.
Rows loadtxt(const std::string& text, int header) {
  std::istringstream in(text);
  std::string line;
  for (int k = 0; k < header; ++k) std::getline(in, line);
  Rows rows;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    std::istringstream ls(line);
    std::vector<double> row;
    std::string tok;
    while (ls >> tok) row.push_back(std::strtod(tok.c_str(), nullptr));
    if (!rows.empty()) {
      EXPECT_EQ(row.size(), rows.front().size()) << line;
    }
    rows.push_back(row);
  }
  return rows;
}

Mode mode(double f, double zeta, std::complex<double> tower_fa, std::complex<double> flap_bw) {
  Mode m;
  m.freq_hz = f;
  m.damped_freq_hz = f * std::sqrt(1 - zeta * zeta);
  m.damping_ratio = zeta;
  BodyMotion tower;
  tower.body = "tower";
  tower.role = "tower";
  tower.nodes = {"node 1", "node 2"};
  tower.x = VecX::LinSpaced(2, 0, 80);  // dynamic size: no fixed-size 512-bit loads (GCC 12 -Warray-bounds)
  tower.position = Mat3X::Zero(3, 2);
  tower.R << 0, 0, 1, 0, -1, 0, 1, 0, 0;  // ElastoDyn's tower: x up, y = −ground Y, z = ground X
  tower.u = Eigen::MatrixXcd::Zero(2, 6);
  tower.u(1, 2) = tower_fa;  // fore-aft: body z
  tower.u(1, 1) = 0.1;       // side-side: body y = −ground Y
  m.motion.bodies.push_back(tower);
  m.motion.collective = Eigen::MatrixXcd::Zero(2, 6);
  m.motion.forward = Eigen::MatrixXcd::Zero(2, 6);
  m.motion.backward = Eigen::MatrixXcd::Zero(2, 6);
  m.motion.backward(1, 1) = flap_bw;  // flap: blade body y
  m.motion.blade_nodes = {"node 1", "node 2"};
  m.motion.blade_x = VecX::LinSpaced(2, 0, 61.5);
  return m;
}

CampbellDiagram diagram() {
  CampbellDiagram d;
  for (int p = 0; p < 2; ++p) {
    CampbellPoint pt;
    pt.rpm = 6 + 3 * p;
    pt.wind_speed = 5 + 2 * p;
    pt.pitch_deg = 0.5 * p;
    pt.modes = {mode(0.32 + 0.001 * p, 0.02, std::polar(2.0, 0.3), 0.5), mode(0.7, -0.004, 0.2, std::polar(1.0, -2.0))};
    d.points.push_back(pt);
  }
  d.lines = {{"tower FA 1", {0, 0}}, {"flap 1 BW", {1, -1}}};
  return d;
}

TEST(Hawcstab2Files, CmbReadsBackByTheReadersRules) {
  const CampbellDiagram d = diagram();
  const std::string cmb = hawcstab2Cmb(d);
  // wetb: the operating name before the first '1', the mode count after the first ']'.
  const std::string header = cmb.substr(0, cmb.find('\n'));
  EXPECT_EQ(header.substr(0, header.find('1')).find("# Wind [m/s]"), 2u);
  std::istringstream after(header.substr(header.find(']') + 1));
  int nr = 0, v = 0;
  while (after >> v) nr = std::max(nr, v);
  ASSERT_EQ(nr, 2);
  const Rows r = loadtxt(cmb, 1);
  ASSERT_EQ(r.size(), 2u);
  ASSERT_EQ(r[0].size(), 3u * 2 + 1);  // CampbellViewer: aeroelastic layout, frequency, damping, real part
  for (int p = 0; p < 2; ++p) {
    EXPECT_DOUBLE_EQ(r[p][0], *d.points[p].wind_speed);
    for (int k = 0; k < 2; ++k) {
      const int idx = d.lines[k].mode[p];
      if (idx < 0) {
        EXPECT_TRUE(std::isnan(r[p][1 + k]) && std::isnan(r[p][3 + k]) && std::isnan(r[p][5 + k]));
        continue;
      }
      const Mode& m = d.points[p].modes[idx];
      // Six significant digits (HAWCStab2's E14.6, mantissa 0.1 … 1): half a unit of the sixth is at
      // most 5e-6 of the value.
      EXPECT_NEAR(r[p][1 + k], m.damped_freq_hz, 5e-6 * m.damped_freq_hz);
      EXPECT_NEAR(r[p][3 + k], 100 * m.damping_ratio, 5e-6 * std::abs(100 * m.damping_ratio));
      const double re = -m.damping_ratio * 2 * std::numbers::pi * m.freq_hz;
      EXPECT_NEAR(r[p][5 + k], re, 5e-6 * std::abs(re));
    }
  }
}

TEST(Hawcstab2Files, AmpReadsBackByCampbellViewersRules) {
  const CampbellDiagram d = diagram();
  const std::string amp = hawcstab2Amp(d);
  std::istringstream in(amp);
  std::string l1, l2, l3, l4, l5;
  std::getline(in, l1), std::getline(in, l2), std::getline(in, l3), std::getline(in, l4), std::getline(in, l5);
  EXPECT_EQ(l1, "# Modal MAGNITUDE | PHASE of the following DOFs");
  EXPECT_EQ(l3.rfind("# Mode number:", 0), 0u);
  EXPECT_EQ(l4.rfind("# Column num.:", 0), 0u);
  EXPECT_NE(l5.find("TWR x [m]   phase [deg]"), std::string::npos);
  const Rows r = loadtxt(amp, 5);
  ASSERT_EQ(r.size(), 2u);
  const int sensors = 15;
  ASSERT_EQ(r[0].size(), 1u + 2 * sensors * 2);
  const int modes = static_cast<int>((r[0].size() - 1) / sensors / 2);
  ASSERT_EQ(modes, 2);
  // Point 0, mode 1: tower top side-side 0.1 (ground −Y → phase 180), fore-aft 2 at 0.3 rad, BW flap 0.5;
  // amplitudes over the largest (2).
  const auto amp0 = [&](int mode, int dof) { return r[0][static_cast<std::size_t>(mode * sensors * 2 + 1 + 2 * dof)]; };
  const auto ph0 = [&](int mode, int dof) { return r[0][static_cast<std::size_t>(mode * sensors * 2 + 2 + 2 * dof)]; };
  EXPECT_NEAR(amp0(0, 0), 0.05, 5e-8);
  EXPECT_NEAR(std::abs(ph0(0, 0)), 180.0, 5e-4);
  EXPECT_NEAR(amp0(0, 1), 1.0, 5e-7);
  EXPECT_NEAR(ph0(0, 1), 0.3 * 180 / std::numbers::pi, 5e-5);  // 0.171887E+02: ±5e-5
  EXPECT_NEAR(amp0(0, 10), 0.25, 5e-8);                        // BW flap
  EXPECT_NEAR(amp0(0, 9), 0.0, 1e-12);                         // Sym flap
  // Mode 2: BW flap 1 is the largest, at −2 rad.
  EXPECT_NEAR(amp0(1, 10), 1.0, 5e-7);
  EXPECT_NEAR(ph0(1, 10), -2 * 180 / std::numbers::pi, 5e-4);  // -0.114592E+03: ±5e-4
  // Point 1 has no mode on line 2: nan.
  EXPECT_TRUE(std::isnan(r[1][1 + 2 * sensors]));
}

TEST(Hawcstab2Files, OptHasFiveColumnsAndThePointCount) {
  const CampbellDiagram d = diagram();
  const std::string opt = hawcstab2Opt(d);
  EXPECT_EQ(std::stoi(opt.substr(0, opt.find(' ', opt.find_first_not_of(' ')))), 2);
  const Rows r = loadtxt(opt, 1);
  ASSERT_EQ(r.size(), 2u);
  ASSERT_EQ(r[0].size(), 5u);
  EXPECT_DOUBLE_EQ(r[1][0], 7.0);
  EXPECT_DOUBLE_EQ(r[1][1], 0.5);
  EXPECT_DOUBLE_EQ(r[1][2], 9.0);
}

TEST(Hawcstab2Files, FortranNumbersHaveHawcstab2sForm) {
  EXPECT_EQ(fortranE(1.0), "  0.100000E+01");
  EXPECT_EQ(fortranE(-123.404), " -0.123404E+03");
  EXPECT_EQ(fortranE(0.000535), "  0.535000E-03");
  EXPECT_EQ(fortranE(0.0), "  0.000000E+00");
  EXPECT_EQ(fortranE(9.9999996), "  0.100000E+02");
  EXPECT_EQ(fortranE(std::nan("")), "           nan");
}

}  // namespace
}  // namespace whirl

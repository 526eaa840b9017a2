// Multiblade transform of OpenFAST .lin files (tests/data/openfast-lin, see tests/data/openfast/README.md)
// against the MBC3 [Bir2010] result of the same files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "modal/eigen.hpp"
#include "modal/mbc_lin.hpp"
#include "src/base/error.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "tests/support/openfast_9rpm_mbc3.hpp"
#include "tests/unit/test_util.hpp"

namespace {

const std::string kData = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast-lin/";

struct Point {
  whirl::MbcResult mbc;
  std::vector<whirl::ModalFrequency> modes;  ///< Im λ > 0, sorted by natural frequency
  std::vector<double> real_roots_hz;         ///< |λ|/2π of the real eigenvalues, ascending
};

/// MBC of the given files and eigenanalysis of the averaged A_NR.
Point campbellPoint(const std::vector<std::string>& files) {
  std::vector<whirl::MbcSample> samples;
  whirl::MbcLayout layout;
  for (const auto& f : files) {
    const auto lin = whirl::readOpenFastLin(kData + f);
    if (samples.empty()) layout = whirl::mbcLayoutFromLin(lin);
    samples.push_back(whirl::mbcSampleFromLin(lin));
  }
  Point p;
  p.mbc = whirl::mbcAverage(layout, samples);
  const auto eig = whirl::eigenStandard(p.mbc.A);
  for (Eigen::Index j = 0; j < eig.values.size(); ++j) {
    if (eig.values(j).imag() > 0) p.modes.push_back(whirl::modalFrequency(eig.values(j)));
    if (eig.values(j).imag() == 0) p.real_roots_hz.push_back(whirl::modalFrequency(eig.values(j)).freq_hz);
  }
  std::sort(p.modes.begin(), p.modes.end(), [](const auto& a, const auto& b) { return a.freq_hz < b.freq_hz; });
  std::sort(p.real_roots_hz.begin(), p.real_roots_hz.end());
  return p;
}

// Source: MBC3 of tests/data/openfast-lin/rotating-9rpm/Main.{1,12,24}.lin (tests/support/
// openfast_9rpm_mbc3.hpp), printed with 4 decimals. Tolerance: half a unit of the 4th decimal, the
// rounding of the printed values.
TEST(MbcOpenFast, Rotating9rpmMatchesMbc3) {
  const auto& ref = whirl::test::kOpenFast9rpmMbc3;
  const double tol = 0.5e-4 + 1e-12;
  const auto p = campbellPoint({"rotating-9rpm/Main.1.lin", "rotating-9rpm/Main.12.lin", "rotating-9rpm/Main.24.lin"});
  ASSERT_EQ(p.modes.size(), std::size(ref));
  for (std::size_t i = 0; i < std::size(ref); ++i) {
    EXPECT_NEAR(p.modes[i].freq_hz, ref[i].freq_hz, tol) << ref[i].mode;
    EXPECT_NEAR(p.modes[i].damping_ratio, ref[i].damping_ratio, tol) << ref[i].mode;
  }
  // Same source, "conditions" column: the generator azimuth gives two real roots, 0.0001 and 0.0151 Hz.
  ASSERT_EQ(p.real_roots_hz.size(), 2u);
  EXPECT_NEAR(p.real_roots_hz[0], 0.0001, tol);
  EXPECT_NEAR(p.real_roots_hz[1], 0.0151, tol);

  // States 2-4 (flap 1 of blades 1-3) became collective, cosine, sine; their rates too.
  EXPECT_EQ(whirl::toString(p.mbc.states[0]), "fixed");
  EXPECT_EQ(whirl::toString(p.mbc.states[1]), "collective");
  EXPECT_EQ(whirl::toString(p.mbc.states[2]), "cos");
  EXPECT_EQ(whirl::toString(p.mbc.states[13]), "sin");
  EXPECT_EQ(p.mbc.samples.size(), 3u);
}

TEST(MbcOpenFast, LayoutFromLinFile) {
  const auto lin = whirl::readOpenFastLin(kData + "ws03/ws03.0.1.lin");
  const auto L = whirl::mbcLayoutFromLin(lin);
  EXPECT_EQ(L.num_blades, 3);
  // 6 fixed DOFs (tower 4, yaw, drivetrain), then flap 1, edge 1, flap 2 of blades 1-3; rates follow.
  const std::vector<int> dofs = {-1, -1, -1, -1, -1, -1, 0, 1, 2, 0, 1, 2, 0, 1, 2};
  for (int i = 0; i < 15; ++i) {
    EXPECT_EQ(L.state_blade[i], dofs[i]) << i;
    EXPECT_EQ(L.state_blade[15 + i], dofs[i]) << i;
    EXPECT_EQ(L.velocity_of[i], -1);
    EXPECT_EQ(L.velocity_of[15 + i], i);
  }
  EXPECT_TRUE(L.input_blade.empty() && L.output_blade.empty());
  // Drivetrain acceleration from the state-derivative table (no generator DOF in this model).
  EXPECT_DOUBLE_EQ(whirl::mbcSampleFromLin(lin).rotor_acceleration, 1.177954400191e-4);
}

// ws03 has no reference table; the transform must remove most of the azimuth dependence of A
// (what is left is gravity and wind shear, truly periodic in the fixed frame).
TEST(MbcOpenFast, Ws03AzimuthDependenceMostlyRemoved) {
  const std::vector<std::string> files = {"ws03/ws03.0.1.lin", "ws03/ws03.0.13.lin", "ws03/ws03.0.34.lin"};
  const auto p = campbellPoint(files);
  std::vector<Eigen::MatrixXd> raw;
  for (const auto& f : files) raw.push_back(whirl::readOpenFastLin(kData + f).A);
  double spread_raw = 0, spread_mbc = 0;
  for (int k = 1; k < 3; ++k) {
    spread_raw = std::max(spread_raw, (raw[k] - raw[0]).norm() / raw[0].norm());
    spread_mbc = std::max(spread_mbc, (p.mbc.samples[k].A - p.mbc.samples[0].A).norm() / p.mbc.samples[0].A.norm());
  }
  EXPECT_GT(spread_raw, 0.1);
  EXPECT_LT(spread_mbc, 0.1 * spread_raw);
  // 15 DOFs: ServoDyn is off in ws03.0.fst, so the yaw DOF has no spring and gives two real roots.
  EXPECT_EQ(p.modes.size(), 14u);
  EXPECT_EQ(p.real_roots_hz.size(), 2u);
}

TEST(MbcOpenFast, BladeNumbersInDescriptions) {
  using whirl::bladeNumberInDescription;
  EXPECT_EQ(bladeNumberInDescription(
                "ED 1st flapwise bending-mode DOF of blade 2 (internal DOF index = DOF_BF(2,1)), m"),
            2);
  EXPECT_EQ(bladeNumberInDescription("ED Blade 3 pitch command, rad"), 3);
  EXPECT_EQ(bladeNumberInDescription("AD B1N3Alpha, deg"), 1);
  EXPECT_EQ(bladeNumberInDescription("BD_2 FE node 3 translational displacement in X, m"), 2);
  EXPECT_EQ(bladeNumberInDescription("ED RootMxc3, (kN-m)"), 3);
  EXPECT_EQ(bladeNumberInDescription("ED Blade root 2 pitch, rad"), 2);
  EXPECT_EQ(bladeNumberInDescription("ED Variable speed generator DOF (internal DOF index = DOF_GeAz), rad"), 0);
}

TEST(MbcOpenFast, RotatingStateWithoutBladeNamesFileAndLine) {
  whirl::test::TempDir dir;
  std::string text = whirl::test::slurp(kData + "rotating-9rpm/Main.1.lin");
  const std::string from = "1st flapwise bending-mode DOF of blade 2 (internal";
  text.replace(text.find(from), from.size(), "1st flapwise bending-mode DOF of rotor (internal");  // line 24
  const std::string path = dir.write("Main.1.lin", text);
  const auto lin = whirl::readOpenFastLin(path);
  try {
    whirl::mbcLayoutFromLin(lin);
    FAIL() << "expected InputError";
  } catch (const whirl::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path + ":24: continuous states: rotating entry without a blade number"), std::string::npos)
        << msg;
  }
}

}  // namespace

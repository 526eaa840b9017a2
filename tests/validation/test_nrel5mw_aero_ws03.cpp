// The NREL 5MW with a free yaw at 3 m/s, 6.972 rpm against OpenFAST v2.5's linearization of the same
// ElastoDyn deck (tests/data/openfast-lin/ws03/ws03.0.{1,13,34}.lin: 15 DOFs — tower FA/SS 1–2, yaw
// without a spring, drivetrain, blade flap 1, edge 1, flap 2; rotor speed fixed, GenDOF = False).
// Its AeroDyn, InflowWind and ServoDyn files were not published; the deck here
// (tests/data/openfast/aero/ws03) gives it the OpenFAST v5 AeroDyn of tests/data/openfast/aero/v5
// (BEMT, frozen wake, quasi-steady airfoils, no tower influence) and a steady 3 m/s InflowWind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "linearize/periodic.hpp"
#include "modal/eigen.hpp"
#include "modal/mbc_lin.hpp"
#include "modal/rotor_modes.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/io/lin/openfast_lin_names.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/aero/ws03/ws03.0.fst";
const std::string kLin = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast-lin/ws03/ws03.0.";

// Source: the multiblade transform (MBC3 [Bir2010], modal/mbc_lin.hpp, checked against MBC3 in
// tests/unit/test_mbc_openfast.cpp) of ws03.0.{1,13,34}.lin averaged over their 3 azimuths (0.4°,
// 120°, 330°), eigenvalues of the averaged A, printed with 4 decimals (`whirl lin
// tests/data/openfast-lin/ws03/ws03.0.{1,13,34}.lin`). Mode names are whirl's: the 3-azimuth
// average names the 0.33 Hz tower FA mode "flap 1 collective", the 0.63 Hz drivetrain mode
// "flap 1 BW", the 2.92 Hz tower FA 2 "flap 2 FW", the 2.96 Hz tower SS 2 "edge 1 collective".
struct Ref {
  const char* mode;
  double freq_hz, damping;
};
constexpr Ref kRef[] = {{"tower SS 1", 0.3140, 0.0044},          {"tower FA 1", 0.3314, 0.0603},
                        {"drivetrain", 0.6263, 0.0248},          {"1st flap BW", 0.6880, 0.4143},
                        {"1st flap collective", 0.7063, 0.4053}, {"1st edge BW", 0.9650, 0.0340},
                        {"1st flap FW", 1.0225, 0.2033},         {"1st edge FW", 1.2163, 0.0167},
                        {"2nd flap BW", 1.9160, 0.1123},         {"2nd flap collective", 2.0153, 0.1130},
                        {"2nd flap FW", 2.5479, 0.0659},         {"tower FA 2", 2.9157, 0.0165},
                        {"tower SS 2", 2.9555, 0.0104},          {"1st edge collective / drivetrain", 3.6938, 0.0404}};
// Same source: the yaw's real pair (no yaw spring), |λ1 λ2|^½ / 2π and −(λ1 + λ2) / (2 |λ1 λ2|^½).
constexpr double kYawHz = 0.0075, kYawDamping = 20.01;

// The .lin files give the table above (so the reference is the files, not a copy of a printout).
TEST(Nrel5mwAeroWs03, LinFilesGiveTheReference) {
  std::vector<MbcSample> samples;
  MbcLayout layout;
  for (const char* k : {"1", "13", "34"}) {
    const OpenFastLin lin = readOpenFastLin(kLin + k + ".lin");
    if (samples.empty()) layout = mbcLayoutFromLin(lin);
    samples.push_back(mbcSampleFromLin(lin));
  }
  const EigenDecomposition ed = eigenStandard(mbcAverage(layout, samples).A);
  std::vector<ModalFrequency> modes, real;
  for (Eigen::Index j = 0; j < ed.values.size(); ++j) {
    if (ed.values(j).imag() > 0) modes.push_back(modalFrequency(ed.values(j)));
    if (ed.values(j).imag() == 0) real.push_back(modalFrequency(ed.values(j)));
  }
  std::sort(modes.begin(), modes.end(), [](const auto& a, const auto& b) { return a.freq_hz < b.freq_hz; });
  ASSERT_EQ(modes.size(), std::size(kRef));
  const double tol = 0.5e-4 + 1e-12;  // half a unit of the 4th decimal
  for (std::size_t i = 0; i < std::size(kRef); ++i) {
    EXPECT_NEAR(modes[i].freq_hz, kRef[i].freq_hz, tol) << kRef[i].mode;
    EXPECT_NEAR(modes[i].damping_ratio, kRef[i].damping, tol) << kRef[i].mode;
  }
  ASSERT_EQ(real.size(), 2u);
  double prod = 1, sum = 0;
  for (Eigen::Index j = 0; j < ed.values.size(); ++j)
    if (ed.values(j).imag() == 0) {
      prod *= ed.values(j).real();
      sum += ed.values(j).real();
    }
  const double w = std::sqrt(std::abs(prod));
  EXPECT_NEAR(w / (2 * std::numbers::pi), kYawHz, 0.5e-4);
  EXPECT_NEAR(-sum / (2 * w), kYawDamping, 0.5e-2);
}

// Tolerances (issue 15, not the reference's 4 digits): frequency 1 %, damping 10 % relative, or 0.3
// percentage points where ζ < 3 %. Measured (36 azimuths): frequencies within 0.41 % (1st flap FW
// 1.0183 Hz), damping within 3.7 % relative (1st flap FW 0.2109) or 0.07 points (1st edge BW).
// What the differences are (README "Aerodynamics", ws03 table):
// - the 3 unequally spaced azimuths of the .lin files against whirl's 36: whirl with
//   --azimuths 3 gives 1st flap BW 0.6881 Hz, FW 1.0219 Hz (36: 0.6902, 1.0183; .lin 0.6880, 1.0225)
//   — most of the whirling flap modes' frequency difference;
// - the flap damping +1 … +4 % relative, as at 9 rpm (ElastoDyn's node-based load mapping; AeroDyn's
//   skewed-wake correction, in whirl too, moves it by less than 0.1 %);
// - the operating point: OpenFAST's comes from a time simulation (yaw drifted to −0.0196 rad, blade
//   rates up to 0.32 m/s); whirl's is the periodic equilibrium with the free yaw held at 0. Holding
//   the yaw at −0.0196 rad instead (--set NacYaw=-1.1206) moves the modes by at most 1.3e-4 Hz and
//   4e-5 in ζ, the yaw pair's ζ from 21.63 to 21.71.
TEST(Nrel5mwAeroWs03, FreeYawAt3mpsMatchesOpenFast) {
  const Model m = readElastoDynModel(kDeck);
  ASSERT_TRUE(m.aero.active());
  ASSERT_GE(m.roles.yaw_dof, 0);
  PeriodicOptions opt;
  opt.azimuths = 36;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  for (const OperatingPoint& op : p.points) {
    ASSERT_EQ(op.held, std::vector<int>{m.roles.yaw_dof});  // the free yaw held at NacYaw = 0
    EXPECT_EQ(op.q(m.roles.yaw_dof), 0.0);
  }
  const RotorModes r = rotorModes(m, p);
  std::vector<Mode> modes, rigid;
  for (const Mode& md : r.modes) (md.rigid_body ? rigid : modes).push_back(md);
  std::sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  for (const Mode& md : r.modes)
    std::printf("  %-28s %9.4f Hz  damping %8.4f\n", md.name.c_str(), md.freq_hz, md.damping_ratio);
  ASSERT_EQ(modes.size(), std::size(kRef));
  for (std::size_t i = 0; i < std::size(kRef); ++i) {
    const Ref& ref = kRef[i];
    EXPECT_NEAR(modes[i].freq_hz, ref.freq_hz, 0.01 * ref.freq_hz) << ref.mode << " (" << modes[i].name << ")";
    const double tol = ref.damping < 0.03 ? 0.003 : 0.1 * ref.damping;
    EXPECT_NEAR(modes[i].damping_ratio, ref.damping, tol) << ref.mode << " (" << modes[i].name << ")";
  }
  // The yaw: one rigid-body mode, a real pair. Its sum −(λ1 + λ2) = 2 ζ ω is the aerodynamic yaw
  // damping over the yaw inertia (ζ ω: OpenFAST 0.943 1/s, whirl 0.953, within the 10 % on
  // damping); its product ω² is the small yaw stiffness of the tilted, deflected tower and the
  // aerodynamics, which depends on the operating point (OpenFAST's yaw at −0.0196 rad and its
  // velocities): 2.2e-3 against whirl's 1.95e-3 1/s², not compared.
  ASSERT_EQ(rigid.size(), 1u);
  EXPECT_EQ(rigid[0].name, "yaw (rigid body)");
  const double w_ref = 2 * std::numbers::pi * kYawHz, w = 2 * std::numbers::pi * rigid[0].freq_hz;
  EXPECT_NEAR(rigid[0].damping_ratio * w, kYawDamping * w_ref, 0.1 * kYawDamping * w_ref);
}

// The operating point against OpenFAST's: each blade's flap 1, edge 1 and flap 2 coordinates at the azimuths
// of the .lin files (0.4°, 120°, 330°; whirl's 36 azimuths hold 0°, 120°, 330°) — 27 values from the files'
// "Operating Point" column. The blade-to-blade differences are the 1P loads of gravity, shear, the 5° shaft
// tilt and, through AeroDyn's skewed-wake correction (Pitt & Peters 1981; the tilt skews the wake by 5°), the
// induction's 1P: larger on the disk's downwind side (the top, the rotor leaning back), which unloads the blade
// at the top. Measured: rms 0.0073 over the 27 values, flap 1 within 0.020 (without the correction rms 0.027, flap
// 1 up to 0.072 off at the top; with its azimuth turned by 180°, rms 0.048). The rest: OpenFAST's point comes
// from a time simulation at t = 413 s (yaw drifted to −0.0196 rad, blade rates up to 0.32 m/s), in single
// precision; whirl's is the periodic equilibrium with the yaw held at 0.
TEST(Nrel5mwAeroWs03, BladeDeflectionsAtTheLinAzimuthsMatchOpenFast) {
  const Model m = readElastoDynModel(kDeck);
  PeriodicOptions opt;
  opt.azimuths = 36;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  struct File {
    const char* name;
    int point;
  };
  double sum2 = 0;
  int count = 0;
  for (const File f : {File{"1", 0}, File{"13", 12}, File{"34", 33}}) {
    const OpenFastLin lin = readOpenFastLin(kLin + f.name + ".lin");
    ASSERT_NEAR(p.azimuths[static_cast<std::size_t>(f.point)], lin.azimuth, 0.01) << f.name;
    const OperatingPoint& op = p.points[static_cast<std::size_t>(f.point)];
    for (const LinVariable& x : lin.x) {
      const std::string name = dofNameFromLinDescription(x.description);
      if (name.rfind("blade ", 0) != 0 || x.description.find("First time derivative") != std::string::npos) continue;
      const std::optional<int> dof = m.findDof(name);
      ASSERT_TRUE(dof.has_value()) << name;
      const double d = op.q(*dof) - x.op;
      sum2 += d * d;
      ++count;
      if (name.find("flap 1") != std::string::npos) {
        EXPECT_NEAR(op.q(*dof), x.op, 0.025) << name << " at " << f.name;
      }
      std::printf("  ws03.0.%-3s %-18s OpenFAST %8.4f  whirl %8.4f\n", f.name, name.c_str(), x.op, op.q(*dof));
    }
  }
  ASSERT_EQ(count, 27);
  EXPECT_LT(std::sqrt(sum2 / count), 0.01);
}

}  // namespace
}  // namespace whirl

// The aeroelastic linearization of the NREL 5MW against OpenFAST's: the toolbox deck behind
// shared/data/openfast-lin/rotating-9rpm (ElastoDyn blade flap 1, edge 1, flap 2 and the generator;
// AeroDyn BEMT with frozen wake; InflowWind 8 m/s; ServoDyn simple VS torque law), 9 rpm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "linearize/linearize.hpp"
#include "linearize/periodic.hpp"
#include "linearize/simulate_aero.hpp"
#include "modal/rotor_modes.hpp"
#include "src/io/lin/openfast_lin.hpp"
#include "src/io/lin/openfast_lin_names.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/openfast_9rpm_mbc3.hpp"

namespace whirl {
namespace {

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/aero/toolbox/Main.fst";

// Source: MBC3 of OpenFAST v3.3's Main.{1,12,24}.lin (single precision), frequency and damping ratio
// (tests/support/openfast_9rpm_mbc3.hpp).
// Tolerances (the acceptance, not the reference's 4 printed digits): frequency 1 %, damping
// 10 % relative, or 0.3 percentage points where the damping ratio is below 3 %. What remains
// between the two models (ElastoDyn's node-based integration of the distributed loads, single
// precision; AeroDyn's skewed-wake correction is in whirl too) is discussed in docs/theory/aerodynamics.md.
TEST(Nrel5mwAero, Rotating9rpmMatchesOpenFast) {
  const Model m = readElastoDynModel(kDeck);
  ASSERT_TRUE(m.aero.active());
  ASSERT_TRUE(m.generator.active());
  PeriodicOptions opt;
  opt.azimuths = 36;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  const RotorModes r = rotorModes(m, p);
  std::vector<Mode> modes;
  for (const Mode& md : r.modes)
    if (!md.rigid_body && md.damped_freq_hz > 0.1) modes.push_back(md);
  std::sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  for (const Mode& md : modes)
    std::printf("  %-28s %9.4f Hz  damping %8.4f\n", md.name.c_str(), md.freq_hz, md.damping_ratio);
  ASSERT_EQ(modes.size(), std::size(test::kOpenFast9rpmMbc3));
  for (std::size_t i = 0; i < std::size(test::kOpenFast9rpmMbc3); ++i) {
    const test::OpenFast9rpmMode& ref = test::kOpenFast9rpmMbc3[i];
    EXPECT_NEAR(modes[i].freq_hz, ref.freq_hz, 0.01 * ref.freq_hz) << ref.mode;
    const double tol = ref.damping_ratio < 0.03 ? 0.003 : 0.1 * ref.damping_ratio;
    EXPECT_NEAR(modes[i].damping_ratio, ref.damping_ratio, tol) << ref.mode << " (" << modes[i].name << ")";
  }
}

// The same gap located in the matrices: each blade coordinate's diagonal entries of A (acceleration row; position
// and rate columns) at OpenFAST's operating point of each .lin file — the positions and rates of its op column
// (OpenFAST's point is a periodic motion: flap rates up to 0.19 m/s, edge rates up to 0.42 m/s), the azimuth; the
// frozen induction whirl's BEM gives there — against the file's A (OpenFAST v3.3, single precision, finite
// differences). Measured, whirl / OpenFAST:
//   stiffness (position column): flap 1 0.982–1.003, edge 1 0.9997–0.9999, flap 2 0.996–1.0003;
//   damping (rate column): flap 1 1.006–1.035, flap 2 1.014–1.045, edge 1 0.957–0.986.
// The damping entries depend on the blade's azimuth (flap 1: least at 110°–120°, most at 230°–240°, where
// OpenFAST's own entry dips by 4.5 % and whirl's by 3 %); whirl's flap entries are all above OpenFAST's, its edge
// entries all below: as if the sections' aerodynamic damping were shared between the out-of-plane and the in-plane
// motion at a slightly different angle. Not explained (docs/theory/aerodynamics.md, 9 rpm); the bounds
// hold that state: 2 % on the stiffness, 4 % on flap 1 damping, 5 % on flap 2 and edge 1 damping.
TEST(Nrel5mwAero, BladeEntriesOfAAtOpenFastsPointsMatchOpenFast) {
  const Model m = readElastoDynModel(kDeck);
  const std::optional<int> azimuth = m.findDof("generator azimuth");
  ASSERT_TRUE(azimuth.has_value());
  int compared = 0;
  for (const char* file : {"Main.1.lin", "Main.12.lin", "Main.24.lin"}) {
    const OpenFastLin lin = readOpenFastLin(std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast-lin/rotating-9rpm/" +
                                            file);
    const int n_of = lin.n_x / 2;  // positions, then rates, in the same order
    OperatingPoint op = initialPoint(m);
    op.q(*azimuth) = lin.azimuth;
    for (int j = 0; j < lin.n_x; ++j) {
      const std::string name = dofNameFromLinDescription(lin.x[static_cast<std::size_t>(j)].description);
      if (name.rfind("blade ", 0) != 0) continue;
      const std::optional<int> dof = m.findDof(name);
      ASSERT_TRUE(dof.has_value()) << name;
      (j < n_of ? op.q : op.qd)(*dof) = lin.x[static_cast<std::size_t>(j)].op;
    }
    op.inflow = quasiSteadyInflow(m, op);
    const LinearModel l = linearize(m, op);
    const int n = static_cast<int>(l.dofs.size());
    for (int j = 0; j < n_of; ++j) {
      const std::string name = dofNameFromLinDescription(lin.x[static_cast<std::size_t>(j)].description);
      if (name.rfind("blade ", 0) != 0) continue;
      const int dof = *m.findDof(name);
      const int r = static_cast<int>(std::find(l.dofs.begin(), l.dofs.end(), dof) - l.dofs.begin());
      ASSERT_LT(r, n) << name;
      const double k = l.A(n + r, r) / lin.A(n_of + j, j), c = l.A(n + r, n + r) / lin.A(n_of + j, n_of + j);
      std::printf("  %-12s %-14s stiffness %8.4f  damping %8.4f (whirl / OpenFAST)\n", file, name.c_str(), k, c);
      EXPECT_NEAR(k, 1.0, 0.02) << file << " " << name;
      EXPECT_NEAR(c, 1.0, name.find("flap 1") != std::string::npos ? 0.04 : 0.05) << file << " " << name;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 27);
}

}  // namespace
}  // namespace whirl

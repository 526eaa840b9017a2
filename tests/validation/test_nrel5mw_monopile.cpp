// NREL 5MW tower + RNA on a monopile FE substructure with soil springs (cases/nrel5mw_monopile):
// issue 5 asks the Craig–Bampton model (top node + 8 fixed-interface modes) to be within 0.5 % of the
// full FE model (67 nodes × 6 DOFs) on the first 6 coupled modes. Measured: ≤ 0.012 % (mode 6;
// < 1e-8 relative on the first two), printed by the test. The full model takes ~13 s (402 FE DOFs in AD).
#include <cmath>
#include <cstdio>

#include "modal/modes.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

std::vector<Mode> modesOf(const std::vector<std::string>& sets) {
  const LinearModel l = test::linearizeAtEquilibrium(test::loadCase("nrel5mw_monopile", sets));
  return computeModes(l.M, l.C, l.K, l.dof_names);
}

TEST(Nrel5mwMonopileSlow, CraigBamptonWithinHalfPercentOfFullFem) {
  const std::vector<Mode> cb = modesOf({}), full = modesOf({"bodies.monopile.reduction={type: none}"});
  ASSERT_GE(cb.size(), 6u);
  ASSERT_GT(full.size(), 400u);  // the full FE DOFs are coordinates of the coupled model
  for (int k = 0; k < 6; ++k) {
    std::printf("mode %d  CB %.6f Hz  full %.6f Hz  (%s)\n", k + 1, cb[k].freq_hz, full[k].freq_hz,
                full[k].name.c_str());
    EXPECT_NEAR(cb[k].freq_hz, full[k].freq_hz, 0.005 * full[k].freq_hz) << "mode " << k + 1;
  }
}

// The geometric stiffness of the weight carried by the monopile (tower, RNA, its own) softens it:
// gravity lowers the first bending frequencies; without the FE geometric stiffness the drop is smaller.
TEST(Nrel5mwMonopile, GravitySoftensTheSubstructure) {
  const double with = modesOf({})[1].freq_hz, without = modesOf({"gravity=0"})[1].freq_hz,
               no_kg = modesOf({"bodies.monopile.geometric_stiffness=false"})[1].freq_hz;
  EXPECT_LT(with, without);
  EXPECT_LT(with, no_kg);
}

}  // namespace
}  // namespace whirl

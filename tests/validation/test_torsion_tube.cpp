// [Branlard2019, §5.3]: torsion of a clamped-free tube with four torsion shapes;
// ω_j = c β_j / L exactly (the shapes are the exact modes).
#include "modal/modes.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

TEST(TorsionTube, FrequenciesAreCBetaOverL) {
  const Model m = test::loadCase("torsion_tube");
  const LinearModel l = test::linearizeAtEquilibrium(m);
  const auto modes = computeModes(l.M, l.C, l.K, l.dof_names);
  ASSERT_EQ(modes.size(), 4u);
  std::map<std::string, double> computed;
  for (int j = 0; j < 4; ++j) {
    computed["f_" + std::to_string(j + 1)] = modes[j].freq_hz;
    EXPECT_EQ(modes[j].name, "torsion " + std::to_string(j + 1));
  }
  test::expectMatchesReference("torsion_tube", computed);
}

}  // namespace
}  // namespace whirl

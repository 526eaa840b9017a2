// [BranlardGeisler2022, §4.3]: NREL 5MW blade rotating in vacuum, three uncoupled
// shapes. diag Me, diag Ke, Southwell coefficients k_Ω, and the frequencies against rotor speed
// following ω² = ω0² + k_Ω Ω² (flap, eq. 32) and ω² = ω0² + (k_Ω − 1) Ω² (edge, eq. 33).
#include <numbers>

#include "modal/modes.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr const char* kCase = "rotating_blade";
constexpr double two_pi = 2 * std::numbers::pi;
const std::vector<std::string> kShapes = {"flap 1", "edge 1", "flap 2"};

LinearModel at(double rpm, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> sets = {"dofs.azimuth.rate_rpm=" + std::to_string(rpm)};
  sets.insert(sets.end(), extra.begin(), extra.end());
  return test::linearizeAtEquilibrium(test::loadCase(kCase, sets));
}

TEST(RotatingBlade, MassStiffnessAndSouthwellCoefficients) {
  const double rpm = 12;
  const double W = rpm * two_pi / 60;
  const LinearModel l0 = at(0), l1 = at(rpm);
  std::map<std::string, double> computed;
  for (int i = 0; i < 3; ++i) {
    std::string key = kShapes[i];
    key.replace(key.find(' '), 1, "");
    const double Me = l0.M(i, i), Ke = l0.K(i, i);
    // Centrifugal K of a shape: K(Ω) − K(0) = (k_Ω − [edge]) Me Ω²; the edge shape also sees
    // the in-plane softening −Me Ω² [BranlardGeisler2022, eq. 33].
    const double edge = kShapes[i].rfind("edge", 0) == 0 ? 1.0 : 0.0;
    computed["Me_" + key] = Me;
    computed["Ke_" + key] = Ke;
    computed["k_Omega_" + key] = (l1.K(i, i) - Ke) / (Me * W * W) + edge;
  }
  test::expectMatchesReference(kCase, computed);
}

TEST(RotatingBlade, FrequenciesFollowSouthwellFromZeroTo15Rpm) {
  for (int i = 0; i < 3; ++i) {
    // One shape at a time (the paper treats them uncoupled): freeze the other two.
    std::vector<std::string> freeze;
    for (int j = 0; j < 3; ++j)
      if (j != i) freeze.push_back("dofs." + kShapes[j] + ".frozen=true");
    const double edge = i == 1 ? 1.0 : 0.0;
    const LinearModel l0 = at(0, freeze), l15 = at(15, freeze);
    const double W15 = 15 * two_pi / 60;
    const double w0sq = l0.K(0, 0) / l0.M(0, 0);
    const double kOmega = (l15.K(0, 0) - l0.K(0, 0)) / (l0.M(0, 0) * W15 * W15) + edge;
    for (double rpm = 0; rpm <= 15; rpm += 2.5) {
      const LinearModel l = at(rpm, freeze);
      const auto modes = computeModes(l.M, l.C, l.K, l.dof_names);
      const double W = rpm * two_pi / 60;
      const double expected = std::sqrt(w0sq + (kOmega - edge) * W * W) / two_pi;
      EXPECT_NEAR(modes.at(0).freq_hz, expected, 1e-9 * expected) << kShapes[i] << " at " << rpm << " rpm";
    }
  }
}

}  // namespace
}  // namespace whirl

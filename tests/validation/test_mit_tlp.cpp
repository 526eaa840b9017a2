// MIT/NREL TLP (OpenFAST certification Test23, cases/mit_tlp): the eight vertical tendons of the deck
// set's MAP++ file (the deck's own FEAMooring file is not read) as taut lines straight below their
// fairleads. No published linearized tendon stiffness of this system is known (Jonkman on the NREL
// forum, "Mooring matrix and ITI barge RAO"), nor a table of its coupled frequencies in the stored
// corpora: the checks are closed forms of the tendons against the model's AD Jacobian, and the deck
// set's MoorDyn file of the same tendons against the MAP++ one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "linearize/linearize.hpp"
#include "modal/modes.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/cases/mit_tlp/Test23.fst";
const std::vector<std::string> kSets = {
    "CompAero=0",   "RdtnMod=0",     "RotSpeed=0",
    "GenDOF=False", "CompMooring=1", "MooringFile=5MW_Baseline/NRELOffshrBsline5MW_MIT_NREL_TLP_MAP.dat"};

Model tlpModel(const std::vector<std::string>& sets = kSets) { return readElastoDynModel(kDeck, sets); }

// At the undisplaced platform each tendon hangs straight: its vertical stiffness is EA/L exactly
// (z(H = 0, V) = L + (V L − w L²/2)/EA) and its horizontal one the pendulum stiffness
// H/l = 1/X(0, V), X(0, V) = ln(V/(V − w L))/w + L/EA, V = EA (h − L)/L + w L/2.
TEST(MitTlp, TendonStiffnessIsTheClosedForm) {
  const Model with = tlpModel();
  ASSERT_EQ(with.mooring.size(), 8u);
  Model without = with;
  without.mooring.clear();
  const VecX q = VecX::Zero(with.ndof());
  const LinearModel a = test::linearizeAt(with, q), b = test::linearizeAt(without, q);
  auto k = [&](const char* r, const char* c) {
    const int i = test::dofIndex(a, r), j = test::dofIndex(a, c);
    return a.K(i, j) - b.K(i, j);
  };
  const MooringLine& t = with.mooring[0];
  const double L = t.length, w = t.weight, EA = t.EA, h = 200 - 47.89;
  const double V = EA * (h - L) / L + 0.5 * w * L;
  const double pendulum = 1.0 / (std::log(V / (V - w * L)) / w + L / EA);
  std::printf("tendon tension %.6g N; K11 %.6g N/m (8 x %.6g), K33 %.6g N/m (8 EA/L %.6g)\n", V,
              k("platform surge", "platform surge"), pendulum, k("platform heave", "platform heave"), 8 * EA / L);
  EXPECT_NEAR(k("platform surge", "platform surge"), 8 * pendulum, 1e-8 * 8 * pendulum);
  EXPECT_NEAR(k("platform sway", "platform sway"), 8 * pendulum, 1e-8 * 8 * pendulum);
  EXPECT_NEAR(k("platform heave", "platform heave"), 8 * EA / L, 1e-8 * 8 * EA / L);
}

std::vector<Mode> parkedModes(const Model& m) {
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const LinearModel lin = linearize(m, op);
  EXPECT_LT(lin.residual.lpNorm<Eigen::Infinity>(), 1e-3) << "not an equilibrium";
  return computeModes(lin.M, lin.C, lin.K, lin.dof_names);
}

// The MoorDyn file of the deck set holds the same eight tendons (two at each of four fairleads, as
// MAP++'s `repeat`): the same modes. Without friction (MoorDyn v1) and with it (MAP++ CB = 1) alike,
// as no tendon touches the seabed.
TEST(MitTlp, MoorDynTendonsGiveTheMapModes) {
  const std::vector<Mode> map = parkedModes(tlpModel());
  std::vector<std::string> sets = kSets;
  sets.back() = "MooringFile=5MW_Baseline/NRELOffshrBsline5MW_MIT_NREL_TLP_MoorDyn.dat";
  sets[sets.size() - 2] = "CompMooring=3";
  const std::vector<Mode> moordyn = parkedModes(tlpModel(sets));
  ASSERT_EQ(map.size(), moordyn.size());
  for (std::size_t k = 0; k < 8; ++k) {
    std::printf("mode %2zu %9.6f Hz  %s\n", k + 1, map[k].freq_hz, map[k].name.c_str());
    EXPECT_NEAR(moordyn[k].freq_hz, map[k].freq_hz, 1e-6 * map[k].freq_hz);  // to the equilibrium solves' tolerance
  }
}

}  // namespace
}  // namespace whirl

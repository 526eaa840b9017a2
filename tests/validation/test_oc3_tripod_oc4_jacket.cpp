// The NREL 5MW on the OC3 tripod and on the OC4 jacket (OpenFAST certification Test20 and Test21,
// cases/oc3_tripod and cases/oc4_jacket): ElastoDyn's platform DOFs on the transition piece (TP) of a
// multi-member SubDyn substructure clamped at the seabed, HydroDyn's strip theory on its members in the
// water (the jacket's with marine growth and four flooded legs).
//
// Checks (no published number is a test here: the OC3 Phase II and OC4 Phase I full-system frequencies
// were not found in the stored corpora; the cases' READMEs say what was looked for):
// - the decks run from cases/ with the Craig–Bampton modes they ask for (Nmodes 12 and 8);
// - HydroDyn's added mass, marine growth and flooded legs only add mass to the substructure, so every
//   one of the first coupled frequencies falls (Rayleigh);
// - issue 17's cross-check: Craig–Bampton with the deck's modes within 0.5 % of the full FE model on the
//   first 10 coupled modes, and Guyan ≥ Craig–Bampton ≥ full FE (Rayleigh–Ritz). The full FE models
//   (945 and 1005 coordinates) take 40-50 s each to solve, linearize and eigen-solve: the Slow suite.
//
// The decks are read as `whirl modes` reads them with `--set CompAero=0 --set RotSpeed=0 --set
// GenDOF=False`: parked, no aerodynamics, generator locked, HydroDyn as shipped unless said otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "linearize/linearize.hpp"
#include "modal/modes.hpp"
#include "modal/sparse_modes.hpp"
#include "src/parallel/session.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

struct Deck {
  const char* folder;
  const char* fst;
  int cb_modes;  // the SubDyn file's Nmodes
};

const Deck kTripod{"oc3_tripod", "Test20.fst", 12};
const Deck kJacket{"oc4_jacket", "Test21.fst", 8};

Model readDeck(const Deck& d, const std::vector<std::string>& extra = {}, bool hydro = true) {
  std::vector<std::string> sets = {"CompAero=0", "RotSpeed=0", "GenDOF=False"};
  if (!hydro) sets.push_back("CompHydro=0");
  sets.insert(sets.end(), extra.begin(), extra.end());
  return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/" + d.folder + "/" + d.fst, sets);
}

// The modes of (K, M) alone at the operating point: their frequencies obey the Rayleigh bounds exactly.
// The full FE models (about 1000 coordinates) go to SLEPc's symmetric solver for their lowest modes, as
// `whirl modes --solver auto` sends them (its relative residual tolerance 1e-12): the dense 2n pencil
// takes minutes at that size. The dense path if whirl was built without PETSc.
std::vector<Mode> undampedModes(const Model& m) {
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const LinearModel lin = linearize(m, op);
  const auto n = lin.M.rows();
  if (n < kSparseSolverThreshold || !parallel::petscAvailable())
    return computeModes(lin.M, MatX::Zero(n, n), lin.K, lin.dof_names);
  return computeModesSparse(lin.M.sparseView(), SparseMatrix(n, n), lin.K.sparseView(), lin.dof_names, 12, {});
}

// Up to the eigensolver's round-off on dimensional matrices (1e-8 to 1e-7, README, *Large models*).
constexpr double kRoundOff = 1e-7;

void expectDeckRunsWithItsModes(const Deck& d) {
  SCOPED_TRACE(d.folder);
  const Model m = readDeck(d);
  for (const char* dof :
       {"platform surge", "platform sway", "platform heave", "platform roll", "platform pitch", "platform yaw"})
    EXPECT_TRUE(m.findDof(dof).has_value()) << dof;
  const std::string last = "substructure CB " + std::to_string(d.cb_modes);
  const std::string beyond = "substructure CB " + std::to_string(d.cb_modes + 1);
  EXPECT_TRUE(m.findDof(last).has_value()) << last;
  EXPECT_FALSE(m.findDof(beyond).has_value()) << beyond;

  // The water only adds mass (HydroDyn's Morison added mass; the jacket's marine growth and the water
  // in its flooded legs): M grows by a positive semi-definite matrix, so each frequency can only fall.
  const std::vector<Mode> wet = undampedModes(m), dry = undampedModes(readDeck(d, {}, false));
  ASSERT_GE(wet.size(), 10u);
  ASSERT_EQ(wet.size(), dry.size());
  double lowest_drop = 1;
  for (int k = 0; k < 10; ++k) {
    std::printf("%s mode %2d: wet %.6f  dry %.6f Hz  %s\n", d.folder, k + 1, wet[k].freq_hz, dry[k].freq_hz,
                wet[k].name.c_str());
    EXPECT_LE(wet[k].freq_hz, dry[k].freq_hz * (1 + kRoundOff)) << "mode " << k + 1;
    lowest_drop = std::min(lowest_drop, wet[k].freq_hz / dry[k].freq_hz);
  }
  EXPECT_LT(lowest_drop, 1 - 1e-4);  // the water is there: some mode moves by more than round-off
}

TEST(Oc3TripodOc4Jacket, DecksRunFromCasesWithTheirCraigBamptonModes) {
  expectDeckRunsWithItsModes(kTripod);
  expectDeckRunsWithItsModes(kJacket);
}

// Guyan (Nmodes = 0), Craig–Bampton with the deck's Nmodes and the full FE model (CBMod = False): the
// reduced substructures are subspaces of the full one and static condensation is exact at the
// interface, so the operating point is the same and each undamped coupled frequency can only fall as
// the basis grows; Craig–Bampton within 0.5 % of the full model on the first 10 coupled modes.
void expectReductionsConverge(const Deck& d) {
  SCOPED_TRACE(d.folder);
  const Model full_model = readDeck(d, {"CBMod=False"}), cb_model = readDeck(d);
  ASSERT_GT(full_model.ndof(), cb_model.ndof() + 100);  // the full FE DOFs are coordinates of the coupled model
  const std::vector<Mode> guyan = undampedModes(readDeck(d, {"Nmodes=0"})), cb = undampedModes(cb_model),
                          full = undampedModes(full_model);
  ASSERT_GE(full.size(), 10u);
  double worst = 0;
  for (int k = 0; k < 10; ++k) {
    const double fg = guyan[k].freq_hz, fc = cb[k].freq_hz, ff = full[k].freq_hz;
    std::printf("%s mode %2d: Guyan %.6f  CB%d %.6f  full %.6f Hz  (CB - full)/full %.2e  %s\n", d.folder, k + 1, fg,
                d.cb_modes, fc, ff, (fc - ff) / ff, full[k].name.c_str());
    EXPECT_GE(fg, fc * (1 - kRoundOff)) << "mode " << k + 1;
    EXPECT_GE(fc, ff * (1 - kRoundOff)) << "mode " << k + 1;
    EXPECT_NEAR(fc, ff, 0.005 * ff) << "mode " << k + 1;
    worst = std::max(worst, (fc - ff) / ff);
  }
  std::printf("%s: CB%d within %.2e of the full FE model on the first 10 modes\n", d.folder, d.cb_modes, worst);
}

TEST(Oc3TripodOc4JacketSlow, TripodCraigBamptonWithinHalfPercentOfFullFe) { expectReductionsConverge(kTripod); }

TEST(Oc3TripodOc4JacketSlow, JacketCraigBamptonWithinHalfPercentOfFullFe) { expectReductionsConverge(kJacket); }

}  // namespace
}  // namespace whirl

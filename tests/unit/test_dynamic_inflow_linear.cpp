// The dynamic-inflow states (AeroDyn DBEMT_Mod 3, Øye's model: src/aero/dynamic_inflow.hpp) in a turbine's
// linear model (linearize/unsteady_aero.hpp, issue 47 item 2), on the one-blade NREL 5MW rotor of OpenFAST's
// r-test Fake5MW_AeroLin_B1_UA4_DBEMT3 (tau1_const 100 s, four elements; tests/data/openfast-lin/ua4-dbemt3).
// The AD Jacobian of the new blocks against central differences is UnsteadyAeroLinear.AdJacobianEquals-
// CentralDifferences (test_unsteady_aero_linear.cpp), which covers every aerodynamic state of this deck.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/state_space.hpp"
#include "linearize/unsteady_aero.hpp"
#include "modal/aero_roots.hpp"
#include "src/aero/dynamic_inflow.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/io/lin/openfast_lin_names.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "src/writers/state_space_files.hpp"
#include "tests/support/lin_rules_reader.hpp"

namespace {

using namespace whirl;

std::filesystem::path referenceDir() {
  return std::filesystem::path(WHIRL_SOURCE_DIR) / "tests/data/openfast-lin/ua4-dbemt3";
}

Model dbemtDeck() { return readElastoDynModel((referenceDir() / "case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst").string()); }

// OpenFAST's A of the deck (A_30x30.txt, row-major), 1-based as its state list (states_inputs.txt): 1-2 the
// flap q, q̇; 3-10 "vind" (axial, tangential) at nodes 1-4; 11-18 the intermediate states v1 (labelled "First
// time derivative of vind"); 19-30 the UA states of nodes 2-4.
struct OpenFastA {
  std::vector<double> a;
  double operator()(int r, int c) const { return a[static_cast<std::size_t>((r - 1) * 30 + (c - 1))]; }
  OpenFastA() {
    std::ifstream in(referenceDir() / "A_30x30.txt");
    for (double v; in >> v;) a.push_back(v);
  }
};

// OpenFAST's index of the DBEMT state of node j (1-based), component c (0 axial, 1 tangential), v1 or v.
int openFastIndex(int node, int comp, bool v1) { return (v1 ? 11 : 3) + 2 * (node - 1) + comp; }

// whirl's index (in the linear model's first-order states) of the same state.
int whirlIndex(const LinearModel& lin, int node, int comp, bool v1) {
  const std::string name = std::string("DBEMT ") + (v1 ? "v1 " : "v ") + (comp == 0 ? "axial" : "tangential") +
                           " blade 1 element " + std::to_string(node);
  const auto it = std::find(lin.first_order_names.begin(), lin.first_order_names.end(), name);
  EXPECT_NE(it, lin.first_order_names.end()) << name;
  return static_cast<int>(it - lin.first_order_names.begin());
}

OperatingPoint equilibrium(const Model& m) { return solveOperatingPoint(m, initialPoint(m)); }

TEST(DynamicInflowLinear, StatesOnEveryElementAsAeroDyn) {
  const Model m = dbemtDeck();
  EXPECT_EQ(m.aero.dbemt_mod, 3);
  EXPECT_EQ(m.aero.tau1, 100.0);  // AD.dat tau1_const
  ASSERT_EQ(inflowStateCount(m.aero), 16);
  std::vector<std::string> names, groups;
  inflowStateNames(m.aero, names, groups);
  ASSERT_EQ(names.size(), 16u);
  EXPECT_EQ(names[0], "DBEMT v axial blade 1 element 1");
  EXPECT_EQ(names[3], "DBEMT v1 tangential blade 1 element 1");
  EXPECT_EQ(groups[5], "DBEMT v tangential blade 1");
  for (const std::string& n : names) EXPECT_TRUE(isAeroStateName(n)) << n;
  EXPECT_TRUE(isAeroStateName("DBEMT v1 axial element 7 cos"));  // after the multiblade transform
  // DBEMT_Mod 1 and 2 (discrete in time: OpenFAST does not linearize them either) add no states.
  const Model discrete = readElastoDynModel((referenceDir() / "case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst").string(),
                                            {"DBEMT_Mod=1"});
  EXPECT_EQ(inflowStateCount(discrete.aero), 0);
  // The frozen wake (DBEMT_Mod -1) keeps the UA states without dynamic inflow.
  const Model frozen = readElastoDynModel((referenceDir() / "case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst").string(),
                                          {"DBEMT_Mod=-1"});
  EXPECT_EQ(inflowStateCount(frozen.aero), 0);
  EXPECT_EQ(uaStateCount(frozen.aero), 12);
}

TEST(DynamicInflowLinear, OpenFastNamesReadBack) {
  // tests/data/openfast-lin/ua4-dbemt3/states_inputs.txt, states 5 and 13.
  EXPECT_EQ(dofNameFromLinDescription("AD vind (axial) at blade 1, node 2, m/s"), "DBEMT v axial blade 1 element 2");
  EXPECT_EQ(dofNameFromLinDescription("AD First time derivative of vind (tangential) at blade 1, node 2, m/s/s"),
            "DBEMT v1 tangential blade 1 element 2");
  EXPECT_EQ(firstOrderGroupFromLinDescription("AD vind (axial) at blade 3, node 12, m/s"), "DBEMT v axial blade 3");
}

// export's .lin names the states as OpenFAST's (states_inputs.txt: "AD vind (axial) at blade 1, node 2, m/s",
// "AD First time derivative of vind (axial) at blade 1, node 2, m/s/s", rotating), with derivative order 1:
// v1 is not v's rate (docs/theory/unsteady-aero.md), and order 2 would pair them in a reader's transform.
TEST(DynamicInflowLinear, ExportNamesTheStatesAsOpenFast) {
  const Model m = dbemtDeck();
  const OperatingPoint op = equilibrium(m);
  const LinearModel lin = linearize(m, op);
  const test::RulesLin f = test::readLinByOpenFastRules(linFileText(stateSpace(m, op, lin), "r-test"));
  auto row = [&](const std::string& d) {
    const auto it = std::find_if(f.x.begin(), f.x.end(), [&](const test::RulesRow& r) { return r.description == d; });
    EXPECT_NE(it, f.x.end()) << d;
    return it == f.x.end() ? test::RulesRow{} : *it;
  };
  const test::RulesRow v = row("AD vind (axial) at blade 1, node 2, m/s");
  const test::RulesRow v1 = row("AD First time derivative of vind (tangential) at blade 1, node 4, m/s/s");
  EXPECT_TRUE(v.rotating);
  EXPECT_TRUE(v1.rotating);
  EXPECT_EQ(v.order, 1);
  EXPECT_EQ(v1.order, 1);
  // The point's BEM induction before the skewed-wake correction (AeroDyn applies it to DBEMT's output): the
  // state's operating value is the frozen induction divided by the element's correction, a few per cent here.
  EXPECT_NE(v.op, op.inflow.axial(1));
  EXPECT_NEAR(v.op, op.inflow.axial(1), 0.1 * std::abs(op.inflow.axial(1)));
  EXPECT_EQ(f.x.size(), 2 * lin.dofs.size() + 28);
}

TEST(DynamicInflowLinear, SteadyStateIsTheBemInduction) {
  // At whirl's equilibrium of the deck the states rest at v = v_qs, the BEM induced velocities the point was
  // solved with (the frozen wake's AxInd, TnInd: the tip-speed ratio 6.1 leaves AeroDyn's low-TSR weight at 1),
  // and v1 = (1 − k) v_qs; there ż = 0. With the deck's skewed-wake correction off: AeroDyn applies it to the
  // induction after DBEMT, so the frozen wake would carry it and the states not (SkewedWakeCorrectsTheFrozenWake
  // below).
  const Model m = readElastoDynModel((referenceDir() / "case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst").string(),
                                     {"Skew_Mod=0"});
  const OperatingPoint op = equilibrium(m);
  const VecX z = unsteadyAeroSteadyStates(m, op);
  const int nua = uaStateCount(m.aero);
  ASSERT_EQ(z.size(), nua + 16);
  for (int i = 0; i < 4; ++i) {
    const double ax = op.inflow.axial(i), tn = op.inflow.tangential(i);
    const double scale = std::max(1.0, std::abs(ax));
    EXPECT_NEAR(z(nua + 4 * i), ax, 1e-12 * scale) << "element " << i + 1;
    EXPECT_NEAR(z(nua + 4 * i + 1), tn, 1e-12 * scale) << "element " << i + 1;
    EXPECT_NEAR(z(nua + 4 * i + 2), (1 - aero::kOyeK) * ax, 1e-12 * scale) << "element " << i + 1;
    EXPECT_NEAR(z(nua + 4 * i + 3), (1 - aero::kOyeK) * tn, 1e-12 * scale) << "element " << i + 1;
  }
  EXPECT_LT(op.inflow.axial(1), -0.1);  // a real induction: the test can tell v from 0
  Workspace<double> ws(m);
  forwardKinematics(m, ws, op.q, op.qd, op.qdd);
  VecX e = VecX::Zero(m.ndof()), zdot = VecX::Zero(z.size());
  addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, &z, e, &zdot);
  EXPECT_LT(zdot.tail(16).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DynamicInflowLinear, OyeBlockEqualsOpenFast) {
  // The rows of the dynamic-inflow states in their own columns depend on τ1 and each element's span ratio
  // only (not on the operating point): OpenFAST's A, states 3-18, entry by entry after matching names
  // (AeroDyn's node j = whirl's element j). OpenFAST writes 13 significant digits; its τ2 from rLocal with
  // precone, prebend and sweep (whirl's span ratios the same: 1e-13 measured). Its off-diagonal entries
  // there are finite-difference noise of 1e-20 or less; whirl's are 0.
  const Model m = dbemtDeck();
  const LinearModel lin = linearize(m, equilibrium(m));
  const OpenFastA ref;
  const int z0 = 2 * static_cast<int>(lin.dofs.size());
  for (int node = 1; node <= 4; ++node)
    for (int comp = 0; comp < 2; ++comp)
      for (bool v1r : {false, true}) {
        const int wr = z0 + whirlIndex(lin, node, comp, v1r), orow = openFastIndex(node, comp, v1r);
        for (int node2 = 1; node2 <= 4; ++node2)
          for (int comp2 = 0; comp2 < 2; ++comp2)
            for (bool v1c : {false, true}) {
              const int wc = z0 + whirlIndex(lin, node2, comp2, v1c), ocol = openFastIndex(node2, comp2, v1c);
              const double expected = ref(orow, ocol);
              EXPECT_NEAR(lin.A(wr, wc), expected, 1e-11 * std::abs(expected) + 1e-18)
                  << "OpenFAST A(" << orow << ", " << ocol << ")";
            }
        // And no dependence on the UA states (OpenFAST: below 1e-15, finite-difference noise).
        for (int k = 0; k < uaStateCount(m.aero); ++k) EXPECT_EQ(lin.A(wr, z0 + k), 0.0);
      }
}

// The rows of v̇ and v̇1 in the structure's columns carry the quasi-steady induction's derivatives with the
// gains k/τ2 and (1 − k)/τ1, the same column in both: their ratio is k τ1/((1 − k) τ2) as in OpenFAST's A.
TEST(DynamicInflowLinear, DriveByTheQuasiSteadyInductionAsOpenFast) {
  const Model m = dbemtDeck();
  const LinearModel lin = linearize(m, equilibrium(m));
  const OpenFastA ref;
  const int n = static_cast<int>(lin.dofs.size()), z0 = 2 * n;
  ASSERT_EQ(n, 1);  // FlapDOF1 only
  for (int node = 1; node <= 4; ++node) {
    const int wv = z0 + whirlIndex(lin, node, 0, false), wv1 = z0 + whirlIndex(lin, node, 0, true);
    const int ov = openFastIndex(node, 0, false), ov1 = openFastIndex(node, 0, true);
    for (int c : {0, 1}) {  // q, q̇
      const double whirl_ratio = lin.A(wv, c) / lin.A(wv1, c), of_ratio = ref(ov, c + 1) / ref(ov1, c + 1);
      if (lin.A(wv1, c) == 0.0 || std::abs(ref(ov1, c + 1)) < 1e-15) continue;  // the root's q̇: 0, OpenFAST's noise
      // OpenFAST's entries are finite differences of 13-digit numbers: 1e-5 relative on the ratio.
      // OpenFAST's entries carry 13 digits: the ratios agree to 4e-13 (measured).
      EXPECT_NEAR(whirl_ratio, of_ratio, 1e-11 * std::abs(of_ratio)) << "node " << node << " column " << c + 1;
    }
  }
  // At the tip (node 4, tip-loss constant 0: AeroDyn's fixed inductions a = 1, v_qs = −Vx) the drive is the
  // element's own axial velocity, ∂v̇/∂q̇ = −(k/τ2) ∂Vx/∂q̇, nearly independent of the flow: OpenFAST
  // 0.0478953 at its point (a transient, flap 6.24 m and moving), whirl 0.0479834 at its equilibrium
  // (5.91 m, at rest), 1.8e-3 apart: the flap shape's axial component at the tip, turned by the other slope.
  const int tip = z0 + whirlIndex(lin, 4, 0, false);
  EXPECT_NEAR(lin.A(tip, 1), ref(9, 2), 3e-3 * std::abs(ref(9, 2)));
}

// Eliminating the dynamic-inflow states of a slow motion (ż = 0: v = v_qs(q, q̇), K + ΔK + G A_zz⁻¹ Z_q and
// C + ΔC + G A_zz⁻¹ Z_q̇) gives the linear model
// whose induction is re-solved at once (LinearizeOptions::frozen_wake = false, quasi-steady BEM): K and C
// to round-off. The deck's UA states taken out, so that the two models differ by the induction alone.
TEST(DynamicInflowLinear, EliminatedStatesGiveTheQuasiSteadyInduction) {
  Model m = dbemtDeck();
  removeUnsteadyAirfoils(m.aero);
  const OperatingPoint op = equilibrium(m);
  const std::vector<int> cols = m.activeDofs();
  const UnsteadyAeroLinear blocks = unsteadyAeroLinear(m, op, cols, false);
  ASSERT_EQ(blocks.z.size(), 16);
  const MatX GA = blocks.G * blocks.Azz.inverse();
  const MatX dK = blocks.dK + GA * blocks.Zq, dC = blocks.dC + GA * blocks.Zqd;
  LinearizeOptions frozen, induction;
  frozen.unsteady_aero = false;
  frozen.inputs = induction.inputs = false;
  induction.frozen_wake = false;
  const LinearModel fz = linearize(m, op, frozen), qs = linearize(m, op, induction);
  for (int r = 0; r < static_cast<int>(cols.size()); ++r)
    for (int c = 0; c < static_cast<int>(cols.size()); ++c) {
      // The induction does change them: the frozen wake's K, C differ from the quasi-steady ones.
      EXPECT_GT(std::abs(qs.C(r, c) - fz.C(r, c)), 1e-3 * std::abs(qs.C(r, c)));
      EXPECT_NEAR(fz.K(r, c) + dK(cols[r], c), qs.K(r, c), 1e-9 * std::abs(qs.K(r, c)));
      EXPECT_NEAR(fz.C(r, c) + dC(cols[r], c), qs.C(r, c), 1e-9 * std::abs(qs.C(r, c)));
    }
}

// The eigenvalue of the flap mode nearest `target` among A's.
std::complex<double> nearest(const MatX& A, std::complex<double> target) {
  const Eigen::EigenSolver<MatX> es(A);
  std::complex<double> best = es.eigenvalues()(0);
  for (Eigen::Index k = 1; k < es.eigenvalues().size(); ++k)
    if (std::abs(es.eigenvalues()(k) - target) < std::abs(best - target)) best = es.eigenvalues()(k);
  return best;
}

// The two limits of τ1 (UA states out): a fast wake (τ1 → 0) follows v_qs at once, and the flap mode tends to
// the quasi-steady-induction model's; a slow one (OpenFAST's 100 s here) hardly moves over a flap period,
// and the mode tends to the frozen wake's. The slow limit holds where every element's loads see the states:
// the elements with fixed inductions (tip and hub loss constants 0: here the tip node, a quarter of the
// blade's loads) keep the BEM ones, quasi-steady at any τ1, as in AeroDyn; without the losses none has.
TEST(DynamicInflowLinear, FastAndSlowInflowLimits) {
  Model m = readElastoDynModel((referenceDir() / "case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst").string(),
                               {"TipLoss=False", "HubLoss=False"});
  removeUnsteadyAirfoils(m.aero);
  const OperatingPoint op = equilibrium(m);
  LinearizeOptions frozen, induction;
  frozen.unsteady_aero = false;
  frozen.inputs = induction.inputs = false;
  induction.frozen_wake = false;
  const LinearModel fz = linearize(m, op, frozen), qs = linearize(m, op, induction);
  const Eigen::EigenSolver<MatX> efz(fz.A), eqs(qs.A);
  auto flap = [](const Eigen::EigenSolver<MatX>& es) {  // the root with positive imaginary part
    for (Eigen::Index k = 0; k < es.eigenvalues().size(); ++k)
      if (es.eigenvalues()(k).imag() > 0) return es.eigenvalues()(k);
    return es.eigenvalues()(0);
  };
  const std::complex<double> l_fz = flap(efz), l_qs = flap(eqs);
  ASSERT_GT(std::abs(l_fz - l_qs), 1e-2 * std::abs(l_qs));  // the limits differ
  LinearizeOptions with;
  with.inputs = false;
  Model fast = m;
  fast.aero.tau1 = 1e-4;
  const std::complex<double> l_fast = nearest(linearize(fast, op, with).A, l_qs);
  const std::complex<double> l_slow = nearest(linearize(m, op, with).A, l_fz);
  // Measured: 4.1e-6 (τ1 = 1e-4 s) and 1.4e-4 (τ1 = 100 s) of |λ|, the two limits 0.52 apart.
  EXPECT_LT(std::abs(l_fast - l_qs), 1e-5 * std::abs(l_qs)) << l_fast << " " << l_qs;
  EXPECT_LT(std::abs(l_slow - l_fz), 5e-4 * std::abs(l_fz)) << l_slow << " " << l_fz;
  EXPECT_GT(std::abs(l_slow - l_qs), std::abs(l_slow - l_fz));
}

// With the deck's skewed-wake correction (Skew_Mod 1: the 5° shaft tilt skews the wake by about 5°) the
// dynamic-inflow states rest at the uncorrected BEM induction, their rates 0, and the frozen wake of the point
// is that induction corrected, element by element, by the factor the loads with the states apply: those loads
// equal the frozen wake's (AeroDyn BEMT_CalcOutput_Inductions: DBEMT, then ApplySkewedWakeCorrection_AllNodes).
// Fails when the correction is applied before DBEMT or not to the states' loads.
TEST(DynamicInflowLinear, SkewedWakeCorrectsTheFrozenWake) {
  // Without the UA states, whose loads reconstruct the static polar only to about 1 % here.
  const Model m = readElastoDynModel((referenceDir() / "case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst").string(),
                                     {"UA_Mod=0"});
  ASSERT_GT(m.aero.skew_factor, 1.47);  // "default": 15π/32
  const OperatingPoint op = equilibrium(m);
  const VecX z = unsteadyAeroSteadyStates(m, op);
  const int nua = uaStateCount(m.aero);
  Workspace<double> ws(m);
  forwardKinematics(m, ws, op.q, op.qd, op.qdd);
  VecX e_states = VecX::Zero(m.ndof()), e_frozen = VecX::Zero(m.ndof()), zdot = VecX::Zero(z.size());
  addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, &z, e_states, &zdot);
  addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, nullptr, e_frozen, nullptr);
  EXPECT_LT(zdot.tail(16).cwiseAbs().maxCoeff(), 1e-10);
  int corrected = 0;
  for (int i = 0; i < 4; ++i) {
    const double ratio = op.inflow.axial(i) / z(nua + 4 * i);
    if (std::abs(ratio - 1) > 1e-6) ++corrected;
    EXPECT_LT(std::abs(ratio - 1), 0.1) << "element " << i + 1;
    EXPECT_NEAR(z(nua + 4 * i + 1), op.inflow.tangential(i), 1e-12 * std::max(1.0, std::abs(op.inflow.tangential(i))));
  }
  EXPECT_GE(corrected, 2);
  EXPECT_LT((e_states - e_frozen).cwiseAbs().maxCoeff(), 1e-9 * e_frozen.cwiseAbs().maxCoeff());
}

}  // namespace

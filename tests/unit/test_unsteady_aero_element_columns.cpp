// The aerodynamic states' Jacobian columns formed element by element (linearize/unsteady_aero.cpp, issue 47
// "Numbers"): a state of element i enters only element i's loads and rates, so unsteadyAeroLinear evaluates
// each element's state columns with that element alone (addUnsteadyAeroLoads' element filter). Checked
// against the independent path it replaced: chunks of 8 states seeded through every element of every blade.
// The same path checks the columns of q, q̇ and u, whose directions a column that moves one blade only shares
// with the other blades' (their loads evaluated one blade at a time, addUnsteadyAeroLoads' blade filter).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "linearize/operating_point.hpp"
#include "linearize/unsteady_aero.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/reference.hpp"

namespace {

using namespace whirl;

// The blocks of every column by the former path: each chunk of 8 columns (q, q̇, u, then the states in z's
// order) seeded through the whole addUnsteadyAeroLoads, e_UA − e_QS on the columns of q, q̇, u.
UnsteadyAeroLinear allElementsSeeded(const Model& m, const OperatingPoint& op, const VecX& states,
                                     const std::vector<int>& cols, bool inputs) {
  const int n = m.ndof(), nz = static_cast<int>(states.size()), nc = static_cast<int>(cols.size());
  const int nu = inputs ? m.ninput() : 0, ntot = 2 * nc + nu + nz;
  auto load = [](const VecX& v) {
    VecXT<ADChunk> a(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) a(i) = ADChunk(v(i));
    return a;
  };
  VecXT<ADChunk> q = load(op.q), qd = load(op.qd), qdd = load(op.qdd), u = load(op.u), z = load(states);
  VecXT<ADChunk> e_ua(n), e_qs(n), zdot(nz);
  // Column c: q, q̇, u (with the frozen coordinates it drives, at its gain) or state.
  auto seed = [&](int c, int k, double s) {
    if (c < nc) q(cols[c]).derivatives()(k) = s;
    else if (c < 2 * nc) qd(cols[c - nc]).derivatives()(k) = s;
    else if (c < 2 * nc + nu) {
      u(c - 2 * nc).derivatives()(k) = s;
      for (const InputDofTarget& t : m.inputs[c - 2 * nc].dofs) q(t.dof).derivatives()(k) = s * t.gain;
    } else z(c - 2 * nc - nu).derivatives()(k) = s;
  };
  Workspace<ADChunk> ws(m);
  MatX Je(n, ntot), Jz(nz, ntot);
  for (int c0 = 0; c0 < ntot; c0 += kChunk) {
    const int w = std::min(kChunk, ntot - c0);
    for (int k = 0; k < w; ++k) seed(c0 + k, k, 1.0);
    forwardKinematics(m, ws, q, qd, qdd);
    for (int i = 0; i < n; ++i) e_ua(i) = e_qs(i) = ADChunk(0.0);
    addUnsteadyAeroLoads<ADChunk>(m, ws, q, qd, u, op.inflow, &z, e_ua, &zdot);
    addUnsteadyAeroLoads<ADChunk>(m, ws, q, qd, u, op.inflow, nullptr, e_qs, nullptr);
    for (int k = 0; k < w; ++k) {
      const bool state = c0 + k >= 2 * nc + nu;
      for (int i = 0; i < n; ++i) Je(i, c0 + k) = e_ua(i).derivatives()(k) - (state ? 0.0 : e_qs(i).derivatives()(k));
      for (int i = 0; i < nz; ++i) Jz(i, c0 + k) = zdot(i).derivatives()(k);
    }
    for (int k = 0; k < w; ++k) seed(c0 + k, k, 0.0);
  }
  UnsteadyAeroLinear out;
  out.dK = -Je.leftCols(nc);
  out.dC = -Je.middleCols(nc, nc);
  out.dQ = Je.middleCols(2 * nc, nu);
  out.G = Je.rightCols(nz);
  out.Zq = Jz.leftCols(nc);
  out.Zqd = Jz.middleCols(nc, nc);
  out.Zu = Jz.middleCols(2 * nc, nu);
  out.Azz = Jz.rightCols(nz);
  return out;
}

// Every block of unsteadyAeroLinear at op equals the former path's to 1e-12 of the block's largest entry
// (the same operations on each element: equal to round-off).
void expectSameBlocks(const Model& m, const OperatingPoint& op) {
  const std::vector<int> cols = m.activeDofs();
  const UnsteadyAeroLinear now = unsteadyAeroLinear(m, op, cols, true);
  const UnsteadyAeroLinear ref = allElementsSeeded(m, op, now.z, cols, true);
  auto same = [](const char* what, const MatX& a, const MatX& b) {
    ASSERT_EQ(a.rows(), b.rows()) << what;
    ASSERT_EQ(a.cols(), b.cols()) << what;
    const double scale = b.cwiseAbs().maxCoeff();
    EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-12 * scale) << what;
  };
  same("dK", now.dK, ref.dK);
  same("dC", now.dC, ref.dC);
  same("dQ", now.dQ, ref.dQ);
  same("Zq", now.Zq, ref.Zq);
  same("Zqd", now.Zqd, ref.Zqd);
  same("Zu", now.Zu, ref.Zu);
  same("G", now.G, ref.G);
  same("Azz", now.Azz, ref.Azz);
  // The comparison means something: the states' blocks are not empty (x3 and v1 enter the rates only).
  EXPECT_GT(now.G.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(now.Azz.cwiseAbs().maxCoeff(), 0.0);
}

std::string deck(const char* path) { return (std::filesystem::path(WHIRL_SOURCE_DIR) / path).string(); }

TEST(UnsteadyAeroElementColumns, OneBladeRTestDeckWithUaAndDynamicInflow) {
  // OpenFAST r-test Fake5MW_AeroLin_B1_UA4_DBEMT3: UA on elements 2-4, DBEMT on elements 1-4 (element 1 has
  // dynamic-inflow states only).
  const Model m = readElastoDynModel(deck("tests/data/openfast-lin/ua4-dbemt3/case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst"));
  ASSERT_EQ(uaStateCount(m.aero), 12);
  ASSERT_EQ(inflowStateCount(m.aero), 16);
  expectSameBlocks(m, solveOperatingPoint(m, initialPoint(m)));
}

// The NREL 5MW (cases/nrel5mw/Main_Aero.fst, UA_Mod 4 from the airfoil files' UA data) at rated, 11.4 m/s
// and 12.1 rpm, pitch 0: three blades that see different flows (gravity, shear), so a state's columns
// given to another element, of its blade or of another, differ from the reference.
TEST(UnsteadyAeroElementColumns, Nrel5mwWithUa) {
  const Model m = readElastoDynModel(deck("cases/nrel5mw/Main_Aero.fst"), {"AFAeroMod=2", "UAMod=4"});
  ASSERT_EQ(uaStateCount(m.aero), 180);
  expectSameBlocks(m, test::nrel5mwRatedPoint(m));
}

TEST(UnsteadyAeroElementColumns, Nrel5mwWithUaAndDynamicInflow) {
  const Model m = readElastoDynModel(deck("cases/nrel5mw/Main_Aero.fst"),
                                     {"AFAeroMod=2", "UAMod=4", "WakeMod=2", "DBEMT_Mod=3"});
  ASSERT_EQ(aeroStateCount(m.aero), 180 + 228);
  expectSameBlocks(m, test::nrel5mwRatedPoint(m));
}

// The NREL 5MW at rated with UA and DBEMT, the kinematics at the point, and what addUnsteadyAeroLoads gives for
// every element at once (in double, at the point's steady states): the reference of the filter tests.
struct EveryElement {
  Model m = readElastoDynModel(deck("cases/nrel5mw/Main_Aero.fst"),
                               {"AFAeroMod=2", "UAMod=4", "WakeMod=2", "DBEMT_Mod=3"});
  OperatingPoint op = test::nrel5mwRatedPoint(m);
  VecX z = unsteadyAeroSteadyStates(m, op);
  Workspace<double> ws{m};
  VecX e = VecX::Zero(m.ndof()), zdot = VecX::Zero(z.size());

  EveryElement() {
    forwardKinematics(m, ws, op.q, op.qd, op.qdd);
    addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, &z, e, &zdot);
  }
  /// The loads and rates of a filtered call: element `el` alone, or blade `b` alone.
  void add(VecX& sum, VecX& rates, int el, int b) {
    addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, &z, sum, &rates, nullptr, nullptr, el, false,
                                 nullptr, b);
  }
};

TEST(UnsteadyAeroElementColumns, ElementFilterGivesThatElementsShareOfTheLoads) {
  // The loads of all elements are the sum of each element's alone.
  EveryElement all;
  VecX sum = VecX::Zero(all.m.ndof()), zdot = VecX::Constant(all.z.size(), 7.0);
  for (int el = 0; el < all.m.aero.nstations(); ++el) all.add(sum, zdot, el, -1);
  EXPECT_LE((sum - all.e).cwiseAbs().maxCoeff(), 1e-12 * all.e.cwiseAbs().maxCoeff());
  EXPECT_EQ(zdot, all.zdot);  // every rate written once, by its own element (none left at 7)
}

TEST(UnsteadyAeroElementColumns, BladeFilterGivesThatBladesShareOfTheLoads) {
  // The loads of all blades are the sum of each blade's alone, and each blade writes its own states' rates.
  EveryElement all;
  VecX sum = VecX::Zero(all.m.ndof()), zdot = VecX::Constant(all.z.size(), 7.0);
  for (int b = 0; b < static_cast<int>(all.m.aero.blades.size()); ++b) {
    VecX one = VecX::Zero(all.m.ndof());
    all.add(one, zdot, -1, b);
    EXPECT_GT(one.cwiseAbs().maxCoeff(), 0.01 * all.e.cwiseAbs().maxCoeff()) << "blade " << b + 1;
    sum += one;
  }
  EXPECT_LE((sum - all.e).cwiseAbs().maxCoeff(), 1e-12 * all.e.cwiseAbs().maxCoeff());
  EXPECT_EQ(zdot, all.zdot);
}

}  // namespace

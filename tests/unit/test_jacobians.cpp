// Cross-checks of independent paths (CONTRIBUTING.md, tests: cross-check independent paths):
//  - the AD Jacobians ∂e/∂q, ∂e/∂q̇, ∂e/∂u equal central finite differences;
//  - ∂e/∂q̈ (AD) equals the mass matrix assembled in double, to round-off;
//  - the assembled mass matrix is symmetric;
//  - the residual values a K pass returns equal the double residual;
//  - a reused workspace (values cached per point) gives what a fresh one gives at a new point.
#include <gtest/gtest.h>

#include <random>

#include "linearize/jacobian.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"
#include "tests/support/rich_model.hpp"

namespace whirl {
namespace {

struct State {
  VecX q, qd, qdd, u;
};

State randomState(const Model& m, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  State s{VecX(m.ndof()), VecX(m.ndof()), VecX(m.ndof()), VecX(m.ninput())};
  for (int i = 0; i < m.ndof(); ++i) {
    const bool elastic = m.dofs[i].kind == DofKind::Elastic;
    s.q(i) = (elastic ? 0.5 : 0.2) * d(gen);
    s.qd(i) = (elastic ? 0.8 : 0.3) * d(gen);
    s.qdd(i) = d(gen);
  }
  for (int i = 0; i < m.ninput(); ++i) s.u(i) = m.inputs[i].value * (1 + 0.1 * d(gen));
  return s;
}

// Central differences of e along one argument, column by column.
MatX finiteDifference(const Model& m, const State& s, Wrt wrt) {
  Workspace<double> ws(m);
  const int ncol = wrt == Wrt::U ? m.ninput() : m.ndof();
  MatX J(m.ndof(), ncol);
  VecX ep(m.ndof()), em(m.ndof());
  for (int c = 0; c < ncol; ++c) {
    State p = s, n = s;
    VecX& xp = wrt == Wrt::Q ? p.q : wrt == Wrt::Qd ? p.qd : wrt == Wrt::Qdd ? p.qdd : p.u;
    VecX& xn = wrt == Wrt::Q ? n.q : wrt == Wrt::Qd ? n.qd : wrt == Wrt::Qdd ? n.qdd : n.u;
    const double h = 1e-6 * std::max(1.0, std::abs(xp(c)));
    xp(c) += h;
    xn(c) -= h;
    residual(m, ws, p.q, p.qd, p.qdd, p.u, ep);
    residual(m, ws, n.q, n.qd, n.qdd, n.u, em);
    J.col(c) = (ep - em) / (2 * h);
  }
  return J;
}

std::vector<int> allColumns(int n) {
  std::vector<int> c(n);
  for (int i = 0; i < n; ++i) c[i] = i;
  return c;
}

class Jacobians : public ::testing::TestWithParam<bool> {};

TEST_P(Jacobians, AdEqualsCentralFiniteDifferences) {
  const Model m = test::richModel(GetParam());
  JacobianWorkspace jw(m);
  for (unsigned seed : {1u, 2u}) {
    const State s = randomState(m, seed);
    for (Wrt wrt : {Wrt::Q, Wrt::Qd, Wrt::U}) {
      const int ncol = wrt == Wrt::U ? m.ninput() : m.ndof();
      const MatX ad = residualJacobian(m, jw, s.q, s.qd, s.qdd, s.u, wrt, allColumns(ncol));
      const MatX fd = finiteDifference(m, s, wrt);
      // Central differences with h = 1e-6 carry ~1e-9 relative truncation and round-off error;
      // compare entrywise against the scale of each row.
      for (int r = 0; r < m.ndof(); ++r) {
        const double scale = std::max(ad.row(r).cwiseAbs().maxCoeff(), 1e-3);
        for (int c = 0; c < ncol; ++c)
          ASSERT_NEAR(ad(r, c), fd(r, c), 1e-6 * scale)
              << "row " << m.dofs[r].name << " col " << c << " wrt " << static_cast<int>(wrt) << " seed " << seed;
      }
    }
  }
}

TEST_P(Jacobians, AdMassEqualsAssembledMassMatrix) {
  const Model m = test::richModel(GetParam());
  JacobianWorkspace jw(m);
  Workspace<double> ws(m);
  for (unsigned seed : {3u, 4u, 5u}) {
    const State s = randomState(m, seed);
    const MatX dedqdd = residualJacobian(m, jw, s.q, s.qd, s.qdd, s.u, Wrt::Qdd, allColumns(m.ndof()));
    MatX M;
    massMatrix(m, ws, s.q, M);
    const double scale = M.cwiseAbs().maxCoeff();
    EXPECT_LT((M + dedqdd).cwiseAbs().maxCoeff(), 1e-12 * scale) << "seed " << seed;
    EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  }
}

// A simulation's Newton step takes M from the kinematics its residual left in the workspace: the
// positions there must not depend on the rates the residual was evaluated with.
TEST_P(Jacobians, MassAtTheResidualsKinematicsEqualsTheMassMatrix) {
  const Model m = test::richModel(GetParam());
  Workspace<double> ws(m), fresh(m);
  for (unsigned seed : {10u, 11u}) {
    const State s = randomState(m, seed);
    VecX e(m.ndof());
    residual(m, ws, s.q, s.qd, s.qdd, s.u, e);
    MatX at_kinematics, M;
    massMatrixAtKinematics(m, ws, at_kinematics);
    massMatrix(m, fresh, s.q, M);
    // The same sums, partly formed by the residual (its shape-integral products): equal to round-off.
    EXPECT_LE((at_kinematics - M).cwiseAbs().maxCoeff(), 1e-14 * M.cwiseAbs().maxCoeff()) << "seed " << seed;
  }
}

TEST_P(Jacobians, ValuesOfAKPassEqualTheDoubleResidual) {
  const Model m = test::richModel(GetParam());
  JacobianWorkspace jw(m);
  Workspace<double> ws(m);
  for (unsigned seed : {6u, 7u}) {
    const State s = randomState(m, seed);
    VecX value;
    residualJacobian(m, jw, s.q, s.qd, s.qdd, s.u, Wrt::Q, allColumns(m.ndof()), &value);
    ASSERT_EQ(value.size(), m.ndof()) << "the first K chunk seeds the root coordinates: every body varies";
    VecX e(m.ndof());
    residual(m, ws, s.q, s.qd, s.qdd, s.u, e);
    EXPECT_LT((value - e).cwiseAbs().maxCoeff(), 1e-12 * e.cwiseAbs().maxCoeff()) << "seed " << seed;
    // A q̇ pass skips the load terms: its values are incomplete and not returned.
    residualJacobian(m, jw, s.q, s.qd, s.qdd, s.u, Wrt::Qd, allColumns(m.ndof()), &value);
    if (value.size() > 0) {
      EXPECT_LT((value - e).cwiseAbs().maxCoeff(), 1e-12 * e.cwiseAbs().maxCoeff());
    }
  }
}

TEST_P(Jacobians, ReusedWorkspaceEqualsFreshAtANewPoint) {
  const Model m = test::richModel(GetParam());
  JacobianWorkspace reused(m);
  const State a = randomState(m, 8);
  State b = a;
  // Move one elastic coordinate only (its body's cached basis products must be refreshed), then all.
  int elastic = 0;
  while (m.dofs[elastic].kind != DofKind::Elastic) ++elastic;
  b.q(elastic) += 1e-3;
  const State c = randomState(m, 9);
  for (Wrt wrt : {Wrt::Q, Wrt::Qd, Wrt::U}) {
    const int ncol = wrt == Wrt::U ? m.ninput() : m.ndof();
    residualJacobian(m, reused, a.q, a.qd, a.qdd, a.u, wrt, allColumns(ncol));
    for (const State* s : {static_cast<const State*>(&b), &c}) {
      JacobianWorkspace fresh(m);
      const MatX J1 = residualJacobian(m, reused, s->q, s->qd, s->qdd, s->u, wrt, allColumns(ncol));
      const MatX J2 = residualJacobian(m, fresh, s->q, s->qd, s->qdd, s->u, wrt, allColumns(ncol));
      EXPECT_LE((J1 - J2).cwiseAbs().maxCoeff(), 1e-14 * J2.cwiseAbs().maxCoeff()) << "wrt " << static_cast<int>(wrt);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AxialShortening, Jacobians, ::testing::Values(true, false));

}  // namespace
}  // namespace whirl

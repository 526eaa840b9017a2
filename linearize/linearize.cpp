#include "linearize/linearize.hpp"

#include "linearize/jacobian.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace {

// X ← M⁻¹ X with M = Pᵀ L D Lᵀ P from Eigen's LDLT: substitutions on whole rows of X (row-major,
// each step an axpy over all right-hand sides), several times faster than Eigen's blocked triangular
// solves at the sizes of a linear turbine model.
void ldltSolveInPlace(const Eigen::LDLT<MatX>& ldlt, MatX& X) {
  const int n = static_cast<int>(X.rows());
  const MatX& LD = ldlt.matrixLDLT();  // strict lower part: L (unit diagonal); diagonal: D
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Y = ldlt.transpositionsP() * X;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < i; ++k) Y.row(i) -= LD(i, k) * Y.row(k);
  for (int i = 0; i < n; ++i) Y.row(i) /= LD(i, i);
  for (int i = n - 1; i >= 0; --i)
    for (int k = i + 1; k < n; ++k) Y.row(i) -= LD(k, i) * Y.row(k);
  X = ldlt.transpositionsP().transpose() * Y;
}

}  // namespace

LinearModel linearize(const Model& m, const OperatingPoint& op, const LinearizeOptions& opt) {
  LinearizeWorkspace lw(m);
  return linearize(m, op, lw, opt);
}

LinearModel linearize(const Model& m, const OperatingPoint& op, LinearizeWorkspace& lw, const LinearizeOptions& opt) {
  requireActiveDof(m, m.name);  // an empty mass matrix has no LDLᵀ to check (vectorD().minCoeff())
  LinearModel lin;
  lin.dofs = m.activeDofs();
  const int n = static_cast<int>(lin.dofs.size());
  for (int i : lin.dofs) lin.dof_names.push_back(m.dofs[i].name);
  for (const auto& in : m.inputs) lin.input_names.push_back(in.name);
  const int nu = opt.inputs ? m.ninput() : 0;
  std::vector<int> inputs(nu);
  for (int i = 0; i < nu; ++i) inputs[i] = i;

  Workspace<double>& ws = lw.ws;
  JacobianWorkspace& jw = lw.jw;
  auto rows = [&](const MatX& J, double sign) {
    MatX out(n, J.cols());
    if (J.cols() == 0) return out;  // no inputs: J.row(k) of an empty matrix would offset a null pointer
    for (int r = 0; r < n; ++r) out.row(r) = sign * J.row(lin.dofs[r]);
    return out;
  };
  // Without induction (AeroDyn WakeMod = 0) there is nothing to freeze.
  const AeroInflow* frozen = m.aero.active() && m.aero.induction && opt.frozen_wake ? &op.inflow : nullptr;
  if (frozen && static_cast<int>(frozen->axial.size()) != m.aero.nstations())
    throw ComputeError("frozen-wake linearization: the operating point carries no induction of the blade elements "
                       "(solve it with solveOperatingPoint)");
  VecX e;  // e at the point, from a K pass that evaluated every term, or in double below
  lin.K = rows(residualJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Q, lin.dofs, &e, frozen), -1.0);
  lin.C = rows(residualJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Qd, lin.dofs, nullptr, frozen), -1.0);
  lin.Q = nu > 0 ? rows(residualJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::U, inputs, nullptr, frozen), 1.0)
                 : MatX(n, 0);
  MatX Mfull;
  massMatrix(m, ws, op.q, Mfull);
  lin.M.resize(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) lin.M(r, c) = Mfull(lin.dofs[r], lin.dofs[c]);
  if (e.size() != m.ndof()) {
    e.resize(m.ndof());
    residual(m, ws, op.q, op.qd, op.qdd, op.u, e, frozen);
  }
  lin.residual.resize(n);
  for (int r = 0; r < n; ++r) lin.residual(r) = e(lin.dofs[r]);

  Eigen::LDLT<MatX> ldlt(lin.M);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() <= 0)
    throw ComputeError("the mass matrix is not positive definite: a coordinate without inertia? (check masses, "
                       "inertias and which DOFs are frozen)");
  // One solve with the right-hand sides [K C Q].
  MatX rhs(n, 2 * n + nu);
  rhs << lin.K, lin.C, lin.Q;
  ldltSolveInPlace(ldlt, rhs);
  lin.A = MatX::Zero(2 * n, 2 * n);
  lin.A.block(0, n, n, n).setIdentity();
  lin.A.block(n, 0, n, 2 * n) = -rhs.leftCols(2 * n);
  lin.B = MatX::Zero(2 * n, nu);
  if (nu > 0) lin.B.block(n, 0, n, nu) = rhs.rightCols(nu);
  return lin;
}

}  // namespace whirl

#include "linearize/linearize.hpp"

#include <utility>

#include "linearize/jacobian.hpp"
#include "linearize/unsteady_aero.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"

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

// The first-order states of Model::body_states on the active coordinates: G (n × nz), the loads C z on
// the free joints' coordinates, and Bz (nz × n), ż = A z + Bz q̇; names and groups into `lin`.
void firstOrderStates(const Model& m, LinearModel& lin, MatX& G, MatX& Bz) {
  const int n = static_cast<int>(lin.dofs.size());
  int nz = 0;
  for (const BodyStateSpace& bs : m.body_states) nz += static_cast<int>(bs.A.rows());
  G = MatX::Zero(n, nz);
  Bz = MatX::Zero(nz, n);
  int z0 = 0;
  for (const BodyStateSpace& bs : m.body_states) {
    const int d0 = m.bodies[bs.body].joint_dof, k = static_cast<int>(bs.A.rows());
    for (int c = 0; c < n; ++c) {
      const int r = lin.dofs[c] - d0;  // a frozen coordinate does not move: no column
      if (r < 0 || r >= 6) continue;
      G.block(c, z0, 1, k) = bs.C.row(r);
      Bz.block(z0, c, k, 1) = bs.B.col(r);
    }
    for (int j = 0; j < k; ++j) {
      int within = 1;
      for (int i = 0; i < j; ++i) within += bs.groups[i] == bs.groups[j];
      lin.first_order_groups.push_back(bs.groups[j]);
      lin.first_order_names.push_back(bs.groups[j] + " " + std::to_string(within));
    }
    z0 += k;
  }
}

// The unsteady-airfoil states (linearize/unsteady_aero.hpp) after the body states: K, C, Q take the UA loads'
// changes, G their columns, and Zq = [Z_q, Z_q̇] (on the active coordinates), Za = A_zz, Zu = Z_u their rows;
// names, groups and steady values into lin.
void addUnsteadyAero(const Model& m, const OperatingPoint& op, bool inputs, LinearizeWorkspace& lw, LinearModel& lin,
                     MatX& G, MatX& Zq, MatX& Za, MatX& Zu) {
  UnsteadyAeroLinear ua = unsteadyAeroLinear(m, op, lin.dofs, inputs, lw.ws, lw.jw);
  const int n = static_cast<int>(lin.dofs.size()), nb = static_cast<int>(G.cols());
  const int nz = static_cast<int>(ua.z.size());
  for (int r = 0; r < n; ++r) {
    lin.K.row(r) += ua.dK.row(lin.dofs[r]);
    lin.C.row(r) += ua.dC.row(lin.dofs[r]);
    if (inputs) lin.Q.row(r) += ua.dQ.row(lin.dofs[r]);
  }
  G.conservativeResize(n, nb + nz);
  for (int r = 0; r < n; ++r) G.block(r, nb, 1, nz) = ua.G.row(lin.dofs[r]);
  Zq.resize(nz, 2 * n);
  Zq << ua.Zq, ua.Zqd;
  Za = std::move(ua.Azz);  // nz² entries
  Zu = ua.Zu;
  lin.first_order_names.insert(lin.first_order_names.end(), ua.names.begin(), ua.names.end());
  lin.first_order_groups.insert(lin.first_order_groups.end(), ua.groups.begin(), ua.groups.end());
  for (std::size_t b = 0; b < m.aero.blades.size(); ++b)
    for (const AeroStation& st : m.aero.blades[b].stations)
      if (st.ua)
        lin.first_order_blades.insert(lin.first_order_blades.end(), uaStatesPerElement(m.aero), static_cast<int>(b));
  for (std::size_t b = 0; b < m.aero.blades.size(); ++b)  // the dynamic-inflow states, after the UA ones
    lin.first_order_blades.insert(lin.first_order_blades.end(),
                                  inflowStatesPerElement(m.aero) * m.aero.blades[b].stations.size(),
                                  static_cast<int>(b));
  lin.first_order_values.conservativeResize(nb + nz);
  lin.first_order_values.tail(nz) = ua.z;
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
    throw ComputeError(
        "frozen-wake linearization: the operating point carries no induction of the blade elements "
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
    throw ComputeError(
        "the mass matrix is not positive definite: a coordinate without inertia? (check masses, "
        "inertias and which DOFs are frozen)");
  MatX G, Bz;  // loads of the first-order states on the coordinates, their drive by the rates
  firstOrderStates(m, lin, G, Bz);
  const int nb = static_cast<int>(G.cols());  // body states, then the unsteady-airfoil states
  lin.first_order_values = VecX::Zero(nb);
  lin.first_order_blades.assign(static_cast<std::size_t>(nb), -1);
  MatX Zq, Za, Zu;  // the UA rows: [Z_q, Z_q̇] on the active coordinates, A_zz, Z_u
  // The aerodynamic states linearize on a frozen induction: the point's BEM induction, or none (WakeMod 0:
  // op.inflow holds zeros, the geometric inflow the quasi-steady passes above take). AeroDyn keeps UA with
  // WakeMod 0 (its BEMT runs with UseInduction false); only the quasi-steady-induction linearization
  // (opt.frozen_wake false) has no frozen induction to carry them.
  const bool unsteady = opt.unsteady_aero && aeroStateCount(m.aero) > 0 && (frozen || !m.aero.induction);
  if (unsteady) addUnsteadyAero(m, op, nu > 0, lw, lin, G, Zq, Za, Zu);
  const int nz = static_cast<int>(G.cols());
  // One solve with the right-hand sides [K C G Q] (K, C, Q with the UA loads' changes, if any).
  MatX rhs(n, 2 * n + nz + nu);
  rhs << lin.K, lin.C, G, lin.Q;
  ldltSolveInPlace(ldlt, rhs);
  lin.A = MatX::Zero(2 * n + nz, 2 * n + nz);
  lin.A.block(0, n, n, n).setIdentity();
  lin.A.block(n, 0, n, 2 * n) = -rhs.leftCols(2 * n);
  if (nz > 0) {
    lin.A.block(n, 2 * n, n, nz) = rhs.middleCols(2 * n, nz);
    lin.A.block(2 * n, n, nb, n) = Bz;
    int z0 = 0;
    for (const BodyStateSpace& bs : m.body_states) {
      lin.A.block(2 * n + z0, 2 * n + z0, bs.A.rows(), bs.A.rows()) = bs.A;
      z0 += static_cast<int>(bs.A.rows());
    }
    if (nz > nb) {
      lin.A.block(2 * n + nb, 0, nz - nb, 2 * n) = Zq;
      lin.A.block(2 * n + nb, 2 * n + nb, nz - nb, nz - nb) = Za;
    }
  }
  lin.B = MatX::Zero(2 * n + nz, nu);
  if (nu > 0) lin.B.block(n, 0, n, nu) = rhs.rightCols(nu);
  if (nu > 0 && nz > nb) lin.B.bottomRows(nz - nb) = Zu;
  return lin;
}

}  // namespace whirl

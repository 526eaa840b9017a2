#include "linearize/jacobian.hpp"

#include <cassert>

#include "src/base/error.hpp"
#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace {

// Seeds direction k of column `col` (value ±1 sets, 0 clears), with the chain rule through the
// frozen coordinates an input drives.
void seed(const Model& m, JacobianWorkspace& jw, Wrt wrt, int col, int k, bool on) {
  VecXT<ADChunk>& x = wrt == Wrt::Q     ? jw.q
                      : wrt == Wrt::Qd  ? jw.qd
                      : wrt == Wrt::Qdd ? jw.qdd
                      : wrt == Wrt::Z   ? jw.z
                                        : jw.u;
  x(col).derivatives()(k) = on ? 1.0 : 0.0;
  if (wrt != Wrt::U) return;
  for (const InputDofTarget& t : m.inputs[col].dofs) jw.q(t.dof).derivatives()(k) = on ? t.gain : 0.0;
}

// Double kinematics at (q, q̇, q̈) in jw.kin, recomputed only when the point changed.
void pointKinematics(const Model& m, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd) {
  auto same = [](const VecX& a, const VecX& b) { return a.size() == b.size() && (a.array() == b.array()).all(); };
  if (same(jw.kin_q, q) && same(jw.kin_qd, qd) && same(jw.kin_qdd, qdd)) return;
  forwardKinematics(m, jw.kin, q, qd, qdd);
  jw.kin_q = q;
  jw.kin_qd = qd;
  jw.kin_qdd = qdd;
}

// z (if given): the aerodynamic states, loaded into jw.z (Wrt::Z seeds them).
template <class Eval>
MatX jacobian(const Model& m, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd, const VecX& u,
              Wrt wrt, const std::vector<int>& cols, VecXT<ADChunk>& f, Eval eval, const VecX* z = nullptr) {
  auto load = [](VecXT<ADChunk>& dst, const VecX& src) {
    for (Eigen::Index i = 0; i < src.size(); ++i) dst(i) = ADChunk(src(i));  // zero derivatives
  };
  load(jw.q, q);
  load(jw.qd, qd);
  load(jw.qdd, qdd);
  load(jw.u, u);
  if (z) {
    jw.z.resize(z->size());
    load(jw.z, *z);
  }
  pointKinematics(m, jw, q, qd, qdd);
  const int n = static_cast<int>(f.size());
  const int ncol = static_cast<int>(cols.size());
  MatX J(n, ncol);
  for (int c0 = 0; c0 < ncol; c0 += kChunk) {
    const int w = std::min(kChunk, ncol - c0);
    for (int k = 0; k < w; ++k) seed(m, jw, wrt, cols[c0 + k], k, true);
    eval();
    for (int r = 0; r < n; ++r)
      for (int k = 0; k < w; ++k) J(r, c0 + k) = f(r).derivatives()(k);
    for (int k = 0; k < w; ++k) seed(m, jw, wrt, cols[c0 + k], k, false);
  }
  return J;
}

}  // namespace

JacobianWorkspace::JacobianWorkspace(const Model& m) : ws(m), kin(m) {
  q.resize(m.ndof());
  qd.resize(m.ndof());
  qdd.resize(m.ndof());
  u.resize(m.ninput());
  e.resize(m.ndof());
  y.resize(m.noutput());
}

MatX residualJacobian(const Model& m, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd,
                      const VecX& u, Wrt wrt, const std::vector<int>& cols, VecX* value, const AeroInflow* frozen) {
  assert(q.size() == m.ndof() && qd.size() == m.ndof() && qdd.size() == m.ndof() && u.size() == m.ninput());
  if (value) value->resize(0);
  // Every pass reads only derivatives, with the double kinematics of the point (kept current by
  // jacobian()) for the frames it does not move.
  const AdPass pass{&jw.kin};
  auto full = [&]() {
    const bool complete = residual(m, jw.ws, jw.q, jw.qd, jw.qdd, jw.u, jw.e, frozen, nullptr, pass);
    if (value && value->size() == 0 && complete) {
      value->resize(m.ndof());
      for (int k = 0; k < m.ndof(); ++k) (*value)(k) = jw.e(k).value();
    }
  };
  if (wrt != Wrt::U) return jacobian(m, jw, q, qd, qdd, u, wrt, cols, jw.e, full);
  // Inputs that move coordinates (pitch) need the whole residual; load inputs only the load terms.
  std::vector<int> kin_cols, load_cols, kin_at, load_at;
  for (int c = 0; c < static_cast<int>(cols.size()); ++c) {
    const bool moves = !m.inputs[cols[c]].dofs.empty();
    (moves ? kin_cols : load_cols).push_back(cols[c]);
    (moves ? kin_at : load_at).push_back(c);
  }
  MatX J(m.ndof(), cols.size());
  if (!kin_cols.empty()) {
    const MatX Jk = jacobian(m, jw, q, qd, qdd, u, wrt, kin_cols, jw.e, full);
    for (size_t c = 0; c < kin_at.size(); ++c) J.col(kin_at[c]) = Jk.col(c);
  }
  if (!load_cols.empty()) {
    pointKinematics(m, jw, q, qd, qdd);
    const MatX Jl = jacobian(m, jw, q, qd, qdd, u, wrt, load_cols, jw.e, [&]() {
      for (int k = 0; k < m.ndof(); ++k) jw.e(k) = ADChunk(0.0);
      addInputLoads(m, jw.kin, jw.kin_qd, jw.u, jw.e);
      // The blade jets of the AD passes at this point serve here too (wind-speed column).
      addAeroLoads<double, ADChunk>(m, jw.kin, jw.kin_q, jw.u, frozen, nullptr, jw.e, 0, nullptr, &jw.ws.jets);
    });
    for (size_t c = 0; c < load_at.size(); ++c) J.col(load_at[c]) = Jl.col(c);
  }
  return J;
}

MatX outputJacobian(const Model& m, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd,
                    const VecX& u, Wrt wrt, const std::vector<int>& cols, const AeroInflow* frozen, const VecX* z) {
  if (wrt == Wrt::Z && !z) throw ComputeError("output Jacobian with respect to the aerodynamic states without states");
  const AdPass pass{&jw.kin};
  return jacobian(
      m, jw, q, qd, qdd, u, wrt, cols, jw.y,
      [&]() { evaluateOutputs(m, jw.ws, jw.q, jw.qd, jw.qdd, jw.y, &jw.u, frozen, pass, z ? &jw.z : nullptr); }, z);
}

}  // namespace whirl

#include "linearize/jacobian.hpp"

#include "src/dynamics/residual.hpp"

namespace whirl {

JacobianWorkspace::JacobianWorkspace(const Model& m) : ws(m) {
  ws.derivatives_only = true;
  q.resize(m.ndof());
  qd.resize(m.ndof());
  qdd.resize(m.ndof());
  u.resize(m.ninput());
  e.resize(m.ndof());
}

MatX residualJacobian(const Model& m, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd,
                      const VecX& u, Wrt wrt, const std::vector<int>& cols) {
  auto load = [](VecXT<ADChunk>& dst, const VecX& src) {
    for (Eigen::Index i = 0; i < src.size(); ++i) dst(i) = ADChunk(src(i));  // zero derivatives
  };
  load(jw.q, q);
  load(jw.qd, qd);
  load(jw.qdd, qdd);
  load(jw.u, u);
  VecXT<ADChunk>& x = wrt == Wrt::Q ? jw.q : wrt == Wrt::Qd ? jw.qd : wrt == Wrt::Qdd ? jw.qdd : jw.u;
  const int n = m.ndof();
  const int ncol = static_cast<int>(cols.size());
  MatX J(n, ncol);
  for (int c0 = 0; c0 < ncol; c0 += kChunk) {
    const int w = std::min(kChunk, ncol - c0);
    for (int k = 0; k < w; ++k) x(cols[c0 + k]).derivatives()(k) = 1.0;
    residual(m, jw.ws, jw.q, jw.qd, jw.qdd, jw.u, jw.e);
    for (int r = 0; r < n; ++r)
      for (int k = 0; k < w; ++k) J(r, c0 + k) = jw.e(r).derivatives()(k);
    for (int k = 0; k < w; ++k) x(cols[c0 + k]).derivatives()(k) = 0.0;
  }
  return J;
}

}  // namespace whirl

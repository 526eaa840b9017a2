#include "src/dynamics/mass_matrix.hpp"

#include <array>

#include "src/dynamics/kinematics.hpp"

namespace whirl {
namespace {
constexpr int eps(int i, int j, int k) { return ((i - j) * (j - k) * (k - i)) / 2; }
}  // namespace

MatX bodyMassMatrix(const BodyInertia& in, const BasisState<double>& b) {
  const int ne = in.ne, nc = in.nc();
  const VecX& c = b.c;
  MatX Mb = MatX::Zero(6 + ne, 6 + ne);
  const Vec3 sbar = in.m1 * c;
  // y_jl = S_jl c serves both the rotational block (Q_jl = cᵀ y_jl) and the coupling rows
  // cᵀ S_jk D = (S_kj c)ᵀ D (S_kj = S_jkᵀ).
  std::array<VecX, 9> y;
  Mat3 Q;
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l) {
      y[3 * j + l].noalias() = in.S[3 * j + l].lazyProduct(c);
      Q(j, l) = c.dot(y[3 * j + l]);
    }
  Mb.block<3, 3>(0, 0) = in.mass * Mat3::Identity();
  Mb.block<3, 3>(0, 3) = -skew<double>(sbar);
  Mb.block<3, 3>(3, 0) = skew<double>(sbar);
  Mb.block<3, 3>(3, 3) = Q.trace() * Mat3::Identity() - Q;
  if (ne == 0) return Mb;
  const MatX& D = b.D;
  Mb.block(0, 6, 3, ne) = in.m1.lazyProduct(D);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        if (eps(i, j, k) != 0) Mb.block(3 + i, 6, 1, ne) += eps(i, j, k) * y[3 * k + j].transpose().lazyProduct(D);
  if (in.Strace.rows() == nc) {
    Mb.block(6, 6, ne, ne) = D.transpose().lazyProduct(in.Strace.lazyProduct(D).eval());
  } else {  // a body that was never finalized
    const MatX Skk = in.S[0] + in.S[4] + in.S[8];
    Mb.block(6, 6, ne, ne) = D.transpose() * Skk * D;
  }
  Mb.block(6, 0, ne, 6) = Mb.block(0, 6, 6, ne).transpose();
  return Mb;
}

void massMatrix(const Model& m, Workspace<double>& ws, const VecX& q, MatX& M) {
  const int n = m.ndof();
  const VecX zero = VecX::Zero(n);
  forwardKinematics(m, ws, q, zero, zero);
  M.setZero(n, n);
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    const FrameState<double>& f = ws.frames[i];
    const std::vector<int>& sup = m.support[i];
    const int ne = b.inertia.ne;
    // B restricted to the columns the body depends on: its support and its own elastic coordinates.
    std::vector<int> cols = sup;
    for (int k = 0; k < ne; ++k) cols.push_back(b.elastic_dof + k);
    MatX B = MatX::Zero(6 + ne, cols.size());
    for (size_t c = 0; c < sup.size(); ++c) {
      B.block<3, 1>(0, c) = f.R.transpose() * f.Jv.col(sup[c]);
      B.block<3, 1>(3, c) = f.R.transpose() * f.Jw.col(sup[c]);
    }
    for (int k = 0; k < ne; ++k) B(6 + k, sup.size() + k) = 1.0;
    const MatX Mb = bodyMassMatrix(b.inertia, ws.basis[i]);
    const MatX Mq = B.transpose().lazyProduct(Mb.lazyProduct(B).eval());
    for (size_t r = 0; r < cols.size(); ++r)
      for (size_t c = 0; c < cols.size(); ++c) M(cols[r], cols[c]) += Mq(r, c);
  }
  for (const BodyMatrices& bm : m.body_matrices) {
    const int d0 = m.bodies[bm.body].joint_dof;
    M.block<6, 6>(d0, d0) += bm.A;
  }
}

}  // namespace whirl

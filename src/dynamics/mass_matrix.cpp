#include "src/dynamics/mass_matrix.hpp"

#include <array>
#include <cassert>

#include "src/dynamics/body_forces.hxx"

namespace whirl {
namespace {
constexpr int eps(int i, int j, int k) { return ((i - j) * (j - k) * (k - i)) / 2; }
}  // namespace

namespace {

// Body mass matrix into Mb ((6 + ne)², zeroed here), with 9 scratch vectors (dim ≥ nc).
// `known`: the position-level products of a residual at the same c (y_jl = S_jl c, Pc = cᵀ y,
// m1c = m1 c; body_forces.hxx), used instead of forming them again; null: formed here.
// Plain loops: the blocks are tiny (nc ≤ ~30), where Eigen's dynamic-size products cost more in
// dispatch than in arithmetic.
void bodyMassMatrixInto(const BodyInertia& in, const BasisState<double>& b, const BasisProducts<double, double>* known,
                        std::array<VecX, 9>& scratch, Eigen::Ref<MatX> Mb) {
  const int ne = in.ne, nc = in.nc();
  const VecX& c = b.c;
  Mb.setZero();
  // S_jl is zero beyond len[j] × len[l] (body.hpp; set by finalize, with Strace).
  const bool finalized = in.Strace.rows() == nc;
  const std::array<int, 3> len = finalized ? in.len : std::array<int, 3>{nc, nc, nc};
  // y_jl = S_jl c serves both the rotational block (Q_jl = cᵀ y_jl) and the coupling rows
  // cᵀ S_jk D = (S_kj c)ᵀ D (S_kj = S_jkᵀ).
  const bool reuse = known && finalized;  // the residual's lengths are the finalized ones
  const std::array<VecX, 9>& y = reuse ? known->y : scratch;
  Vec3 sbar;
  Mat3 Q;
  if (reuse) {
    sbar = known->m1c;
    Q = known->Pc;
  } else {
    for (int j = 0; j < 3; ++j) sbar(j) = detail::dot(in.m1.data() + j, 3, c, nc);
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l) {
        VecX& yjl = scratch[3 * j + l];
        if (finalized) detail::shapeProduct(in, 3 * j + l, c, yjl);
        else detail::matvec(in.S[3 * j + l], c, len[j], len[l], yjl);
        double q = 0;
        for (int p = 0; p < len[j]; ++p) q += c(p) * yjl(p);
        Q(j, l) = q;
      }
  }
  Mb.block<3, 3>(0, 0) = in.mass * Mat3::Identity();
  Mb.block<3, 3>(0, 3) = -skew<double>(sbar);
  Mb.block<3, 3>(3, 0) = skew<double>(sbar);
  Mb.block<3, 3>(3, 3) = Q.trace() * Mat3::Identity() - Q;
  if (ne == 0) return;
  const MatX& D = b.D;
  for (int k = 0; k < ne; ++k) {
    for (int r = 0; r < 3; ++r) {
      double v = 0;
      for (int p = 0; p < nc; ++p) v += in.m1(r, p) * D(p, k);
      Mb(r, 6 + k) = v;
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int kk = 0; kk < 3; ++kk)
          if (eps(i, j, kk) != 0) {
            const VecX& ykj = y[3 * kk + j];
            double v = 0;
            for (int p = 0; p < len[kk]; ++p) v += ykj(p) * D(p, k);
            Mb(3 + i, 6 + k) += eps(i, j, kk) * v;
          }
  }
  // Elastic block Dᵀ (Σ_k S_kk) D, one column of (Σ S_kk) D at a time.
  VecX& t = scratch[0];
  for (int k = 0; k < ne; ++k) {
    for (int p = 0; p < nc; ++p) t(p) = 0;
    for (int q = 0; q < nc; ++q) {
      const double dqk = D(q, k);
      if (dqk == 0.0) continue;
      if (finalized) {
        for (int p = 0; p < nc; ++p) t(p) += in.Strace(p, q) * dqk;
      } else {  // a body that was never finalized
        for (int p = 0; p < nc; ++p) t(p) += (in.S[0](p, q) + in.S[4](p, q) + in.S[8](p, q)) * dqk;
      }
    }
    for (int j = 0; j < ne; ++j) {
      double v = 0;
      for (int p = 0; p < nc; ++p) v += D(p, j) * t(p);
      Mb(6 + j, 6 + k) = v;
    }
  }
  Mb.block(6, 0, ne, 6) = Mb.block(0, 6, 6, ne).transpose();
}

}  // namespace

MatX bodyMassMatrix(const BodyInertia& in, const BasisState<double>& b) {
  std::array<VecX, 9> y;
  for (VecX& v : y) v.resize(in.nc());
  MatX Mb(6 + in.ne, 6 + in.ne);
  bodyMassMatrixInto(in, b, nullptr, y, Mb);
  return Mb;
}

void massMatrix(const Model& m, Workspace<double>& ws, const VecX& q, MatX& M) {
  assert(q.size() == m.ndof());
  forwardKinematics(m, ws, q, ws.mass.zero, ws.mass.zero);
  massMatrixAtKinematics(m, ws, M);
}

void massMatrixAtKinematics(const Model& m, Workspace<double>& ws, MatX& M) {
  const int n = m.ndof();
  MassScratch& s = ws.mass;
  M.setZero(n, n);
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    if (b.inertia.massless && b.inertia.ne == 0) continue;  // no entries
    const FrameState<double>& f = ws.frames[i];
    const std::vector<int>& sup = m.support[i];
    const int ne = b.inertia.ne, nsup = static_cast<int>(sup.size());
    // M += Bᵀ M_b B with B = [Jb 0; 0 I] restricted to the columns the body depends on: its
    // support (Jb = [Rᵀ Jv; Rᵀ Jω], 6 × nsup) and its own elastic coordinates.
    auto Mb = s.Mb.topLeftCorner(6 + ne, 6 + ne);
    const BasisProducts<double, double>* known = ws.body_products_current && b.inertia.ne > 0 ? &ws.body_products[i]
                                                                                              : nullptr;
    bodyMassMatrixInto(b.inertia, ws.basis[i], known, s.y, Mb);
    const Mat3 Rt = f.R.transpose();
    auto Jb = s.Jb.leftCols(nsup);
    for (int c = 0; c < nsup; ++c) {
      Jb.block<3, 1>(0, c).noalias() = Rt * f.Jv.col(sup[c]);
      Jb.block<3, 1>(3, c).noalias() = Rt * f.Jw.col(sup[c]);
    }
    const Eigen::Matrix<double, 6, 6> M66 = Mb.topLeftCorner<6, 6>();
    auto MJ = s.MJ.leftCols(nsup);
    MJ.noalias() = M66 * Jb;
    for (int c = 0; c < nsup; ++c) {
      const Eigen::Matrix<double, 6, 1> mj = MJ.col(c);
      for (int r = 0; r <= c; ++r) {
        const double v = Jb.col(r).dot(mj);
        M(sup[r], sup[c]) += v;
        if (r != c) M(sup[c], sup[r]) += v;
      }
    }
    if (ne == 0) continue;
    const int e0 = b.elastic_dof;
    for (int k = 0; k < ne; ++k) {
      const Eigen::Matrix<double, 6, 1> mk = Mb.block<6, 1>(0, 6 + k);
      for (int r = 0; r < nsup; ++r) {
        const double v = Jb.col(r).dot(mk);
        M(sup[r], e0 + k) += v;
        M(e0 + k, sup[r]) += v;
      }
    }
    M.block(e0, e0, ne, ne) += Mb.block(6, 6, ne, ne);
    if (b.elastic.A.size() > 0) M.block(e0, e0, ne, ne) += b.elastic.A;
  }
  for (const BodyMatrices& bm : m.body_matrices) {
    const int d0 = m.bodies[bm.body].joint_dof;
    M.block<6, 6>(d0, d0) += bm.A;
  }
}

}  // namespace whirl

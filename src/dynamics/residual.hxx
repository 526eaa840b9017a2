#pragma once
#include "src/dynamics/kinematics.hxx"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace detail {

// y[0..rows) = S[0..rows, 0..cols) x for a small dense double matrix and a vector of T (no
// temporaries, no mixed-type GEMV); zero entries of S are skipped.
template <class T>
void matvec(const MatX& S, const VecXT<T>& x, int rows, int cols, VecXT<T>& y) {
  for (int i = 0; i < rows; ++i) y(i) = T(0);
  for (int j = 0; j < cols; ++j) {
    const T& xj = x(j);
    const double* col = S.data() + static_cast<Eigen::Index>(j) * S.rows();
    for (int i = 0; i < rows; ++i)
      if (col[i] != 0.0) y(i) += col[i] * xj;
  }
}

template <class T>
T dot(const double* a, int stride, const VecXT<T>& x, int n) {
  T s(0);
  for (int k = 0; k < n; ++k) s += a[k * stride] * x(k);
  return s;
}

// Inertia and gravity forces of one body on its own virtual motions, body-frame components:
//   F = −∫ a_P dm,  T = −∫ s × a_P dm (about the origin),  H = −Dᵀ ∫ Pᵀ a_P dm,
// with a_P = â + A s + 2 W ṡ + s̈, â = a − g, A = α̃ + ω̃ω̃, W = ω̃, s = P c (seed 001 eq. 13–15, A1–A19).
template <class T>
void bodyInertiaForces(const BodyInertia& in, const BasisState<T>& b, const Vec3T<T>& ahat, const Vec3T<T>& alpha,
                       const Vec3T<T>& omega, Workspace<T>& ws, Vec3T<T>& F, Vec3T<T>& Tq, T* H) {
  const int nc = in.nc();
  const Mat3T<T> W = skew(omega);
  const Mat3T<T> A = skew(alpha) + W * W;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      VecXT<T>& u = ws.ukl[3 * k + l];
      for (int p = 0; p < nc; ++p) u(p) = A(k, l) * b.c(p) + T(2) * W(k, l) * b.cd(p);
      if (k == l)
        for (int p = 0; p < nc; ++p) u(p) += b.cdd(p);
    }
  const std::array<int, 3>& len = in.len;
  // Force.
  for (int k = 0; k < 3; ++k) {
    T s = in.mass * ahat(k);
    for (int l = 0; l < 3; ++l) s += dot(in.m1.data() + l, 3, ws.ukl[3 * k + l], len[l]);
    F(k) = -s;
  }
  // Moment: ∫ s_j (a_P)_k dm = (m1_j·c) â_k + Σ_l (S_lj c)·u_kl.
  Mat3T<T> Q;  // Q(j,k) = ∫ s_j (a_P)_k dm
  for (int j = 0; j < 3; ++j) {
    const T m1c = dot(in.m1.data() + j, 3, b.c, len[j]);
    for (int k = 0; k < 3; ++k) Q(j, k) = m1c * ahat(k);
  }
  for (int l = 0; l < 3; ++l)
    for (int j = 0; j < 3; ++j) {
      matvec(in.S[3 * l + j], b.c, len[l], len[j], ws.tmp);  // S_lj c
      for (int k = 0; k < 3; ++k) {
        const VecXT<T>& u = ws.ukl[3 * k + l];
        T s(0);
        for (int p = 0; p < len[l]; ++p) s += ws.tmp(p) * u(p);
        Q(j, k) += s;
      }
    }
  Tq(0) = -(Q(1, 2) - Q(2, 1));
  Tq(1) = -(Q(2, 0) - Q(0, 2));
  Tq(2) = -(Q(0, 1) - Q(1, 0));
  if (in.ne == 0) return;
  // Elastic: G = Σ_k [m1_kᵀ â_k + Σ_l S_kl u_kl],  H = −Dᵀ G.
  VecXT<T>& G = ws.g;
  for (int p = 0; p < nc; ++p) G(p) = in.m1(0, p) * ahat(0) + in.m1(1, p) * ahat(1) + in.m1(2, p) * ahat(2);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      matvec(in.S[3 * k + l], ws.ukl[3 * k + l], len[k], len[l], ws.tmp);
      for (int p = 0; p < len[k]; ++p) G(p) += ws.tmp(p);
    }
  for (int j = 0; j < in.ne; ++j) {
    T s(0);
    for (int p = 0; p < nc; ++p) s += b.D(p, j) * G(p);
    H[j] = -s;
  }
}

inline bool seeded(double) { return true; }
template <class T>
bool seeded(const T& x) {
  return !x.derivatives().isZero(0.0);
}

// Whether the inertia forces of body i depend on a seeded direction: through its frame (the
// coordinates of its support) or its own elastic coordinates.
template <class T>
bool bodyVaries(const Model& m, int i, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd) {
  auto any = [&](int s) { return seeded(q(s)) || seeded(qd(s)) || seeded(qdd(s)); };
  for (int s : m.support[i])
    if (any(s)) return true;
  const Body& b = m.bodies[i];
  for (int j = 0; j < b.inertia.ne; ++j)
    if (any(b.elastic_dof + j)) return true;
  return false;
}

template <class T>
T inputScale(const VecXT<T>& u, int input) {
  return input >= 0 ? u(input) : T(1);
}

}  // namespace detail

template <class T>
void residual(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
              const VecXT<T>& u, VecXT<T>& e) {
  forwardKinematics(m, ws, q, qd, qdd);
  const int nb = static_cast<int>(m.bodies.size());
  for (int k = 0; k < m.ndof(); ++k) e(k) = T(0);
  const Vec3T<T> gravity = m.gravity.cast<T>();
  T* H = ws.h.data();  // elastic forces of one body (sized to the largest ne)
  for (int i = 0; i < nb; ++i) {
    const Body& b = m.bodies[i];
    if constexpr (!std::is_same_v<T, double>)
      if (ws.derivatives_only && !detail::bodyVaries(m, i, q, qd, qdd)) continue;
    const FrameState<T>& f = ws.frames[i];
    const Mat3T<T> Rt = f.R.transpose();
    const Vec3T<T> ahat = Rt * (f.a - gravity);
    const Vec3T<T> alpha = Rt * f.dw;
    const Vec3T<T> omega = Rt * f.w;
    Vec3T<T> F, Tq;
    detail::bodyInertiaForces(b.inertia, ws.basis[i], ahat, alpha, omega, ws, F, Tq, H);
    const Vec3T<T> Fw = f.R * F, Tw = f.R * Tq;
    for (int s : m.support[i]) e(s) += f.Jv.col(s).dot(Fw) + f.Jw.col(s).dot(Tw);
    if (b.inertia.ne > 0) {
      const int e0 = b.elastic_dof, ne = b.inertia.ne;
      for (int j = 0; j < ne; ++j) {
        T s = H[j];
        for (int k = 0; k < ne; ++k) s -= b.elastic.K(j, k) * q(e0 + k) + b.elastic.D(j, k) * qd(e0 + k);
        e(e0 + j) += s;
      }
    }
  }
  for (const PointLoad& l : m.point_loads) {
    const Body& b = m.bodies[l.body];
    const FrameState<T>& f = ws.frames[l.body];
    const BasisState<T>& bs = ws.basis[l.body];
    const T scale = detail::inputScale(u, l.input);
    Vec3T<T> s = Vec3T<T>::Zero();
    if (l.point >= 0) {
      const Mat3X& P = b.points[l.point].P;
      for (int k = 0; k < P.cols(); ++k) s += P.col(k) * bs.c(k);
    }
    Vec3T<T> Fb, Mb;
    if (l.body_frame) {
      Fb = l.force.cast<T>() * scale;
      Mb = l.moment.cast<T>() * scale;
    } else {
      Fb = f.R.transpose() * (l.force.cast<T>() * scale);
      Mb = f.R.transpose() * (l.moment.cast<T>() * scale);
    }
    const Vec3T<T> Fw = f.R * Fb;
    const Vec3T<T> Mw = f.R * (Mb + s.cross(Fb));
    for (int sd : m.support[l.body]) e(sd) += f.Jv.col(sd).dot(Fw) + f.Jw.col(sd).dot(Mw);
    if (l.point >= 0 && b.inertia.ne > 0) {
      const BodyPoint& pt = b.points[l.point];
      for (int j = 0; j < b.inertia.ne; ++j) {
        Vec3T<T> col = Vec3T<T>::Zero();
        for (int k = 0; k < pt.P.cols(); ++k) col += pt.P.col(k) * bs.D(k, j);
        e(b.elastic_dof + j) += col.dot(Fb) + pt.theta.col(j).cast<T>().dot(Mb);
      }
    }
  }
  for (const DofLoad& l : m.dof_loads) e(l.dof) += l.value * detail::inputScale(u, l.input);
  for (const DofSpring& s : m.springs) e(s.dof) -= s.k * (q(s.dof) - s.q0) + s.c * qd(s.dof);
  for (const BodyMatrices& bm : m.body_matrices) {
    const int d0 = m.bodies[bm.body].joint_dof;
    for (int r = 0; r < 6; ++r) {
      T s(0);
      for (int c = 0; c < 6; ++c)
        s += bm.K(r, c) * (q(d0 + c) - bm.x0(c)) + bm.C(r, c) * qd(d0 + c) + bm.A(r, c) * qdd(d0 + c);
      e(d0 + r) -= s;
    }
  }
}

}  // namespace whirl

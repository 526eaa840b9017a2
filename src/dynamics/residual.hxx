#pragma once
#include "src/dynamics/body_forces.hxx"
#include "src/dynamics/kinematics.hxx"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace detail {

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

// Whether any of the body's own elastic coordinates carries a seeded direction in x.
template <class T>
bool elasticSeeded(const Body& b, const VecXT<T>& x) {
  for (int j = 0; j < b.inertia.ne; ++j)
    if (seeded(x(b.elastic_dof + j))) return true;
  return false;
}

// Inertia forces of body i (body_forces.hxx) from its frame's â, α, ω. In an AD pass, the basis
// products are formed in double when the body's own coordinates are not seeded (c, ċ, c̈ and D
// then carry zero derivatives), and c-only products in double when only q̇ or q̈ are seeded.
template <class T>
void bodyInertiaForces(const Model& m, int i, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd,
                       const VecXT<T>& qdd, const Vec3T<T>& ahat, const Vec3T<T>& alpha, const Vec3T<T>& omega,
                       Vec3T<T>& F, Vec3T<T>& Tq, T* H) {
  const Body& b = m.bodies[i];
  const BodyInertia& in = b.inertia;
  const BasisState<T>& bs = ws.basis[i];
  if constexpr (std::is_same_v<T, double>) {
    basisProducts(in, bs.c, bs.cd, bs.cdd, ws.prod);
    frameForces(in, ws.prod, bs.D, ahat, alpha, omega, ws.g, F, Tq, H);
  } else {
    if (elasticSeeded(b, q)) {
      basisProducts(in, bs.c, bs.cd, bs.cdd, ws.prod);
      frameForces(in, ws.prod, bs.D, ahat, alpha, omega, ws.g, F, Tq, H);
      return;
    }
    BasisState<double>& bv = ws.basis_value;
    const int nc = in.nc();
    for (int r = 0; r < nc; ++r) bv.c(r) = bs.c(r).value();
    for (int j = 0; j < in.ne; ++j)
      for (int r = 0; r < nc; ++r) bv.D(r, j) = bs.D(r, j).value();
    if (elasticSeeded(b, qd) || elasticSeeded(b, qdd)) {
      basisProducts(in, bv.c, bs.cd, bs.cdd, ws.prod_dt);
      frameForces(in, ws.prod_dt, bv.D, ahat, alpha, omega, ws.g, F, Tq, H);
      return;
    }
    for (int r = 0; r < nc; ++r) {
      bv.cd(r) = bs.cd(r).value();
      bv.cdd(r) = bs.cdd(r).value();
    }
    basisProducts(in, bv.c, bv.cd, bv.cdd, ws.prod_dd);
    frameForces(in, ws.prod_dd, bv.D, ahat, alpha, omega, ws.g, F, Tq, H);
  }
}

}  // namespace detail

template <class TK, class T>
void addInputLoads(const Model& m, const Workspace<TK>& ws, const VecXT<T>& u, VecXT<T>& e) {
  for (const PointLoad& l : m.point_loads) {
    // The load scaled by its input (or 1): its generalized force is scale × that of the unit load,
    // formed in TK; only the final products carry the scalar of u.
    const Body& b = m.bodies[l.body];
    const FrameState<TK>& f = ws.frames[l.body];
    const BasisState<TK>& bs = ws.basis[l.body];
    const T scale = detail::inputScale(u, l.input);
    Vec3T<TK> s = Vec3T<TK>::Zero();
    if (l.point >= 0) {
      const Mat3X& P = b.points[l.point].P;
      for (int k = 0; k < P.cols(); ++k) s += P.col(k) * bs.c(k);
    }
    Vec3T<TK> Fb, Mb;
    if (l.body_frame) {
      Fb = l.force.cast<TK>();
      Mb = l.moment.cast<TK>();
    } else {
      Fb = f.R.transpose() * l.force.cast<TK>();
      Mb = f.R.transpose() * l.moment.cast<TK>();
    }
    const Vec3T<TK> Fw = f.R * Fb;
    const Vec3T<TK> Mw = f.R * Vec3T<TK>(Mb + s.cross(Fb));
    for (int sd : m.support[l.body]) {
      const TK g = f.Jv.col(sd).dot(Fw) + f.Jw.col(sd).dot(Mw);
      e(sd) += scale * g;
    }
    if (l.point >= 0 && b.inertia.ne > 0) {
      const BodyPoint& pt = b.points[l.point];
      for (int j = 0; j < b.inertia.ne; ++j) {
        Vec3T<TK> col = Vec3T<TK>::Zero();
        for (int k = 0; k < pt.P.cols(); ++k) col += pt.P.col(k) * bs.D(k, j);
        const TK g = col.dot(Fb) + pt.theta.col(j).cast<TK>().dot(Mb);
        e(b.elastic_dof + j) += scale * g;
      }
    }
  }
  for (const DofLoad& l : m.dof_loads) e(l.dof) += l.value * detail::inputScale(u, l.input);
}

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
    detail::bodyInertiaForces(m, i, ws, q, qd, qdd, ahat, alpha, omega, F, Tq, H);
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
  addInputLoads(m, ws, u, e);
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

#pragma once
#include <algorithm>
#include <cassert>
#include <cmath>

#include "src/dynamics/kinematics.hpp"

namespace whirl {

template <class T>
Mat3T<T> axisRotation(const Vec3& n, const T& phi) {
  using std::cos;
  using std::sin;
  const T c = cos(phi), s = sin(phi);
  Mat3T<T> R;
  if (n == Vec3::UnitX()) {
    R << T(1), T(0), T(0), T(0), c, -s, T(0), s, c;
  } else if (n == Vec3::UnitY()) {
    R << c, T(0), s, T(0), T(1), T(0), -s, T(0), c;
  } else if (n == Vec3::UnitZ()) {
    R << c, -s, T(0), s, c, T(0), T(0), T(0), T(1);
  } else {  // Rodrigues
    const T oc = T(1) - c;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = oc * n(i) * n(j);
    for (int i = 0; i < 3; ++i) R(i, i) += c;
    R(0, 1) -= s * n(2);
    R(1, 0) += s * n(2);
    R(0, 2) += s * n(1);
    R(2, 0) -= s * n(1);
    R(1, 2) -= s * n(0);
    R(2, 1) += s * n(0);
  }
  return R;
}

namespace detail {

inline bool seeded(double) { return true; }
template <class T>
bool seeded(const T& x) {
  return !x.derivatives().isZero(0.0);
}

// Whether a coordinate the frame of body i depends on carries a seeded direction.
template <class T>
bool supportSeeded(const Model& m, int i, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd) {
  for (int s : m.support[i])
    if (seeded(q(s)) || seeded(qd(s)) || seeded(qdd(s))) return true;
  return false;
}

// c = [1; q; q_i q_j (i<=j)], its first two time derivatives and D = ∂c/∂q. D's rows of 1 and q
// (constant) and the zeros of its quadratic rows are those initBasisD left: only the entries of the
// quadratic rows that depend on q are written here.
template <class T>
void evalBasis(const BodyInertia& in, const T* q, const T* qd, const T* qdd, BasisState<T>& b) {
  const int ne = in.ne;
  b.c(0) = T(1);
  b.cd(0) = T(0);
  b.cdd(0) = T(0);
  for (int k = 0; k < ne; ++k) {
    b.c(1 + k) = q[k];
    b.cd(1 + k) = qd[k];
    b.cdd(1 + k) = qdd[k];
  }
  if (!in.quadratic) return;
  int p = 1 + ne;
  for (int i = 0; i < ne; ++i)
    for (int j = i; j < ne; ++j, ++p) {
      b.c(p) = q[i] * q[j];
      b.cd(p) = qd[i] * q[j] + q[i] * qd[j];
      b.cdd(p) = qdd[i] * q[j] + T(2) * qd[i] * qd[j] + q[i] * qdd[j];
      if (i == j) {
        b.D(p, i) = q[i] + q[i];
      } else {
        b.D(p, i) = q[j];
        b.D(p, j) = q[i];
      }
    }
}

/// The fewest elastic coordinates for which an AD pass takes a body's basis from the double
/// kinematics and its stage-1 products from their preaccumulated derivatives (basis_jet.hxx): with
/// ElastoDyn's 3 or 4 shapes (nc 10, 15) the AD evaluation is as fast and the jet's forming at each
/// new point made a sweep of NREL 5MW linearizations (nrel5mwAzimuths) 8–12 % slower.
inline constexpr int kJetMinShapes = 6;

// Whether any of the body's own elastic coordinates carries a seeded direction in x.
template <class T>
bool elasticSeeded(const Body& b, const VecXT<T>& x) {
  for (int j = 0; j < b.inertia.ne; ++j)
    if (seeded(x(b.elastic_dof + j))) return true;
  return false;
}

// b = the double basis c (values only, no derivatives): what evalBasis gives when none of its
// arguments is seeded, without its products in the AD scalar.
template <class T>
void constantBasis(const BodyInertia& in, const BasisState<double>& c, BasisState<T>& b) {
  const int ne = in.ne, nc = in.nc();
  for (int r = 0; r < nc; ++r) {
    b.c(r) = T(c.c(r));
    b.cd(r) = T(c.cd(r));
    b.cdd(r) = T(c.cdd(r));
  }
  if (!in.quadratic) return;
  int p = 1 + ne;
  for (int i = 0; i < ne; ++i)
    for (int j = i; j < ne; ++j, ++p) {
      b.D(p, i) = T(c.D(p, i));
      b.D(p, j) = T(c.D(p, j));
    }
}

// D's constant part (evalBasis writes the rest): once per buffer.
template <class T>
void initBasisD(const BodyInertia& in, BasisState<T>& b) {
  b.D.setZero();
  for (int k = 0; k < in.ne; ++k) b.D(1 + k, k) = T(1);
}

// Rigid translation of the frame origin by d (ground components) moving with velocity dv and
// acceleration da relative to the frame (ground components).
template <class T>
void translate(FrameState<T>& f, const Vec3T<T>& d, const Vec3T<T>& dv, const Vec3T<T>& da,
               const std::vector<int>& support) {
  f.a += f.dw.cross(d) + f.w.cross(f.w.cross(d)) + T(2) * f.w.cross(dv) + da;
  f.v += f.w.cross(d) + dv;
  f.r += d;
  for (int s : support) f.Jv.col(s) += f.Jw.col(s).cross(d);
}

// Rotation of the frame about its own unit axis n by phi(t).
template <class T>
void rotate(FrameState<T>& f, const Vec3& n, const T& phi, const T& phid, const T& phidd) {
  const Vec3T<T> nw = f.R * n.cast<T>();
  f.dw += f.w.cross(nw) * phid + nw * phidd;
  f.w += nw * phid;
  f.R = f.R * axisRotation(n, phi);
}

}  // namespace detail

template <class T>
void forwardKinematics(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
                       const AdPass& pass) {
  assert(q.size() == m.ndof() && qd.size() == m.ndof() && qdd.size() == m.ndof());
  const int nb = static_cast<int>(m.bodies.size());
  if constexpr (std::is_same_v<T, double>) ws.body_products_current = false;
  for (int i = 0; i < nb; ++i) {
    const Body& b = m.bodies[i];
    BasisState<T>& bs = ws.basis[i];
    if (b.inertia.ne > 0) {
      const int e0 = b.elastic_dof;
      if constexpr (!std::is_same_v<T, double>) {
        // In a derivatives-only pass, a basis no seeded coordinate moves is the double basis.
        if (pass.derivativesOnly() && b.inertia.ne >= detail::kJetMinShapes &&
            !(detail::elasticSeeded(b, q) || detail::elasticSeeded(b, qd) || detail::elasticSeeded(b, qdd))) {
          detail::constantBasis(b.inertia, pass.kinematics->basis[i], bs);
          continue;
        }
      }
      detail::evalBasis(b.inertia, q.data() + e0, qd.data() + e0, qdd.data() + e0, bs);
    } else {
      bs.c(0) = T(1);
      bs.cd(0) = T(0);
      bs.cdd(0) = T(0);
    }
  }
  for (int i = 0; i < nb; ++i) {
    const Body& b = m.bodies[i];
    FrameState<T>& f = ws.frames[i];
    const std::vector<int>& sup = m.support[i];
    if constexpr (!std::is_same_v<T, double>) {
      // In a derivatives-only pass, a frame no seeded coordinate moves is the double frame.
      if (pass.derivativesOnly() && !detail::supportSeeded(m, i, q, qd, qdd)) {
        const FrameState<double>& c = pass.kinematics->frames[i];
        f.R = c.R.template cast<T>();
        f.r = c.r.template cast<T>();
        f.v = c.v.template cast<T>();
        f.a = c.a.template cast<T>();
        f.w = c.w.template cast<T>();
        f.dw = c.dw.template cast<T>();
        for (int s : sup) {
          f.Jv.col(s) = c.Jv.col(s).template cast<T>();
          f.Jw.col(s) = c.Jw.col(s).template cast<T>();
        }
        continue;
      }
    }
    if (b.parent >= 0) {
      const FrameState<T>& p = ws.frames[b.parent];
      f.R = p.R;
      f.r = p.r;
      f.v = p.v;
      f.a = p.a;
      f.w = p.w;
      f.dw = p.dw;
      for (int s : sup) {
        f.Jv.col(s) = p.Jv.col(s);
        f.Jw.col(s) = p.Jw.col(s);
      }
    } else {
      f.R.setIdentity();
      f.r.setZero();
      f.v.setZero();
      f.a.setZero();
      f.w.setZero();
      f.dw.setZero();
      for (int s : sup) {
        f.Jv.col(s).setZero();
        f.Jw.col(s).setZero();
      }
    }
    for (const ChainStep& st : m.chains[i]) {
      switch (st.kind) {
        case ChainStep::PointTranslate: {
          const Body& pb = m.bodies[st.body];
          const BasisState<T>& pbs = ws.basis[st.body];
          const Mat3X& P = pb.points[st.point].P;
          Vec3T<T> t = Vec3T<T>::Zero(), td = Vec3T<T>::Zero(), tdd = Vec3T<T>::Zero();
          for (int k = 0; k < P.cols(); ++k) {
            t += P.col(k) * pbs.c(k);
            td += P.col(k) * pbs.cd(k);
            tdd += P.col(k) * pbs.cdd(k);
          }
          detail::translate(f, Vec3T<T>(f.R * t), Vec3T<T>(f.R * td), Vec3T<T>(f.R * tdd), sup);
          for (int j = 0; j < pb.inertia.ne; ++j) {
            Vec3T<T> col = Vec3T<T>::Zero();
            for (int k = 0; k < P.cols(); ++k) col += P.col(k) * pbs.D(k, j);
            f.Jv.col(pb.elastic_dof + j) += f.R * col;
          }
          break;
        }
        case ChainStep::ElasticRotate: {
          const Body& pb = m.bodies[st.body];
          const Mat3X& th = pb.points[st.point].theta;
          const int e0 = pb.elastic_dof;
          T phi(0), phid(0), phidd(0);
          for (int j = 0; j < pb.inertia.ne; ++j) {
            const double cj = th(st.axis_index, j);
            phi += cj * q(e0 + j);
            phid += cj * qd(e0 + j);
            phidd += cj * qdd(e0 + j);
          }
          const Vec3 n = Vec3::Unit(st.axis_index);
          const Vec3T<T> nw = f.R * n.cast<T>();
          for (int j = 0; j < pb.inertia.ne; ++j) f.Jw.col(e0 + j) += nw * th(st.axis_index, j);
          detail::rotate(f, n, phi, phid, phidd);
          break;
        }
        case ChainStep::ConstTranslate: {
          const Vec3T<T> d = f.R * st.vec.cast<T>();
          const Vec3T<T> zero = Vec3T<T>::Zero();
          detail::translate(f, d, zero, zero, sup);
          break;
        }
        case ChainStep::ConstRotate: f.R = f.R * st.rot.cast<T>(); break;
        case ChainStep::AxisRotate: {
          const Vec3T<T> nw = f.R * st.vec.cast<T>();
          if (st.ratio == 1.0) {
            f.Jw.col(st.dof) += nw;
            detail::rotate(f, st.vec, q(st.dof), qd(st.dof), qdd(st.dof));
          } else {
            f.Jw.col(st.dof) += nw * st.ratio;
            detail::rotate(f, st.vec, T(st.ratio * q(st.dof)), T(st.ratio * qd(st.dof)), T(st.ratio * qdd(st.dof)));
          }
          break;
        }
        case ChainStep::AxisTranslate: {
          const Vec3T<T> nw = f.R * st.vec.cast<T>();
          detail::translate(f, Vec3T<T>(nw * q(st.dof)), Vec3T<T>(nw * qd(st.dof)), Vec3T<T>(nw * qdd(st.dof)), sup);
          f.Jv.col(st.dof) += nw;
          break;
        }
      }
    }
  }
}

}  // namespace whirl

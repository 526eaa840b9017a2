#pragma once
/// \file
/// Generalized force of a force and a moment applied at a material point of a body (Kane: the
/// partial velocities of the point and the partial angular velocities of its cross-section).
#include "src/dynamics/workspace.hpp"

namespace whirl::detail {

/// e += scale · Σ_j (∂v_P/∂q̇_j · F + ∂ω_P/∂q̇_j · M) for a force Fb and a moment Mb (body-frame
/// components) at point `point` of body b (its origin when point < 0), at the kinematics in ws.
/// Scalars: TK of the kinematics, TF of the load (TK or richer), T of the scale and of e.
template <class TK, class TF, class T>
void addPointForce(const Model& m, const Workspace<TK>& ws, int b, int point, const Vec3T<TF>& Fb, const Vec3T<TF>& Mb,
                   const T& scale, VecXT<T>& e) {
  const Body& body = m.bodies[b];
  const FrameState<TK>& f = ws.frames[b];
  const BasisState<TK>& bs = ws.basis[b];
  Vec3T<TK> s = Vec3T<TK>::Zero();
  if (point >= 0) {
    const Mat3X& P = body.points[point].P;
    for (int k = 0; k < P.cols(); ++k) s += P.col(k) * bs.c(k);
  }
  const Mat3T<TF> R = f.R.template cast<TF>();
  const Vec3T<TF> Fw = R * Fb;
  const Vec3T<TF> Mw = R * Vec3T<TF>(Mb + s.template cast<TF>().cross(Fb));
  for (int sd : m.support[b]) {
    const TF g = f.Jv.col(sd).template cast<TF>().dot(Fw) + f.Jw.col(sd).template cast<TF>().dot(Mw);
    e(sd) += scale * g;
  }
  if (point < 0 || body.inertia.ne == 0) return;
  const BodyPoint& pt = body.points[point];
  for (int j = 0; j < body.inertia.ne; ++j) {
    Vec3T<TK> col = Vec3T<TK>::Zero();
    for (int k = 0; k < pt.P.cols(); ++k) col += pt.P.col(k) * bs.D(k, j);
    const TF g = col.template cast<TF>().dot(Fb) + pt.theta.col(j).template cast<TF>().dot(Mb);
    e(body.elastic_dof + j) += scale * g;
  }
}

/// e += the generalized forces of loads on body b given as sums (BodyLoadSum): F, M in ground
/// components (M about the body origin), Fb, Mb in body components, fk(k) = Σ P_kᵀ F_b (k < nc) and
/// gθ(j) = Σ θ_jᵀ M_b (j < ne): e(support) += Jvᵀ (F + R Fb) + Jωᵀ (M + R Mb),
/// e(elastic j) += gθ(j) + Σ_k D_kj fk(k).
template <class TK, class T, class FK, class GT>
void projectBodySums(const Model& m, const Workspace<TK>& ws, int b, const Vec3T<T>& F0, const Vec3T<T>& M0,
                     const Vec3T<T>& Fb, const Vec3T<T>& Mb, FK fk, GT gtheta, VecXT<T>& e) {
  const FrameState<TK>& f = ws.frames[b];
  const Mat3T<T> R = f.R.template cast<T>();
  const Vec3T<T> F = F0 + R * Fb, M = M0 + R * Mb;
  for (int sd : m.support[b]) e(sd) += f.Jv.col(sd).template cast<T>().dot(F) + f.Jw.col(sd).template cast<T>().dot(M);
  const Body& body = m.bodies[b];
  const MatXT<TK>& D = ws.basis[b].D;
  for (Eigen::Index j = 0; j < D.cols(); ++j) {
    T g = gtheta(j);
    for (Eigen::Index k = 0; k < D.rows(); ++k) g += T(D(k, j)) * fk(k);
    e(body.elastic_dof + static_cast<int>(j)) += g;
  }
}

/// Point loads on one body summed for a single projection (addPointForce for many points):
/// e(support) += Jvᵀ ΣF + Jwᵀ ΣM (world frame, moments about the body origin) and
/// e(elastic j) += Σ_k D_kj (Σ P_kᵀ F_b) + Σ θ_jᵀ M_b (body frame). Results equal the sum of
/// addPointForce calls to round-off. Every point must have the same number of basis functions nc.
template <class T>
class BodyLoadSum {
 public:
  BodyLoadSum(int ne, Eigen::Index nc) : fk_(VecXT<T>::Zero(nc)), gtheta_(VecXT<T>::Zero(ne)) {}

  /// Adds weight · (F, M) at point pt (world components Fw, Mw; Rs = R s its offset from the body
  /// origin, world frame; R the body orientation).
  template <class TK>
  void add(const BodyPoint& pt, const Mat3T<TK>& R, const Vec3T<TK>& Rs, const Vec3T<T>& Fw, const Vec3T<T>& Mw,
           double weight) {
    const Vec3T<T> wF = weight * Fw, wM = weight * Mw;
    F_ += wF;
    M_ += wM + Vec3T<T>(Rs.template cast<T>().cross(wF));
    const Mat3T<T> Rt = R.transpose().template cast<T>();
    const Vec3T<T> Fb = Rt * wF, Mb = Rt * wM;
    for (Eigen::Index k = 0; k < fk_.size(); ++k) fk_(k) += pt.P.col(k).dot(Fb);
    for (Eigen::Index j = 0; j < gtheta_.size(); ++j) gtheta_(j) += pt.theta.col(j).dot(Mb);
  }

  /// Adds weight · (Fb, Mb) at point pt, all in body components (s: the point's offset from the body
  /// origin). Summed apart from add() and turned to ground components once, in project().
  template <class TK>
  void addBody(const BodyPoint& pt, const Vec3T<TK>& s, const Vec3T<T>& Fb, const Vec3T<T>& Mb, double weight) {
    const Vec3T<T> wF = weight * Fb, wM = weight * Mb;
    Fb_ += wF;
    Mb_ += wM + Vec3T<T>(s.template cast<T>().cross(wF));
    // Local pointers: a store to the sums might alias the matrices' data pointers, which would be
    // reloaded at every term.
    T* fk = fk_.data();
    T* gt = gtheta_.data();
    const double* P = pt.P.data();
    const double* th = pt.theta.data();
    for (Eigen::Index k = 0, n = fk_.size(); k < n; ++k)
      fk[k] += P[3 * k] * wF(0) + P[3 * k + 1] * wF(1) + P[3 * k + 2] * wF(2);
    for (Eigen::Index j = 0, n = gtheta_.size(); j < n; ++j)
      gt[j] += th[3 * j] * wM(0) + th[3 * j + 1] * wM(1) + th[3 * j + 2] * wM(2);
  }

  /// Number of body-component sums: Fb (3), Mb (3), fk (nc), gθ (ne).
  Eigen::Index size() const { return 6 + fk_.size() + gtheta_.size(); }

  /// The body-component sums [Fb; Mb; fk; gθ] (dim size(); nothing added by add()).
  T bodySum(Eigen::Index i) const {
    if (i < 3) return Fb_(i);
    if (i < 6) return Mb_(i - 3);
    if (i < 6 + fk_.size()) return fk_(i - 6);
    return gtheta_(i - 6 - fk_.size());
  }

  /// Sets body-component sum i (layout of bodySum).
  void setBodySum(Eigen::Index i, const T& v) {
    if (i < 3) Fb_(i) = v;
    else if (i < 6) Mb_(i - 3) = v;
    else if (i < 6 + fk_.size()) fk_(i - 6) = v;
    else gtheta_(i - 6 - fk_.size()) = v;
  }

  /// The resultant force and its moment about the body origin, ground components (R: the body's axes).
  template <class TK>
  void resultant(const Mat3T<TK>& R, Vec3T<T>& F, Vec3T<T>& M) const {
    const Mat3T<T> Rt = R.template cast<T>();
    F = F_ + Rt * Fb_;
    M = M_ + Rt * Mb_;
  }

  /// Adds the sums to the generalized forces of body b's support and elastic coordinates.
  template <class TK>
  void project(const Model& m, const Workspace<TK>& ws, int b, VecXT<T>& e) const {
    projectBodySums(
        m, ws, b, F_, M_, Fb_, Mb_, [&](Eigen::Index k) { return fk_(k); }, [&](Eigen::Index j) { return gtheta_(j); },
        e);
  }

 private:
  Vec3T<T> F_ = Vec3T<T>::Zero(), M_ = Vec3T<T>::Zero();    ///< ground components (add)
  Vec3T<T> Fb_ = Vec3T<T>::Zero(), Mb_ = Vec3T<T>::Zero();  ///< body components (addBody)
  VecXT<T> fk_, gtheta_;
};

}  // namespace whirl::detail

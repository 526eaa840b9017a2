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
void addPointForce(const Model& m, const Workspace<TK>& ws, int b, int point, const Vec3T<TF>& Fb,
                   const Vec3T<TF>& Mb, const T& scale, VecXT<T>& e) {
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

}  // namespace whirl::detail

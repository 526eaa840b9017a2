#pragma once
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/outputs.hpp"

namespace whirl {
namespace detail {

// Ground-frame position, velocity or acceleration of a point of body b (origin when point < 0):
// p = r + R s, ṗ = v + ω × R s + R ṡ, p̈ = a + ω̇ × R s + ω × (ω × R s) + 2 ω × R ṡ + R s̈, s = P c.
template <class T>
Vec3T<T> pointMotion(const Model& m, const Workspace<T>& ws, int b, int point, int order) {
  const FrameState<T>& f = ws.frames[b];
  const Vec3T<T> base = order == 0 ? f.r : order == 1 ? f.v : f.a;
  if (point < 0) return base;
  const BasisState<T>& bs = ws.basis[b];
  const Mat3X& P = m.bodies[b].points[point].P;
  Vec3T<T> s = Vec3T<T>::Zero(), sd = Vec3T<T>::Zero(), sdd = Vec3T<T>::Zero();
  for (int k = 0; k < P.cols(); ++k) {
    s += P.col(k) * bs.c(k);
    sd += P.col(k) * bs.cd(k);
    sdd += P.col(k) * bs.cdd(k);
  }
  const Vec3T<T> Rs = f.R * s, Rsd = f.R * sd;
  if (order == 0) return Vec3T<T>(base + Rs);
  if (order == 1) return Vec3T<T>(base + f.w.cross(Rs) + Rsd);
  return Vec3T<T>(base + f.dw.cross(Rs) + f.w.cross(f.w.cross(Rs)) + T(2) * f.w.cross(Rsd) + f.R * sdd);
}

}  // namespace detail

template <class T>
void evaluateOutputs(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
                     VecXT<T>& y) {
  bool points = false;
  for (const Output& o : m.outputs) points = points || o.kind == OutputKind::Point;
  if (points) forwardKinematics(m, ws, q, qd, qdd);
  for (int i = 0; i < m.noutput(); ++i) {
    const Output& o = m.outputs[i];
    if (o.kind == OutputKind::DofCombination) {
      const VecXT<T>& x = o.order == 0 ? q : o.order == 1 ? qd : qdd;
      T s(0);
      for (const auto& [d, g] : o.terms) s += g * x(d);
      y(i) = s;
      continue;
    }
    const Vec3T<T> p = detail::pointMotion(m, ws, o.body, o.point, o.order);
    const Vec3T<T> dir = o.frame_body >= 0 ? Vec3T<T>(ws.frames[o.frame_body].R * o.direction.cast<T>())
                                           : Vec3T<T>(o.direction.cast<T>());
    y(i) = dir.dot(p);
  }
}

}  // namespace whirl

#pragma once
#include "src/base/error.hpp"
#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/generator_torque.hpp"
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
                     VecXT<T>& y, const VecXT<T>* u, const AeroInflow* frozen, const AdPass& pass) {
  bool points = false, rotor = false;
  for (const Output& o : m.outputs) {
    points = points || o.kind == OutputKind::Point || o.kind == OutputKind::Angular;
    rotor = rotor || o.kind == OutputKind::Rotor;
  }
  if (points || rotor) forwardKinematics(m, ws, q, qd, qdd, pass);
  RotorTotals<T> totals;
  T generator_torque(0), generator_speed(0), rotor_speed(0);
  if (rotor) {
    if (!u) throw ComputeError("rotor outputs need the inputs (wind speed, generator torque)");
    if (m.aero.active()) {
      addAeroLoads(m, ws, q, *u, frozen, nullptr, ws.scratch, 0, &totals);
      rotor_speed = ws.frames[m.aero.hub_body].w.dot(ws.frames[m.aero.hub_body].R.col(0));
    }
    if (m.generator.active()) {
      for (const auto& [d, g] : m.outputs[m.generator.speed_output].terms) generator_speed += g * qd(d);
      generator_torque = generatorTorque(m.generator, generator_speed);
      if (m.roles.generator_torque_input >= 0) generator_torque += (*u)(m.roles.generator_torque_input);
    }
  }
  for (int i = 0; i < m.noutput(); ++i) {
    const Output& o = m.outputs[i];
    if (o.kind == OutputKind::Rotor) {
      switch (o.rotor_quantity) {
        case RotorQuantity::AeroThrust: y(i) = totals.thrust; break;
        case RotorQuantity::AeroTorque: y(i) = totals.torque; break;
        case RotorQuantity::AeroPower: y(i) = totals.torque * rotor_speed; break;
        case RotorQuantity::GeneratorTorque: y(i) = generator_torque; break;
        case RotorQuantity::GeneratorPower: y(i) = generator_torque * generator_speed * m.generator.efficiency; break;
      }
      continue;
    }
    if (o.kind == OutputKind::DofCombination) {
      const VecXT<T>& x = o.order == 0 ? q : o.order == 1 ? qd : qdd;
      T s(0);
      for (const auto& [d, g] : o.terms) s += g * x(d);
      y(i) = s;
      continue;
    }
    const Vec3T<T> p = o.kind == OutputKind::Angular ? (o.order == 1 ? ws.frames[o.body].w : ws.frames[o.body].dw)
                                                     : detail::pointMotion(m, ws, o.body, o.point, o.order);
    const Vec3T<T> dir = o.frame_body >= 0 ? Vec3T<T>(ws.frames[o.frame_body].R * o.direction.cast<T>())
                                           : Vec3T<T>(o.direction.cast<T>());
    y(i) = dir.dot(p);
  }
}

}  // namespace whirl

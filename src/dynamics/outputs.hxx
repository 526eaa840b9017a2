#pragma once
#include <string>
#include <utility>
#include <vector>

#include "src/base/error.hpp"
#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/generator_torque.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hxx"

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

// Whether body i is `root` or hangs below it.
inline bool inSubtree(const Model& m, int i, int root) {
  for (; i >= 0; i = m.bodies[i].parent)
    if (i == root) return true;
  return false;
}

// The moment about root's origin of the loads on root and the bodies below it, ground components:
// each body's inertia and gravity forces (body_forces.hxx: F, T about its origin), the blades' element
// loads (`totals`: resultant and moment about the blade origin) and the point loads. Forces between
// bodies of the subtree (joints, springs, the gearbox) cancel: what remains is the load at the cut.
template <class T>
Vec3T<T> subtreeLoadMoment(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
                           const VecXT<T>* u, const RotorTotals<T>& totals, int root) {
  const Vec3T<T> r0 = ws.frames[root].r, gravity = m.gravity.cast<T>();
  Vec3T<T> M = Vec3T<T>::Zero();
  for (int i = 0; i < static_cast<int>(m.bodies.size()); ++i) {
    const Body& b = m.bodies[i];
    if (!inSubtree(m, i, root) || (b.inertia.massless && b.inertia.ne == 0)) continue;
    const FrameState<T>& f = ws.frames[i];
    const Mat3T<T> Rt = f.R.transpose();
    Vec3T<T> F, Tq;
    bodyInertiaForces(m, i, ws, q, qd, qdd, Vec3T<T>(Rt * (f.a - gravity)), Vec3T<T>(Rt * f.dw), Vec3T<T>(Rt * f.w), F,
                      Tq, ws.h.data());
    M += f.R * Tq + (f.r - r0).cross(f.R * F);
  }
  for (std::size_t bi = 0; bi < totals.blade_moment.size(); ++bi) {
    const int body = m.aero.blades[bi].body;
    if (inSubtree(m, body, root)) M += totals.blade_moment[bi] + (ws.frames[body].r - r0).cross(totals.blade_force[bi]);
  }
  const T law = generatorLawTorque(m, qd);
  for (const PointLoad& l : m.point_loads) {
    if (!inSubtree(m, l.body, root)) continue;
    const T scale = pointLoadScale(m, l, *u, law);
    const Mat3T<T>& R = ws.frames[l.body].R;
    const Vec3T<T> Fw = l.body_frame ? Vec3T<T>(R * l.force.cast<T>()) : Vec3T<T>(l.force.cast<T>());
    const Vec3T<T> Mw = l.body_frame ? Vec3T<T>(R * l.moment.cast<T>()) : Vec3T<T>(l.moment.cast<T>());
    M += scale * Vec3T<T>(Mw + (pointMotion(m, ws, l.body, l.point, 0) - r0).cross(Fw));
  }
  return M;
}

}  // namespace detail

template <class T>
void evaluateOutputs(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
                     VecXT<T>& y, const VecXT<T>* u, const AeroInflow* frozen, const AdPass& pass, const VecXT<T>* z) {
  bool points = false, rotor = false, subtree = false;
  for (const Output& o : m.outputs) {
    points = points || o.kind == OutputKind::Point || o.kind == OutputKind::Angular;
    rotor = rotor || o.kind == OutputKind::Rotor;
    subtree = subtree || o.kind == OutputKind::SubtreeLoadMoment;
  }
  if (points || rotor || subtree) forwardKinematics(m, ws, q, qd, qdd, pass);
  RotorTotals<T>& totals = ws.totals;  // the workspace's: no allocation per AD pass
  totals.thrust = totals.torque = T(0.0);
  totals.blade_force.clear();
  totals.blade_moment.clear();
  T generator_torque(0), generator_speed(0), rotor_speed(0);
  if (subtree && !u) throw ComputeError("load outputs need the inputs (wind speed, applied loads)");
  if ((rotor || subtree) && m.aero.active()) {
    if (!u) throw ComputeError("rotor outputs need the inputs (wind speed, generator torque)");
    if (z) {  // the loads of the states, as the equations of motion with them (linearize/unsteady_aero.hpp)
      if (!frozen) throw ComputeError("load outputs with aerodynamic states need the frozen induction of the point");
      if (z->size() != aeroStateCount(m.aero))
        throw ComputeError("load outputs: " + std::to_string(z->size()) + " aerodynamic state values for " +
                           std::to_string(aeroStateCount(m.aero)) + " states");
      addUnsteadyAeroLoads<T>(m, ws, q, qd, *u, *frozen, z, ws.scratch, nullptr, nullptr, nullptr, -1, false, &totals);
    } else {
      addAeroLoads(m, ws, q, *u, frozen, nullptr, ws.scratch, 0, &totals);
    }
    rotor_speed = ws.frames[m.aero.hub_body].w.dot(ws.frames[m.aero.hub_body].R.col(0));
  }
  if (rotor) {
    if (!u) throw ComputeError("rotor outputs need the inputs (wind speed, generator torque)");
    if (m.generator.active()) {
      for (const auto& [d, g] : m.outputs[m.generator.speed_output].terms) generator_speed += g * qd(d);
      generator_torque = generatorTorque(m.generator, generator_speed);
      if (m.roles.generator_torque_input >= 0) generator_torque += (*u)(m.roles.generator_torque_input);
    }
  }
  // One sum per cut body: a deck's flap and edge channels share their blade's, the tower's fore-aft
  // and side-side channels the tower's (each sum runs over every body the cut carries).
  auto& cut_moments = ws.cut_moments;
  cut_moments.clear();
  const auto cutMoment = [&](int root) -> const Vec3T<T>& {
    for (const auto& [body, M] : cut_moments)
      if (body == root) return M;
    cut_moments.emplace_back(root, detail::subtreeLoadMoment(m, ws, q, qd, qdd, u, totals, root));
    return cut_moments.back().second;
  };
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
    const Vec3T<T> p = o.kind == OutputKind::SubtreeLoadMoment ? cutMoment(o.body)
                       : o.kind == OutputKind::Angular ? (o.order == 1 ? ws.frames[o.body].w : ws.frames[o.body].dw)
                                                       : detail::pointMotion(m, ws, o.body, o.point, o.order);
    const Vec3T<T> dir = o.frame_body >= 0 ? Vec3T<T>(ws.frames[o.frame_body].R * o.direction.cast<T>())
                                           : Vec3T<T>(o.direction.cast<T>());
    y(i) = dir.dot(p);
  }
}

}  // namespace whirl

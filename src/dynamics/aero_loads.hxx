#pragma once
#include <cstdint>
#include <type_traits>

#include "src/dynamics/aero_blade_jet.hxx"
#include "src/dynamics/aero_element.hxx"
#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/aero_skew.hxx"

namespace whirl {

template <class TK, class T>
void addAeroLoads(const Model& m, Workspace<TK>& ws, const VecXT<TK>& q, const VecXT<T>& u, const AeroInflow* frozen,
                  AeroRecord* record, VecXT<T>& e, std::uint64_t skip, RotorTotals<T>* totals, AeroJets* jets) {
  const AeroModel& am = m.aero;
  if (!am.active()) return;
  const FrameState<TK>& hub = ws.frames[am.hub_body];
  const Vec3T<TK> disk = hub.R.col(0);
  const T speed = m.roles.wind_speed_input >= 0 ? u(m.roles.wind_speed_input) : T(0);
  const Vec3 wind_dir = detail::windDirection(am.wind);
  AeroJets& store = jets ? *jets : ws.jets;
  // AeroDyn turns the induction off at low tip-speed ratios (BEMT check_turnOffBEMT): λ = |Ω| zTip / |V·x|
  // with the rotor speed about the disk normal and the hub-height wind along it (AeroDyn: the
  // disk-averaged inflow; equal without shear and structural motion), weight 0 below λ = 1, 1 above 2.
  T weight(1.0);
  if (am.induction && !frozen) {
    const TK omega = hub.w.dot(disk);
    const T along = speed * T(TK(wind_dir.template cast<TK>().dot(disk)));
    const T va = valueOf(along) < 0 ? T(-along) : along;
    const T om = T(valueOf(omega) < 0 ? TK(-omega) : omega);
    if (valueOf(va) > 0) weight = aero::inductionWeight<T>(om * am.tip_radius / va);
    else weight = T(valueOf(om) > 0 ? 1.0 : 0.0);
  }
  // AD passes with the induction frozen chain each blade's preaccumulated derivatives
  // (aero_blade_jet.hxx) instead of evaluating its elements in the AD scalar.
  const bool jet_pass = std::is_same_v<T, ADChunk> && frozen && !record && !totals;
  if (record) {  // keeps the element vector's storage: an equilibrium solve records every residual
    record->elements.clear();
    record->thrust = record->torque = 0;
  }
  // The skewed-wake correction acts on the solved induction; a frozen one carries it from its point.
  const detail::RotorSkew<TK> skew = frozen ? detail::RotorSkew<TK>{}
                                            : detail::rotorSkew<TK>(am, disk, wind_dir, valueOf(speed));
  const detail::RotorInflow<TK, T> inflow{hub.r, disk, speed, wind_dir, weight, frozen, &skew};
  if (totals) {  // skipped blades keep zero resultants; assign() keeps the vectors' storage
    totals->thrust = totals->torque = T(0.0);
    totals->blade_force.assign(am.blades.size(), Vec3T<T>::Zero());
    totals->blade_moment.assign(am.blades.size(), Vec3T<T>::Zero());
  }
  int index0 = 0;  // first element of the blade, over all blades
  for (std::size_t bi = 0; bi < am.blades.size(); ++bi) {
    const AeroBlade& blade = am.blades[bi];
    const int n = static_cast<int>(blade.stations.size());
    if (bi < 64 && (skip >> bi & 1u)) {
      index0 += n;
      continue;
    }
    const Body& body = m.bodies[blade.body];
    const FrameState<TK>& f = ws.frames[blade.body];
    const BasisState<TK>& bs = ws.basis[blade.body];
    const TK pitch = blade.pitch_dof >= 0 ? q(blade.pitch_dof) : TK(0);
    const TK* qe = body.inertia.ne > 0 ? q.data() + body.elastic_dof : nullptr;
    const detail::BladeMotion<TK> bm{f.R, f.r, f.v, f.w, bs.c, bs.cd, qe, pitch};
    if constexpr (std::is_same_v<T, ADChunk>) {
      if (jet_pass) {
        detail::addBladeJetLoads(m, static_cast<int>(bi), index0, bm, hub.r, disk, speed, *frozen, ws, store, e);
        index0 += n;
        continue;
      }
    }
    // The elements' generalized forces summed before they are projected (Kane: the partial velocities
    // of a point are those of the body frame plus the shape functions at it): the frame part is the
    // resultant force and moment about the body origin, the elastic part Σ_k D_kj Σ_el P_kᵀ F. One
    // projection per blade instead of one per element.
    detail::BodyLoadSum<T> sum(body.inertia.ne, body.points[blade.stations.front().point].P.cols());
    detail::bladeLoads(m, static_cast<int>(bi), index0, bm, inflow, ws.bem, store.sections, record, totals, sum);
    sum.project(m, ws, blade.body, e);
    if (totals) {
      sum.resultant(f.R, totals->blade_force[bi], totals->blade_moment[bi]);
    }
    index0 += n;
  }
}

}  // namespace whirl

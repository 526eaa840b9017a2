#pragma once
#include <cmath>
#include <string>

#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/aero_section.hxx"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/point_force.hxx"
#include "src/model/scalar.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace detail {

/// Wind velocity at height z (ground frame): U (z / z_ref)^α along the propagation direction, tilted
/// by the upflow angle (InflowWind's steady wind, WindType = 1).
/// `direction` is windDirection(w), computed once per load evaluation.
template <class TK, class T>
Vec3T<T> steadyWind(const SteadyWind& w, const Vec3& direction, const T& speed, const TK& z) {
  T U = speed;
  if (w.shear_exponent != 0.0) {
    using std::pow;
    const TK ratio = z / w.reference_height;
    if (valueOf(ratio) > 0) U = U * T(TK(pow(ratio, w.shear_exponent)));
    else U = T(0);
  }
  return Vec3T<T>(U * direction(0), U * direction(1), U * direction(2));
}

/// Unit vector of the steady wind (ground frame): along the propagation direction, tilted up by the
/// upflow angle.
inline Vec3 windDirection(const SteadyWind& w) {
  const double cu = std::cos(w.upflow), su = std::sin(w.upflow);
  return Vec3(cu * std::cos(w.direction), -cu * std::sin(w.direction), su);
}

}  // namespace detail

template <class TK, class T>
void addAeroLoads(const Model& m, Workspace<TK>& ws, const VecXT<TK>& q, const VecXT<T>& u,
                  const AeroInflow* frozen, AeroRecord* record, VecXT<T>& e, std::uint64_t skip,
                  RotorTotals<T>* totals) {
  const AeroModel& am = m.aero;
  if (!am.active()) return;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const FrameState<TK>& hub = ws.frames[am.hub_body];
  const Vec3T<TK> disk = hub.R.col(0);
  const T speed = m.roles.wind_speed_input >= 0 ? u(m.roles.wind_speed_input) : T(0);
  const Vec3 wind_dir = detail::windDirection(am.wind);
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
  if (record) *record = AeroRecord{};
  int index = 0;  // element over all blades
  for (std::size_t bi = 0; bi < am.blades.size(); ++bi) {
    const AeroBlade& blade = am.blades[bi];
    if (bi < 64 && (skip >> bi & 1u)) {
      index += static_cast<int>(blade.stations.size());
      continue;
    }
    const Body& body = m.bodies[blade.body];
    const FrameState<TK>& f = ws.frames[blade.body];
    const BasisState<TK>& bs = ws.basis[blade.body];
    const TK pitch = blade.pitch_dof >= 0 ? q(blade.pitch_dof) : TK(0);
    // The body turned back by its pitch: AeroDyn's blade frame without pitch (aero_model.hpp).
    // Its axes in body components (Ab) and in ground components (Rnp = R Ab): the element loads are
    // formed and summed in body components, so that no element is turned by the AD rotation R.
    const Mat3T<TK> Ab = axisRotation(body.axis, TK(-pitch));
    const Mat3T<TK> Rnp = f.R * Ab;
    const Vec3T<TK> xa = Rnp.col(1), ya = Rnp.col(2), za = Rnp.col(0);
    const Vec3T<TK> xab = Ab.col(1), yab = Ab.col(2), zab = Ab.col(0);
    // The elements' generalized forces summed before they are projected (Kane: the partial velocities
    // of a point are those of the body frame plus the shape functions at it): the frame part is the
    // resultant force and moment about the body origin, the elastic part Σ_k D_kj Σ_el P_kᵀ F. One
    // projection per blade instead of one per element.
    detail::BodyLoadSum<T> sum(body.inertia.ne, body.points[blade.stations.front().point].P.cols());
    for (std::size_t si = 0; si < blade.stations.size(); ++si, ++index) {
      const AeroStation& st = blade.stations[si];
      const BodyPoint& pt = body.points[st.point];
      Vec3T<TK> s = Vec3T<TK>::Zero(), sd = Vec3T<TK>::Zero();
      for (int k = 0; k < pt.P.cols(); ++k) {
        s += pt.P.col(k) * bs.c(k);
        sd += pt.P.col(k) * bs.cd(k);
      }
      Vec3T<TK> rot = Vec3T<TK>::Zero();  // small rotations of the section about body x, y, z
      for (int j = 0; j < body.inertia.ne; ++j) rot += pt.theta.col(j) * q(body.elastic_dof + j);
      const Vec3T<TK> Rs = f.R * s;
      const Vec3T<TK> pos = f.r + Rs;
      const Vec3T<TK> vel = f.v + f.w.cross(Rs) + f.R * sd;
      // Out-of-plane slope of the deflected span axis (1, θz, −θy): the annulus frame's tilt.
      const Vec3T<TK> span(TK(1), rot(2), -rot(1));  // body components
      // cos and sin of the slope atan2(span·xa, span·za), without the angle.
      const TK sx = span.dot(xab), sz = span.dot(zab);
      const TK h = sqrt(sx * sx + sz * sz);
      const TK cs = sz / h, ss = sx / h;
      const Vec3T<TK> xn = cs * xa - ss * za, zn = ss * xa + cs * za;
      const Vec3T<T> rel = detail::steadyWind(am.wind, wind_dir, speed, pos(2)) - vel.template cast<T>();
      const T vx = rel.dot(xn.template cast<T>()), vy = rel.dot(ya.template cast<T>());
      const Vec3T<TK> d = pos - hub.r;
      const Vec3T<TK> dr = d - d.dot(disk) * disk;
      const TK r = sqrt(dr.dot(dr));
      // Positive twist and pitch turn the leading edge into the wind, about −x; an elastic
      // rotation about +x is the opposite.
      const T theta = T(st.twist) + T(pitch - rot(0));
      detail::SectionState<T> sec;
      try {
        sec = frozen ? detail::frozenSectionJet(am, st, vx, vy, theta, valueOf(r), frozen->axial(index),
                                                frozen->tangential(index), ws.jets[static_cast<std::size_t>(index)])
                     : detail::bemSection(am, st, vx, vy, theta, T(r), weight,
                                          ws.bem[static_cast<std::size_t>(index)]);
      } catch (const ComputeError& err) {
        throw ComputeError(body.name + " aero element " + std::to_string(si + 1) + " (span " +
                           std::to_string(st.span) + " m) at hub-height wind speed " +
                           std::to_string(valueOf(speed)) + " m/s: " + err.what());
      }
      const aero::SectionLoads<T>& L = sec.loads;
      const Vec3T<TK> xnb = cs * xab - ss * zab, znb = ss * xab + cs * zab;  // body components of xn, zn
      const Vec3T<T> Fb = L.fx * xnb.template cast<T>() + L.fy * yab.template cast<T>();
      const Vec3T<T> Mb = L.mz * znb.template cast<T>();
      sum.addBody(pt, s, Fb, Mb, st.weight);
      if (totals || (std::is_same_v<T, double> && record)) {  // ground components: rotor totals, the record
        const Vec3T<T> Fg = L.fx * xn.template cast<T>() + L.fy * ya.template cast<T>();
        const Vec3T<T> Mg = L.mz * zn.template cast<T>();
        if (totals) {
          const Vec3T<T> axis = disk.template cast<T>();
          totals->thrust += T(st.weight) * Fg.dot(axis);
          totals->torque += T(st.weight) * (Vec3T<T>(d.template cast<T>().cross(Fg)) + Mg).dot(axis);
        }
        if constexpr (std::is_same_v<T, double> && std::is_same_v<TK, double>) {
          if (record) {
            AeroElementState es;
            es.vx = vx;
            es.vy = vy;
            es.r = r;
            es.phi = L.phi;
            es.alpha = L.alpha;
            es.a = sec.a;
            es.ap = sec.ap;
            es.w = L.W;
            es.cl = L.cl;
            es.cd = L.cd;
            es.cm = L.cm;
            es.fx = L.fx;
            es.fy = L.fy;
            es.m = L.mz;
            record->elements.push_back(es);
            record->thrust += st.weight * Fg.dot(disk);
            record->torque += st.weight * (d.cross(Fg) + Mg).dot(disk);
          }
        }
      }
    }
    sum.project(m, ws, blade.body, e);
  }
}

}  // namespace whirl

#pragma once
/// \file
/// The blade elements of one blade: each element's point, motion and annulus axes from the blade
/// body's motion, and the loads of all its elements summed in body components (aero_loads.hpp for
/// the model; aero_model.hpp for the frames).
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "src/base/error.hpp"
#include "src/base/scalar.hpp"
#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/aero_section.hxx"
#include "src/dynamics/aero_skew.hxx"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/point_force.hxx"

namespace whirl::detail {

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

/// What a blade's element loads depend on: the pose and motion of the blade body's frame (R body →
/// ground, origin r, velocity v, angular velocity ω; ground components), its basis state c, ċ
/// (dim nc), its elastic coordinates q_e (dim ne) and its pitch angle.
template <class TK>
struct BladeMotion {
  const Mat3T<TK>& R;
  const Vec3T<TK>& r;
  const Vec3T<TK>& v;
  const Vec3T<TK>& w;
  const VecXT<TK>& c;
  const VecXT<TK>& cd;
  const TK* qe;
  TK pitch;
};

/// The axes of AeroDyn's blade frame without pitch: the body turned back by its pitch angle, in
/// body components (Ab) and ground components (Rnp = R Ab).
template <class TK>
struct BladeAxes {
  Mat3T<TK> Ab, Rnp;
};

template <class TK>
BladeAxes<TK> bladeAxes(const Body& body, const BladeMotion<TK>& bm) {
  BladeAxes<TK> a;
  a.Ab = axisRotation(body.axis, TK(-bm.pitch));
  a.Rnp = bm.R * a.Ab;
  return a;
}

/// The offset Σ_k P_k c_k of a body point from the body origin (body components, dim 3; P: 3 × nc) for the
/// basis coefficients coef(k), k < nc.
template <class TK, class Coef>
Vec3T<TK> pointOffset(const BodyPoint& pt, Coef coef) {
  Vec3T<TK> s = Vec3T<TK>::Zero();
  for (int k = 0; k < pt.P.cols(); ++k) s += pt.P.col(k) * coef(k);
  return s;
}

/// One element's point and annulus frame.
template <class TK>
struct ElementFrame {
  Vec3T<TK> s;              ///< the point's offset from the body origin, body components [m]
  Vec3T<TK> Rs, pos, vel;   ///< R s, the point's position [m] and velocity [m/s], ground components
  Vec3T<TK> xn, ya, zn;     ///< annulus axes x_a (downwind), y_a, z_a (span), ground components
  Vec3T<TK> xnb, yab, znb;  ///< the same axes, body components
  TK twist;                 ///< elastic rotation of the section about the span axis (body x) [rad]
};

/// The element at body point pt: its position, velocity and annulus frame — the no-pitch frame
/// turned about y_a by the out-of-plane slope of the deflected span axis. `curve` [rad] is AeroDyn's
/// BlCrvAng (AeroStation::curve): the node's reference orientation is turned about the pitched blade
/// frame's y axis (edgewise, y_r) by it before the elastic rotation, EulerConstruct(0, BlCrvAng,
/// −BlTwist) in AeroDyn's Init_u (AeroDyn.f90), so the span axis of the section leans downwind (body
/// +y) by it: (cos c, sin c, 0) in body components, turned by the small elastic rotation θ.
template <class TK>
ElementFrame<TK> elementFrame(const Body& body, const BodyPoint& pt, const BladeMotion<TK>& bm,
                              const BladeAxes<TK>& axes, double curve) {
  using std::sqrt;
  ElementFrame<TK> g;
  // Summed in locals from local pointers: summed into g.s, each term was stored and the basis
  // pointers reloaded (the result might alias them).
  const TK* c = bm.c.data();
  const TK* cd = bm.cd.data();
  const Vec3T<TK> s = pointOffset<TK>(pt, [c](int k) -> const TK& { return c[k]; });
  const Vec3T<TK> sd = pointOffset<TK>(pt, [cd](int k) -> const TK& { return cd[k]; });
  Vec3T<TK> rot = Vec3T<TK>::Zero();  // small rotations of the section about body x, y, z
  for (int j = 0; j < body.inertia.ne; ++j) rot += pt.theta.col(j) * bm.qe[j];
  g.s = s;
  g.Rs = bm.R * g.s;
  g.pos = bm.r + g.Rs;
  g.vel = bm.v + bm.w.cross(g.Rs) + bm.R * sd;
  // Out-of-plane slope of the deflected span axis e = e₀ + θ × e₀, e₀ = (cos c, sin c, 0): the annulus
  // frame's tilt; e = (1, θz, −θy) on a section without curve, written apart so that its results stay
  // bit for bit (the compiler's fused multiply-adds would round the general form differently).
  // AeroDyn extracts the tilt as the Euler angle about y_a (Calculate_MeshOrientation_NoSweepPitchTwist:
  // sin = e·x_a); the angle of e's projection on the (x_a, z_a) plane differs from it at second order
  // in the toe (e·y_a: curve and pitch together, or edgewise elastic slopes).
  // (Its dot products written out: a Vec3 built from the constant and two values went through the
  // stack, and reading it back as a pair stalled the store forwarding, a fifth of this function.)
  const Vec3T<TK> xab = axes.Ab.col(1), yab = axes.Ab.col(2), zab = axes.Ab.col(0);
  // cos and sin of the slope atan2(e·xa, e·za), without the angle.
  TK sx, sz;
  if (curve == 0.0) {
    sx = xab(0) + rot(2) * xab(1) - rot(1) * xab(2);
    sz = zab(0) + rot(2) * zab(1) - rot(1) * zab(2);
  } else {
    const double cc = std::cos(curve), sc = std::sin(curve);
    const TK e0 = cc - rot(2) * sc, e1 = sc + rot(2) * cc, e2 = rot(0) * sc - rot(1) * cc;
    sx = e0 * xab(0) + e1 * xab(1) + e2 * xab(2);
    sz = e0 * zab(0) + e1 * zab(1) + e2 * zab(2);
  }
  const TK h = sqrt(sx * sx + sz * sz);
  const TK cs = sz / h, ss = sx / h;
  const Vec3T<TK> xa = axes.Rnp.col(1), za = axes.Rnp.col(0);
  g.xn = cs * xa - ss * za;
  g.zn = ss * xa + cs * za;
  g.ya = axes.Rnp.col(2);
  g.xnb = cs * xab - ss * zab;
  g.znb = ss * xab + cs * zab;
  g.yab = yab;
  g.twist = rot(0);
  return g;
}

/// The distance of a point at d from the rotor apex (ground components) from the rotor axis `disk` [m].
template <class S>
S distanceFromAxis(const Vec3T<S>& d, const Vec3T<S>& disk) {
  using std::sqrt;
  const Vec3T<S> dr = d - d.dot(disk) * disk;
  return sqrt(dr.dot(dr));
}

/// R_tip of a blade (AeroDyn BEMT's Rtip, formed at each step): the largest distance of its elements from the
/// rotor axis, from the blade body's frame (R, origin r0, basis c) and the rotor apex and axis (ground
/// components). The element farthest out is found on the values; only its distance is formed in TK, whose
/// derivatives are the maximum's.
template <class TK>
TK bladeTipRadius(const Body& body, const AeroBlade& blade, const Mat3T<TK>& R, const Vec3T<TK>& r0, const VecXT<TK>& c,
                  const Vec3T<TK>& hub, const Vec3T<TK>& disk) {
  const auto value = [](const TK& x) { return valueOf(x); };
  const Mat3 Rv = R.unaryExpr(value);
  const Vec3 r0v = r0.unaryExpr(value), hubv = hub.unaryExpr(value), diskv = disk.unaryExpr(value);
  const TK* cp = c.data();
  double tip = 0.0;
  const BodyPoint* farthest = nullptr;
  for (const AeroStation& st : blade.stations) {
    const BodyPoint& pt = body.points[st.point];
    const Vec3 s = pointOffset<double>(pt, [cp](int k) { return valueOf(cp[k]); });
    const double r = distanceFromAxis<double>(Vec3(r0v + Rv * s - hubv), diskv);
    if (r > tip) {
      tip = r;
      farthest = &pt;
    }
  }
  if (!farthest) return TK(0.0);
  const Vec3T<TK> s = pointOffset<TK>(*farthest, [cp](int k) -> const TK& { return cp[k]; });
  return distanceFromAxis<TK>(Vec3T<TK>(r0 + R * s - hub), disk);
}

/// Where the elements of one blade are evaluated: the hub (rotor apex and disk normal, for the
/// distance of an element from the rotor axis), the wind, the BEM weight of the rotor's tip-speed
/// ratio, and the induction treatment.
template <class TK, class T>
struct RotorInflow {
  const Vec3T<TK>& hub;   ///< rotor apex, ground components [m]
  const Vec3T<TK>& disk;  ///< rotor axis (disk normal), ground components
  const T& speed;         ///< hub-height wind speed U [m/s]
  const Vec3& wind_dir;   ///< windDirection of the model's wind
  const T& weight;        ///< aero::inductionWeight of the tip-speed ratio (BEM solved only)
  const AeroInflow* frozen;
  const RotorSkew<TK>* skew = nullptr;  ///< the skewed-wake correction of the solved induction, if active
};

/// sum += the loads of blade bi's elements (body components: BodyLoadSum::addBody), elements numbered
/// from index0 over all blades; totals and record (double) accumulate when given.
/// Throws ComputeError naming the blade and element when BEM fails (a non-finite velocity, a root finder
/// that does not converge); where no bracket holds a valid root the inflow is geometric (bemSection).
template <class TK, class T>
void bladeLoads(const Model& m, int bi, int index0, const BladeMotion<TK>& bm, const RotorInflow<TK, T>& in,
                std::vector<BemRoot>& bem, std::vector<SectionJet>& jets, AeroRecord* record, RotorTotals<T>* totals,
                BodyLoadSum<T>& sum) {
  const AeroModel& am = m.aero;
  const AeroBlade& blade = am.blades[static_cast<std::size_t>(bi)];
  const Body& body = m.bodies[blade.body];
  const BladeAxes<TK> axes = bladeAxes(body, bm);
  const bool skewed = !in.frozen && in.skew && in.skew->active;
  // The skewed-wake correction needs R_tip, the largest distance of the blade's elements from the rotor axis,
  // before the first element's loads.
  const BladeSkew<TK> skew = skewed ? bladeSkew(*in.skew, bm.R,
                                                bladeTipRadius(body, blade, bm.R, bm.r, bm.c, in.hub, in.disk))
                                    : BladeSkew<TK>{};
  for (std::size_t si = 0; si < blade.stations.size(); ++si) {
    const int index = index0 + static_cast<int>(si);
    const AeroStation& st = blade.stations[si];
    const BodyPoint& pt = body.points[st.point];
    const ElementFrame<TK> g = elementFrame(body, pt, bm, axes, st.curve);
    const Vec3T<T> rel = steadyWind(am.wind, in.wind_dir, in.speed, g.pos(2)) - g.vel.template cast<T>();
    const T vx = rel.dot(g.xn.template cast<T>()), vy = rel.dot(g.ya.template cast<T>());
    const Vec3T<TK> d = g.pos - in.hub;
    const TK r = distanceFromAxis<TK>(d, in.disk);
    // Positive twist and pitch turn the leading edge into the wind, about −x; an elastic
    // rotation about +x is the opposite.
    const T theta = T(st.twist) + T(bm.pitch - g.twist);
    // Initialized from the call, not assigned (a copy read back wide from narrow stores stalls).
    const SectionState<T> sec = [&] {
      try {
        return in.frozen ? frozenSectionJet(am, st, vx, vy, theta, valueOf(r), in.frozen->axial(index),
                                            in.frozen->tangential(index), jets[static_cast<std::size_t>(index)])
                         : bemSection(am, st, vx, vy, theta, T(r), in.weight, bem[static_cast<std::size_t>(index)],
                                      skewed ? std::optional<ElementSkew<T>>(skew.template at<T>(*in.skew, r))
                                             : std::nullopt);
      } catch (const ComputeError& err) {
        throw ComputeError(body.name + " aero element " + std::to_string(si + 1) + " (span " + std::to_string(st.span) +
                           " m) at hub-height wind speed " + std::to_string(valueOf(in.speed)) + " m/s: " + err.what());
      }
    }();
    const aero::SectionLoads<T>& L = sec.loads;
    const Vec3T<T> Fb = L.fx * g.xnb.template cast<T>() + L.fy * g.yab.template cast<T>();
    const Vec3T<T> Mb = L.mz * g.znb.template cast<T>();
    sum.addBody(pt, g.s, Fb, Mb, st.weight);
    if (totals || (std::is_same_v<T, double> && record)) {  // ground components: rotor totals, the record
      const Vec3T<T> Fg = L.fx * g.xn.template cast<T>() + L.fy * g.ya.template cast<T>();
      const Vec3T<T> Mg = L.mz * g.zn.template cast<T>();
      if (totals) {
        const Vec3T<T> axis = in.disk.template cast<T>();
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
          es.bem_valid = sec.bem_valid;
          record->elements.push_back(es);
          record->thrust += st.weight * Fg.dot(in.disk);
          record->torque += st.weight * (d.cross(Fg) + Mg).dot(in.disk);
        }
      }
    }
  }
}

}  // namespace whirl::detail

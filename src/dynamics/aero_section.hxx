#pragma once
/// \file
/// One blade element's loads per unit span from its relative velocity: AeroDyn's BEMT
/// (src/aero/bem.hpp) with the frozen wake of an operating point, or with the induction solved for
/// the current inflow (quasi-steady, its derivative by the implicit-function theorem).
#include <cmath>
#include <optional>
#include <type_traits>

#include "src/aero/bem.hpp"
#include "src/base/scalar.hpp"
#include "src/dynamics/aero_skew.hxx"
#include "src/dynamics/workspace.hpp"
#include "src/model/aero_model.hpp"

namespace whirl::detail {

/// The BEM description of element st at distance r [m] from the rotor axis.
inline aero::BemStation bemStation(const AeroModel& am, const AeroStation& st, double r) {
  aero::BemStation b;
  b.r = r;
  b.z = st.z;
  b.hub_radius = am.hub_radius;
  b.tip_radius = am.tip_radius;
  b.blades = static_cast<int>(am.blades.size());
  b.chord = st.chord;
  b.polar = &am.polars[st.polar];
  b.kin_visc = am.kinematic_viscosity;
  return b;
}

template <class T>
struct SectionState {
  aero::SectionLoads<T> loads;
  double a = 0, ap = 0;   ///< induction factors (values)
  bool bem_valid = true;  ///< false: BEM had no valid root, the inflow is geometric (BemRoot::bem_valid)
};

/// Loads with the induced velocities held fixed (AeroDyn `computeFrozenWake`).
template <class T>
SectionState<T> frozenSection(const AeroModel& am, const AeroStation& st, const T& vx, const T& vy, const T& theta,
                              double r, double ax_ind, double tn_ind) {
  SectionState<T> s;
  s.loads = aero::frozenLoads(bemStation(am, st, r), vx, vy, theta, ax_ind, tn_ind, am.air_density, am.bem);
  const double vxv = valueOf(vx), vyv = valueOf(vy);
  s.a = vxv != 0 ? -ax_ind / vxv : 0;
  s.ap = vyv != 0 ? tn_ind / vyv : 0;
  return s;
}

/// frozenSection for an AD pass, from the element's jet: the loads and their derivatives in
/// (vx, vy, θ) are evaluated once (three seeded directions) and chained with the pass's derivatives of
/// vx, vy, θ — the same first derivatives as evaluating the section in the pass's scalar. The jet is
/// reused while the inflow values agree to round-off (the passes of one linearization; their
/// kinematics rounds differently from pass to pass). Only fx, fy, mz carry derivatives.
template <class T>
SectionState<T> frozenSectionJet(const AeroModel& am, const AeroStation& st, const T& vx, const T& vy, const T& theta,
                                 double r, double ax_ind, double tn_ind, SectionJet& jet) {
  if constexpr (!std::is_same_v<T, ADChunk>) {
    return frozenSection(am, st, vx, vy, theta, r, ax_ind, tn_ind);
  } else {
    const double x = valueOf(vx), y = valueOf(vy), th = valueOf(theta);
    const double tol = 1e-12, vscale = tol * (std::abs(x) + std::abs(y));
    if (!(jet.valid && std::abs(jet.vx - x) <= vscale && std::abs(jet.vy - y) <= vscale &&
          std::abs(jet.theta - th) <= tol && std::abs(jet.r - r) <= tol * r && jet.ax == ax_ind && jet.tn == tn_ind)) {
      using Der = ADChunk::DerType;
      const ADChunk X(x, Der::Unit(0)), Y(y, Der::Unit(1)), TH(th, Der::Unit(2));
      const aero::SectionLoads<ADChunk> L = aero::frozenLoads(bemStation(am, st, r), X, Y, TH, ax_ind, tn_ind,
                                                              am.air_density, am.bem);
      jet = SectionJet{true, x, y, th, r, ax_ind, tn_ind};
      jet.phi = L.phi.value();
      jet.alpha = L.alpha.value();
      jet.W = L.W.value();
      jet.cl = L.cl.value();
      jet.cd = L.cd.value();
      jet.cm = L.cm.value();
      jet.cx = L.cx.value();
      jet.cy = L.cy.value();
      const ADChunk* f[3] = {&L.fx, &L.fy, &L.mz};
      for (int i = 0; i < 3; ++i) {
        jet.f[i] = f[i]->value();
        for (int k = 0; k < 3; ++k) jet.J[i][k] = f[i]->derivatives()(k);
      }
    }
    SectionState<T> s;
    auto chained = [&](int i) {
      return ADChunk(jet.f[i], jet.J[i][0] * vx.derivatives() + jet.J[i][1] * vy.derivatives() +
                                   jet.J[i][2] * theta.derivatives());
    };
    s.loads.fx = chained(0);
    s.loads.fy = chained(1);
    s.loads.mz = chained(2);
    s.loads.phi = ADChunk(jet.phi);
    s.loads.alpha = ADChunk(jet.alpha);
    s.loads.W = ADChunk(jet.W);
    s.loads.cl = ADChunk(jet.cl);
    s.loads.cd = ADChunk(jet.cd);
    s.loads.cm = ADChunk(jet.cm);
    s.loads.cx = ADChunk(jet.cx);
    s.loads.cy = ADChunk(jet.cy);
    s.a = x != 0 ? -ax_ind / x : 0;
    s.ap = y != 0 ? tn_ind / y : 0;
    return s;
  }
}

/// `o` with another root tolerance (BemRoot::tolerance).
inline aero::BemOptions withTolerance(const aero::BemOptions& o, double tolerance) {
  aero::BemOptions c = o;
  c.tolerance = tolerance;
  return c;
}

/// Loads with the induction of the current inflow: BEM solved at the values, the inflow angle's
/// derivatives by the implicit-function theorem. Without induction (AeroDyn WakeMod = 0): φ is the
/// geometric inflow angle.
///
/// `weight` is AeroDyn's BEM weight of the rotor's tip-speed ratio (aero::inductionWeight): the
/// inductions are scaled by it; at 0 (λ ≤ 1: parked, idling, start-up) BEM is not solved at all.
/// `skew`: the element's skewed-wake correction (aero_skew.hxx), applied to the solved axial induction.
template <class T>
SectionState<T> bemSection(const AeroModel& am, const AeroStation& st, const T& vx, const T& vy, const T& theta,
                           const T& r, const T& weight, BemRoot& root,
                           const std::optional<ElementSkew<T>>& skew = std::nullopt) {
  if (!am.induction || valueOf(weight) == 0.0) return frozenSection(am, st, vx, vy, theta, valueOf(r), 0.0, 0.0);
  aero::BemStation b = bemStation(am, st, valueOf(r));
  b.theta = valueOf(theta);
  const double x = valueOf(vx), y = valueOf(vy);
  // The root depends on the values only: reuse it when they are the same bits, solve otherwise. An
  // AD pass, which reads only derivatives, also takes a root solved at values equal to round-off
  // (the double residual of the same point, whose kinematics rounds differently, or another chunk):
  // the loads' derivatives then differ from those at the exact root by that round-off only.
  const double tol = std::is_same_v<T, double> ? 0.0 : 1e-12;
  const double vscale = tol * (std::abs(x) + std::abs(y));
  // What the loads need of the root, in locals: read back from `root` just after the narrow stores
  // of a search, the fields were loaded in pairs and stalled the store forwarding.
  double phi = root.phi, ra = root.a, rap = root.ap, cl = root.cl, cd = root.cd, cm = root.cm;
  bool bem_valid = root.bem_valid, flow_at_root = root.flow_at_root;
  if (!(root.valid && std::abs(root.vx - x) <= vscale && std::abs(root.vy - y) <= vscale &&
        std::abs(root.theta - b.theta) <= tol && std::abs(root.r - b.r) <= tol * b.r)) {
    // The element's last root starts the search: the equilibrium iterates move it a little. Moved
    // as the frozen-wake angle atan2(X, Y) (X = Vx(1−a), Y = Vy(1+a')) moves to first order, it is
    // nearer still: what is left is the induction's response to the change.
    std::optional<double> hint;
    if (root.valid) {
      const double X = root.vx * (1 - root.a), Y = root.vy * (1 + root.ap);
      const double dX = (x - root.vx) * (1 - root.a), dY = (y - root.vy) * (1 + root.ap);
      double moved = (Y * dX - X * dY) / (X * X + Y * Y);
      // With the induction's response: the root's own move to first order (implicit-function theorem,
      // dφ = −(R_Vx dVx + R_Vy dVy)/R_φ). In the momentum region R = sin φ/(1 − a) − cos φ (Vx/Vy)(1 − k')
      // with a, k' functions of φ alone, so R_Vx, R_Vy are those of the tangential term and the move is
      // the frozen-wake one times R_φ,frozen/R_φ, R_φ,frozen = |(X, Y)|/((1 − a)(1 + a') Vy) (R_φ with a,
      // a' held) and R_φ the last search's secant slope. Only at a root in the operating bracket and for
      // a small move (near a fold R_φ → 0 and the first order says nothing).
      if (root.flow_at_root && x > 0 && y > 0 && root.search_slope > 0) {
        const double frozen_slope = std::sqrt(X * X + Y * Y) / ((1 - root.a) * (1 + root.ap) * root.vy);
        const double responded = moved * (frozen_slope / root.search_slope);
        if (std::abs(responded) < 0.01) moved = responded;
      }
      hint = root.phi + (std::abs(moved) < 0.05 ? moved : 0.0);
    }
    const aero::InflowRoot sol = root.tolerance > 0
                                     ? aero::findInflowRoot(b, x, y, withTolerance(am.bem, root.tolerance), hint,
                                                            root.valid ? root.search_slope : 0.0)
                                     : aero::findInflowRoot(b, x, y, am.bem, hint,
                                                            root.valid ? root.search_slope : 0.0);
    phi = sol.phi;
    ra = sol.a;
    rap = sol.ap;
    bem_valid = sol.valid;
    flow_at_root = sol.flow_at_root;
    cl = sol.at.coef.cl;
    cd = sol.at.coef.cd;
    cm = sol.at.coef.cm;
    root.valid = true;
    root.vx = x;
    root.vy = y;
    root.theta = b.theta;
    root.r = b.r;
    root.phi = phi;
    root.a = ra;
    root.ap = rap;
    root.bem_valid = bem_valid;
    root.slope = 0;
    root.search_slope = sol.slope;
    root.flow_at_root = flow_at_root;
    root.cl = cl;
    root.cd = cd;
    root.cm = cm;
  }
  if (!bem_valid) {  // no valid BEM root: the geometric inflow, a = a' = 0 (AeroDyn's fallback)
    SectionState<T> s = frozenSection(am, st, vx, vy, theta, valueOf(r), 0.0, 0.0);
    s.bem_valid = false;
    return s;
  }
  const bool blended = valueOf(weight) < 1.0;
  if (skew && !aero::hasFixedInductions(b, am.bem)) {
    // The root's induction corrected, then its loads through the induced velocities (limited and weighted
    // as DBEMT's: AeroDyn applies the correction to the solved induction before the low-TSR weight).
    const T* w = blended ? &weight : nullptr;
    if constexpr (std::is_same_v<T, double>) {
      const double ax = -vx * ra * skewFactor<double>(am, *skew, ra), tn = vy * rap;
      const auto [fx, fy] = aero::inducedFlow<double>(vx, vy, ax, tn, w);
      return SectionState<T>{aero::inducedVelocityLoads<double>(b, vx, vy, theta, ax, tn, am.air_density, w),
                             vx != 0 ? 1.0 - fx / vx : 0.0, vy != 0 ? fy / vy - 1.0 : 0.0, true};
    } else {
      aero::InducedVelocity<T> iv = aero::quasiSteadyInducedVelocity<T>(b, vx, vy, theta, phi, am.bem, &r, &root.slope);
      iv.axial = iv.axial * skewFactor<T>(am, *skew, T(-iv.axial / vx));
      const auto [fx, fy] = aero::inducedFlow<T>(vx, vy, iv.axial, iv.tangential, w);
      return SectionState<T>{aero::inducedVelocityLoads<T>(b, vx, vy, theta, iv.axial, iv.tangential, am.air_density,
                                                           w),
                             valueOf(vx) != 0 ? 1.0 - valueOf(fx) / valueOf(vx) : 0.0,
                             valueOf(vy) != 0 ? valueOf(fy) / valueOf(vy) - 1.0 : 0.0, true};
    }
  }
  const double a = ra * (blended ? valueOf(weight) : 1.0), ap = rap * (blended ? valueOf(weight) : 1.0);
  // The loads are constructed in the returned state, not assigned to it: a copy of the callee's
  // result, read back wide from its narrow stores, stalled the store forwarding.
  if constexpr (std::is_same_v<T, double>) {
    // The root's own inductions: the implicit-function step and its AD evaluation of ∂R/∂φ only serve
    // the derivatives (half the cost of an equilibrium's residual).
    // At a root in the operating bracket with its inductions unlimited, the root's own angle and
    // polar are AeroDyn's output ones (to the root tolerance): no atan2, no second table look-up.
    if (flow_at_root && !blended)
      return SectionState<T>{aero::loadsAtRoot(b, vx, vy, theta, phi, ra, rap, {cl, cd, cm}, am.air_density), a, ap,
                             true};
    return SectionState<T>{aero::loadsAtInduction(b, vx, vy, theta, a, ap, am.air_density), a, ap, true};
  } else {
    return SectionState<T>{aero::quasiSteadyLoads(b, vx, vy, theta, phi, am.air_density, am.bem, &r,
                                                  blended ? &weight : nullptr, &root.slope),
                           a, ap, true};
  }
}

}  // namespace whirl::detail

#pragma once
/// \file
/// One blade element's loads per unit span from its relative velocity: AeroDyn's BEMT
/// (src/aero/bem.hpp) with the frozen wake of an operating point, or with the induction solved for
/// the current inflow (quasi-steady, its derivative by the implicit-function theorem).
#include <cmath>
#include <type_traits>

#include "src/aero/bem.hpp"
#include "src/model/scalar.hpp"
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
  return b;
}

template <class T>
struct SectionState {
  aero::SectionLoads<T> loads;
  double a = 0, ap = 0;  ///< induction factors (values)
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

/// Loads with the induction of the current inflow: BEM solved at the values, the inflow angle's
/// derivatives by the implicit-function theorem. Without induction (AeroDyn WakeMod = 0): φ is the
/// geometric inflow angle.
template <class T>
SectionState<T> bemSection(const AeroModel& am, const AeroStation& st, const T& vx, const T& vy, const T& theta,
                           const T& r, BemRoot& root) {
  if (!am.induction) return frozenSection(am, st, vx, vy, theta, valueOf(r), 0.0, 0.0);
  aero::BemStation b = bemStation(am, st, valueOf(r));
  b.theta = valueOf(theta);
  const double x = valueOf(vx), y = valueOf(vy);
  // The root depends on the values only: reuse it when they are the same bits, solve otherwise. An
  // AD pass, which reads only derivatives, also takes a root solved at values equal to round-off
  // (the double residual of the same point, whose kinematics rounds differently, or another chunk):
  // the loads' derivatives then differ from those at the exact root by that round-off only.
  const double tol = std::is_same_v<T, double> ? 0.0 : 1e-12;
  const double vscale = tol * (std::abs(x) + std::abs(y));
  if (!(root.valid && std::abs(root.vx - x) <= vscale && std::abs(root.vy - y) <= vscale &&
        std::abs(root.theta - b.theta) <= tol && std::abs(root.r - b.r) <= tol * b.r)) {
    // The element's last root starts the search: the equilibrium iterates move it a little.
    const aero::BemSolution sol =
        aero::solveInflow(b, x, y, am.bem, root.valid ? std::optional<double>(root.phi) : std::nullopt);
    root = BemRoot{true, x, y, b.theta, b.r, sol.phi, sol.a, sol.ap};
  }
  SectionState<T> s;
  s.loads = aero::quasiSteadyLoads(b, vx, vy, theta, root.phi, am.air_density, am.bem, &r);
  s.a = root.a;
  s.ap = root.ap;
  return s;
}

}  // namespace whirl::detail

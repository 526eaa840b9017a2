#pragma once
/// \file
/// One blade element's section with aerodynamic states (addUnsteadyAeroLoads, aero_unsteady.cpp): the
/// loads with its unsteady-airfoil states, the quasi-steady frozen-wake loads, its state rates, as
/// functions of the section inputs (vx, vy, θ, r, ω, the rotor's BEM weight, the skew's χ0 and
/// (r / R_tip) sin ψ) and its states; and their preaccumulation (UnsteadySectionJet): an AD pass that
/// seeds none of the element's states chains the jet's derivatives with its own derivatives of the eight
/// inputs instead of evaluating the airfoil and inflow equations in its AD scalar (Griewank & Walther
/// 2008, §10), as the frozen-wake section jets of aero_section.hxx do.
#include <array>
#include <cmath>
#include <optional>
#include <tuple>
#include <type_traits>

#include "src/aero/bem.hpp"
#include "src/aero/dynamic_inflow.hpp"
#include "src/dynamics/aero_element.hxx"
#include "src/dynamics/aero_section.hxx"
#include "src/dynamics/aero_skew.hxx"
#include "src/dynamics/aero_unsteady.hpp"

namespace whirl::detail {

template <class T>
T atan2S(const T& y, const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::atan2(y, x);
  } else {  // the fixed-size AD type (Eigen's overload goes through a dynamic-size derivative vector)
    const double xv = x.value(), yv = y.value(), h = xv * xv + yv * yv;
    return T(std::atan2(yv, xv), (xv * y.derivatives() - yv * x.derivatives()) / h);
  }
}

// The section loads from the UA coefficients at the frozen-wake flow (x, y) = (Vx + AxInd, Vy + TnInd),
// as aero::frozenLoads forms them from the static polar (AeroDyn SetOutputsFromBEMT).
template <class T>
aero::SectionLoads<T> loadsOfCoefficients(const T& x, const T& y, const T& phi, const T& alpha, const T& W,
                                          const aero::Coefficients<T>& c, double chord, double rho) {
  aero::SectionLoads<T> L;
  L.phi = phi;
  L.alpha = alpha;
  L.W = W;
  L.cl = c.cl;
  L.cd = c.cd;
  L.cm = c.cm;
  const T sphi = x / W, cphi = y / W;
  L.cx = c.cl * cphi + c.cd * sphi;
  L.cy = c.cl * sphi - c.cd * cphi;
  const T qd = 0.5 * rho * W * W;
  L.fx = L.cx * qd * chord;
  L.fy = -L.cy * qd * chord;
  L.mz = c.cm * qd * (chord * chord);
  return L;
}

// The quasi-steady induced velocity of an element at (vx, vy, θ): the BEM root solved in double at the values
// (kept in `root` and reused while the values agree to round-off: the AD passes of one linearization), the
// derivatives by the implicit-function theorem (aero::quasiSteadyInducedVelocity). No valid root: AeroDyn's
// geometric fallback, no induction.
template <class T>
aero::InducedVelocity<T> quasiSteadyInduction(const AeroModel& am, aero::BemStation b, const T& vx, const T& vy,
                                              const T& theta, const T& r, BemRoot& root) {
  const double x = valueOf(vx), y = valueOf(vy), th = valueOf(theta);
  b.theta = th;
  const double tol = std::is_same_v<T, double> ? 0.0 : 1e-12, vscale = tol * (std::abs(x) + std::abs(y));
  if (!(root.valid && std::abs(root.vx - x) <= vscale && std::abs(root.vy - y) <= vscale &&
        std::abs(root.theta - th) <= tol && std::abs(root.r - b.r) <= tol * b.r)) {
    const aero::InflowRoot sol = aero::findInflowRoot(b, x, y, am.bem,
                                                      root.valid ? std::optional<double>(root.phi) : std::nullopt);
    root = BemRoot{};
    root.valid = true;
    root.vx = x;
    root.vy = y;
    root.theta = th;
    root.r = b.r;
    root.phi = sol.phi;
    root.a = sol.a;
    root.ap = sol.ap;
    root.bem_valid = sol.valid;
  }
  if (!root.bem_valid) return {T(0.0), T(0.0), false};
  if constexpr (!std::is_same_v<T, double>) {
    // An AD pass that seeds none of the inflow (the chunks of state columns): no derivatives, and the value
    // is the root's own (−Vx a, Vy a'), without the implicit-function step in the AD scalar.
    if (vx.derivatives().isZero(0.0) && vy.derivatives().isZero(0.0) && theta.derivatives().isZero(0.0) &&
        r.derivatives().isZero(0.0))
      return {T(-x * root.a), T(y * root.ap), aero::hasFixedInductions(b, am.bem)};
  }
  return aero::quasiSteadyInducedVelocity<T>(b, vx, vy, theta, root.phi, am.bem, &r, &root.slope);
}

/// The section inputs of an element (ground components resolved in its frame; see the file comment).
template <class T>
struct UnsteadySectionInputs {
  T vx, vy, theta, r, omega, weight;
  ElementSkew<T> skew;
};

/// What an element's section does not take as inputs: fixed at a point.
struct UnsteadySectionContext {
  const AeroModel& am;
  const AeroStation& st;
  double ax, tn;      ///< the frozen wake's induced velocities
  bool states;        ///< states given (else every element quasi-steady on the frozen wake)
  bool dynamic;       ///< dynamic-inflow states
  bool skew;          ///< the skewed-wake correction of the dynamic inflow
  bool quasi_steady;  ///< the quasi-steady frozen-wake loads wanted too
};

/// The section's outputs: loads with the states (per unit length, annulus axes), the quasi-steady ones
/// (if asked), the element's state rates (UA states, then dynamic-inflow states: v, v tangential, v1, v1
/// tangential), the quasi-steady induced velocities (dynamic inflow) and the UA inputs.
template <class T>
struct UnsteadySectionOutputs {
  T fx{0.0}, fy{0.0}, mz{0.0}, qs_fx{0.0}, qs_fy{0.0}, qs_mz{0.0};
  std::array<T, UnsteadySectionJet::kStates> zdot;
  T qs_axial{0.0}, qs_tangential{0.0};
  aero::UaInput<T> ua_input;
};

/// The outputs at inputs s and the element's UA states z_ua and dynamic-inflow states z_in (null where it
/// has none). `root`: the element's BEM root, reused at the same values.
template <class T>
UnsteadySectionOutputs<T> unsteadySection(const UnsteadySectionContext& c, const UnsteadySectionInputs<T>& s,
                                          const T* z_ua, const T* z_in, BemRoot& root) {
  using std::sqrt;
  const AeroModel& am = c.am;
  const AeroStation& st = c.st;
  const double r = valueOf(s.r);
  const int ns = uaStatesPerElement(am);
  UnsteadySectionOutputs<T> o;
  o.zdot.fill(T(0.0));
  // The relative flow (x, y) = (Vx(1−a), Vy(1+a')): the frozen wake's, or with the dynamic-inflow states
  // v (AeroDyn calculate_Inductions_from_DBEMT), their rates driven by the quasi-steady induction.
  T x = valueOf(s.vx) == 0 ? s.vx : T(s.vx + c.ax), y = valueOf(s.vy) == 0 ? s.vy : T(s.vy + c.tn);
  T v_ax(0.0), v_tn(0.0);  // the induced velocities the loads see, with dynamic inflow
  if (c.dynamic) {
    const aero::BemStation b = bemStation(am, st, r);
    const aero::InducedVelocity<T> qs = quasiSteadyInduction(am, b, s.vx, s.vy, s.theta, s.r, root);
    // Elements with fixed inductions (a loss constant of 0) take the BEM ones (AeroDyn skips DBEMT there).
    v_ax = qs.fixed ? qs.axial : z_in[0];
    v_tn = qs.fixed ? qs.tangential : z_in[1];
    if (c.skew && !qs.fixed && valueOf(s.vx) != 0) v_ax = v_ax * skewFactor<T>(am, s.skew, T(-v_ax / s.vx));
    std::tie(x, y) = aero::inducedFlow<T>(s.vx, s.vy, v_ax, v_tn, &s.weight);
    const double tau2 = aero::dbemtTau2(am.tau1, st.span_ratio);
    const aero::OyeState<T> da = aero::oyeDerivative<T>({z_in[2], z_in[0]}, qs.axial, am.tau1, tau2);
    const aero::OyeState<T> dt = aero::oyeDerivative<T>({z_in[3], z_in[1]}, qs.tangential, am.tau1, tau2);
    const int k = st.ua ? ns : 0;
    o.zdot[k] = da.v;
    o.zdot[k + 1] = dt.v;
    o.zdot[k + 2] = da.v1;
    o.zdot[k + 3] = dt.v1;
    o.qs_axial = qs.axial;
    o.qs_tangential = qs.tangential;
  }
  aero::SectionLoads<T> L;
  if (!c.states) {
    L = aero::frozenLoads(bemStation(am, st, r), s.vx, s.vy, s.theta, c.ax, c.tn, am.air_density, am.bem);
  } else if (!st.ua) {
    L = c.dynamic ? aero::inducedVelocityLoads<T>(bemStation(am, st, r), s.vx, s.vy, s.theta, v_ax, v_tn,
                                                  am.air_density, &s.weight)
                  : aero::frozenLoads(bemStation(am, st, r), s.vx, s.vy, s.theta, c.ax, c.tn, am.air_density, am.bem);
  } else {
    const T phi = atan2S(x, y), alpha = phi - s.theta, W = sqrt(x * x + y * y);
    using std::cos;
    using std::sin;
    const aero::UaInput<T> in{atan2S(T(W * sin(alpha) + s.omega * (0.5 * st.chord)), T(W * cos(alpha))), alpha, W,
                              s.omega};
    const aero::UaSection sec = uaSection(am, st);
    aero::HgmState<T> xs{T(0.0), T(0.0), T(0.0), T(0.0)};
    if (ns == 4) xs = {z_ua[0], z_ua[1], z_ua[2], z_ua[3]};
    else xs.x4 = z_ua[0];
    L = loadsOfCoefficients(x, y, phi, alpha, W, aero::hgmLoads(sec, xs, in), st.chord, am.air_density);
    const aero::HgmState<T> dx = aero::hgmDerivative(sec, xs, in);
    if (ns == 4) {
      o.zdot[0] = dx.x1;
      o.zdot[1] = dx.x2;
      o.zdot[2] = dx.x3;
      o.zdot[3] = dx.x4;
    } else {
      o.zdot[0] = dx.x4;
    }
    o.ua_input = in;
  }
  o.fx = L.fx;
  o.fy = L.fy;
  o.mz = L.mz;
  if (c.quasi_steady && c.states && (st.ua || c.dynamic)) {
    const aero::SectionLoads<T> Q = aero::frozenLoads(bemStation(am, st, r), s.vx, s.vy, s.theta, c.ax, c.tn,
                                                      am.air_density, am.bem);
    o.qs_fx = Q.fx;
    o.qs_fy = Q.fy;
    o.qs_mz = Q.mz;
  } else if (c.quasi_steady) {  // the element has neither states nor dynamic inflow: the same loads
    o.qs_fx = L.fx;
    o.qs_fy = L.fy;
    o.qs_mz = L.mz;
  }
  return o;
}

/// The section's outputs in the AD scalar through the element's jet (formed at these inputs' and states'
/// values if it was formed at others): the states unseeded, the quasi-steady loads and rates included.
inline UnsteadySectionOutputs<ADChunk> unsteadySectionByJet(const UnsteadySectionContext& c,
                                                            const UnsteadySectionInputs<ADChunk>& s,
                                                            const ADChunk* z_ua, const ADChunk* z_in, int n_ua,
                                                            int n_in, BemRoot& root, UnsteadySectionJet& jet) {
  using Jet = UnsteadySectionJet;
  const std::array<const ADChunk*, Jet::kInputs> in = {&s.vx,    &s.vy,     &s.theta,     &s.r,
                                                       &s.omega, &s.weight, &s.skew.chi0, &s.skew.radial_sin};
  using Key = Eigen::Matrix<double, Jet::kInputs + Jet::kStates + 2, 1>;
  Key key = Key::Zero();
  for (int k = 0; k < Jet::kInputs; ++k) key(k) = in[static_cast<std::size_t>(k)]->value();
  for (int k = 0; k < n_ua; ++k) key(Jet::kInputs + k) = z_ua[k].value();
  for (int k = 0; k < n_in; ++k) key(Jet::kInputs + n_ua + k) = z_in[k].value();
  key(Jet::kInputs + Jet::kStates) = c.ax;
  key(Jet::kInputs + Jet::kStates + 1) = c.tn;
  if (!jet.valid || key != jet.key) {
    UnsteadySectionInputs<ADChunk> seeded = s;
    const std::array<ADChunk*, Jet::kInputs> out = {&seeded.vx,        &seeded.vy,
                                                    &seeded.theta,     &seeded.r,
                                                    &seeded.omega,     &seeded.weight,
                                                    &seeded.skew.chi0, &seeded.skew.radial_sin};
    for (int k = 0; k < Jet::kInputs; ++k)
      *out[static_cast<std::size_t>(k)] = ADChunk(key(k), ADChunk::DerType::Unit(k));
    std::array<ADChunk, Jet::kStates> zc;
    for (int k = 0; k < n_ua + n_in; ++k) zc[static_cast<std::size_t>(k)] = ADChunk(key(Jet::kInputs + k));
    UnsteadySectionContext cq = c;
    cq.quasi_steady = true;
    const UnsteadySectionOutputs<ADChunk> f = unsteadySection(cq, seeded, zc.data(), zc.data() + n_ua, root);
    const std::array<const ADChunk*, 6> loads = {&f.fx, &f.fy, &f.mz, &f.qs_fx, &f.qs_fy, &f.qs_mz};
    for (int k = 0; k < 6; ++k) {
      jet.value(k) = loads[static_cast<std::size_t>(k)]->value();
      jet.d.row(k) = loads[static_cast<std::size_t>(k)]->derivatives().transpose();
    }
    for (int k = 0; k < Jet::kStates; ++k) {
      jet.value(6 + k) = f.zdot[static_cast<std::size_t>(k)].value();
      jet.d.row(6 + k) = f.zdot[static_cast<std::size_t>(k)].derivatives().transpose();
    }
    jet.key = key;
    jet.valid = true;
  }
  // The pass's derivatives: outputs' = ∂ outputs/∂ inputs × inputs' (kChunk directions).
  Eigen::Matrix<double, Jet::kInputs, kChunk> din;
  for (int k = 0; k < Jet::kInputs; ++k) din.row(k) = in[static_cast<std::size_t>(k)]->derivatives().transpose();
  const Eigen::Matrix<double, Jet::kOutputs, kChunk> dout = jet.d * din;
  auto at = [&](int k) { return ADChunk(jet.value(k), dout.row(k).transpose()); };
  UnsteadySectionOutputs<ADChunk> o;
  o.fx = at(0);
  o.fy = at(1);
  o.mz = at(2);
  o.qs_fx = at(3);
  o.qs_fy = at(4);
  o.qs_mz = at(5);
  for (int k = 0; k < Jet::kStates; ++k) o.zdot[static_cast<std::size_t>(k)] = at(6 + k);
  return o;
}

}  // namespace whirl::detail

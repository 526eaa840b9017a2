#pragma once
/// \file
/// Definitions of the HGM model's templates (unsteady_airfoil.hpp); included by unsteady_airfoil.cpp,
/// which instantiates them for double and ADChunk.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/aero/unsteady_airfoil.hpp"
#include "src/base/scalar.hpp"

namespace whirl::aero {
namespace hgm_detail {

constexpr double kPi = std::numbers::pi;
constexpr double kUMin = 0.01;       ///< AeroDyn UA_u_min [m/s]
constexpr double kMaxTuOmega = 1.5;  ///< AeroDyn MaxTuOmega [-]

template <class T>
T clampT(const T& v, double lo, double hi) {
  if (valueOf(v) < lo) return T(lo);
  if (valueOf(v) > hi) return T(hi);
  return v;
}

/// NWTC MPi2Pi on a scalar of any type: the wrap shifts the value only, not its derivatives.
template <class T>
T wrapped(const T& a) {
  return a + (wrapMPi2Pi(valueOf(a)) - valueOf(a));
}

/// NWTC BlendCosine: 0 below lo, 1 above hi, a half cosine between.
template <class T>
T blendCosine(const T& x, double lo, double hi) {
  using std::cos;
  if (valueOf(x) >= hi) return T(1.0);
  if (valueOf(x) <= lo || !(lo < hi)) return T(0.0);
  return 0.5 * (1.0 - cos((x - lo) / (hi - lo) * kPi));
}

template <class T>
T absT(const T& v) {
  return valueOf(v) < 0 ? T(-v) : v;
}

/// αE = α34 (1 − A1 − A2) + x1 + x2, α34 wrapped into (−π, π] first (Get_HGM_constants).
template <class T>
T effectiveAngle(const UaSection& s, const T& alpha_34, const HgmState<T>& x) {
  if (s.ua_mod == 6) return alpha_34;  // UA_OYE: no shed vorticity
  const UaConstants& c = s.ua->c;
  return alpha_34 * (1.0 - c.A1 - c.A2) + x.x1 + x.x2;
}

template <class T>
T tuOmega(const T& tu, const T& omega) {
  return clampT<T>(tu * omega, -kMaxTuOmega, kMaxTuOmega);
}

}  // namespace hgm_detail

template <class T>
T hgmTimeScale(const T& u, double chord) {
  using hgm_detail::clampT;
  const T um = valueOf(u) < hgm_detail::kUMin ? T(hgm_detail::kUMin) : u;
  return clampT<T>(chord / (2.0 * um), 0.001, 50.0);
}

template <class T>
HgmState<T> hgmDerivative(const UaSection& s, const HgmState<T>& x, const UaInput<T>& in) {
  using namespace hgm_detail;
  const UaConstants& c = s.ua->c;
  const T tu = hgmTimeScale(in.u, s.chord);
  const T a34 = wrapped(in.alpha_34);
  const T x4 = clampT<T>(x.x4, 0.0, 1.0);
  if (s.ua_mod == 6) {  // UA_OYE: x4 alone, alphaF = α34
    const T zero(0.0);
    return {zero, zero, zero, (separationAt(*s.ua, a34).f_st - x4) / (c.T_f0 * tu)};
  }
  const T alpha_e = effectiveAngle(s, a34, x);
  const T alpha_f = x.x3 / c.c_lalpha + c.alpha0;  // Get_alphaF, eq. 15
  const T f_st = separationAt(*s.ua, alpha_f).f_st;
  const T cl_p = c.c_lalpha * (alpha_e - c.alpha0) + kPi * tuOmega(tu, in.omega);  // eq. 13
  HgmState<T> d;
  d.x1 = -c.b1 / tu * x.x1 + c.b1 * c.A1 / tu * a34;  // eq. 8 (U̇ = 0)
  d.x2 = -c.b2 / tu * x.x2 + c.b2 * c.A2 / tu * a34;  // eq. 9
  d.x3 = (cl_p - x.x3) / (c.T_p * tu);                // eq. 10
  d.x4 = (f_st - x4) / (c.T_f0 * tu);                 // eq. 11
  return d;
}

template <class T>
HgmState<T> hgmSteady(const UaSection& s, const UaInput<T>& in) {
  using namespace hgm_detail;
  const UaConstants& c = s.ua->c;
  const T tu = hgmTimeScale(in.u, s.chord);
  const T a34 = wrapped(in.alpha_34);
  HgmState<T> x;
  if (s.ua_mod == 6) {  // HGM_Steady for UA_OYE: x3 the static Cl (unused), x4 = f_st(α34)
    return {T(0.0), T(0.0), evaluate(*s.polar, a34).cl, separationAt(*s.ua, a34).f_st};
  }
  x.x1 = c.A1 * a34;
  x.x2 = c.A2 * a34;
  x.x3 = c.c_lalpha * (a34 - c.alpha0) + kPi * tuOmega(tu, in.omega);
  x.x4 = separationAt(*s.ua, T(x.x3 / c.c_lalpha + c.alpha0)).f_st;
  return x;
}

template <class T>
Coefficients<T> hgmLoads(const UaSection& s, const HgmState<T>& x, const UaInput<T>& in) {
  using namespace hgm_detail;
  using std::sqrt;
  const UaConstants& c = s.ua->c;
  const T tu = hgmTimeScale(in.u, s.chord);
  const T a34 = wrapped(in.alpha_34);
  const T alpha_e = effectiveAngle(s, a34, x);
  const T tw = tuOmega(tu, in.omega);
  const T x4 = clampT<T>(x.x4, 0.0, 1.0);
  const Coefficients<T> st_e = evaluate(*s.polar, alpha_e);
  const Separation<T> sep_e = separationAt(*s.ua, alpha_e);
  const T cl_fa = (alpha_e - c.alpha0) * c.c_lalpha;
  // Δ (eq. 20): √ of f_st and x4; at 0 its derivative is infinite (as in AeroDyn), so a value of 0 is
  // taken as a constant.
  auto root = [](const T& v) { return valueOf(v) > 0 ? T(sqrt(v)) : T(0.0); };
  const T delta = 0.5 * (root(sep_e.f_st) - root(x4)) - 0.25 * (sep_e.f_st - x4);
  const T cl_circ = x4 * cl_fa + (1.0 - x4) * sep_e.cl_fs;  // eq. 19
  Coefficients<T> out;
  if (s.ua_mod == 6) {  // UA_OYE: the lagged separation only, static Cd and Cm
    out.cl = cl_circ;
    out.cd = st_e.cd;
    out.cm = s.has_cm ? st_e.cm : T(0.0);
  } else {
    out.cl = cl_circ + kPi * tw;                                                              // eq. 16
    out.cd = st_e.cd + (a34 - alpha_e) * cl_circ + (st_e.cd - c.Cd0) * delta + cl_circ * tw;  // eq. 17
    out.cm = s.has_cm ? T(st_e.cm - 0.5 * kPi * tw) : T(0.0);                                 // eq. 18
  }
  // UA_BlendSteady: towards the static polar at the section's α near UACutout and at low speed.
  const T w = (1.0 - blendCosine(absT(wrapped(in.alpha_ac)), c.ua_cutout_blend, c.ua_cutout)) *
              blendCosine(absT(in.u), kUMin, 1.0);
  if (valueOf(w) < 1.0) {
    const Coefficients<T> st = evaluate(*s.polar, in.alpha_ac);
    out.cl = out.cl * w + (1.0 - w) * st.cl;
    out.cd = out.cd * w + (1.0 - w) * st.cd;
    out.cm = out.cm * w + (1.0 - w) * (s.has_cm ? st.cm : T(0.0));
  }
  return out;
}

}  // namespace whirl::aero

#include "src/aero/bem.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <type_traits>

#include "src/aero/prandtl_expansion.hpp"
#include "src/base/brent.hpp"
#include "src/base/error.hpp"
#include "src/base/scalar.hpp"

namespace whirl::aero {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInductionLimit = 1e6;  // AeroDyn InductionLimit (inductionFactors0, getTangentialInduction)
constexpr double kMinF = 1e-4;           // BEMTU_InductionWithResidual: F = max(F, 0.0001)
// BEMTUncoupled BEMT_MaxInduction / BEMT_MinInduction (limitInductionFactors).
constexpr double kMaxA = 1.5, kMinA = -1.0, kMaxAp = 1.0, kMinAp = -1.0;
// BEMT_epsilon2 = 10 sqrt(epsilon) for double precision (ReKi = R8Ki in OpenFAST's default double build): the
// distance kept from the singular angles 0, ±π/2, ±π by the brackets.
const double kEps2 = 10.0 * std::sqrt(DBL_EPSILON);

/// NWTC EqualRealNos for double: |a − b| ≤ max(|a + b|, 1) · 100 ε / 2.
bool equal(double a, double b) { return std::abs(a - b) <= std::max(std::abs(a + b), 1.0) * 50.0 * DBL_EPSILON; }
/// BEMTUncoupled VelocityIsZero.
bool velocityIsZero(double v) { return std::abs(v) < kZeroVelocity; }
/// Fortran SIGN(a, b): |a| with the sign of b (b = 0 → +).
double fsign(double a, double b) { return b >= 0 ? std::abs(a) : -std::abs(a); }

template <class T>
T absT(const T& x) {
  return valueOf(x) < 0 ? T(-x) : x;
}

double atan2T(double y, double x) { return std::atan2(y, x); }
/// atan2 for the fixed-size AD type (Eigen's overload goes through a dynamic-size derivative vector).
ADChunk atan2T(const ADChunk& y, const ADChunk& x) {
  const double xv = x.value(), yv = y.value(), h = xv * xv + yv * yv;
  ADChunk::DerType d = (xv * y.derivatives() - yv * x.derivatives()) / h;
  return ADChunk(std::atan2(yv, xv), d);
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}
std::string deg(double rad) { return num(rad * 180.0 / kPi); }

double stationZ(const BemStation& s) { return s.z > 0 ? s.z : s.r; }

/// AeroDyn p%FixedInductions: a loss constant of exactly 0 (the tip node, or a node at the blade root) with that
/// loss on → a = 1, a' = 0 and a zero residual whatever φ.
/// A zero hub radius (infinite hub-loss constant, F_hub = 1) never fixes the inductions here; in AeroDyn,
/// EqualRealNos(+Inf, 0) is true (its tolerance scales with |a + b| = Inf), so zHub = 0 with HubLoss on would fix
/// a = 1 at every node — not reproduced.
bool fixedInductions(const BemStation& s, const BemOptions& o, double tip, double hub) {
  return (o.tip_loss && equal(tip, 0.0)) || (o.hub_loss && s.hub_radius > 0 && equal(hub, 0.0));
}

/// A station's loss constants, whether they fix its inductions, and its solidity at s.r: formed once
/// per root search, not at each of its evaluations.
struct StationConstants {
  double tip, hub;
  bool fixed;
  double sigma;
};
StationConstants stationConstants(const BemStation& s, const BemOptions& o) {
  const double tip = tipLossConstant(s), hub = hubLossConstant(s);
  return {tip, hub, fixedInductions(s, o, tip, hub), s.blades * s.chord / (2.0 * kPi * s.r)};
}

/// The tip and hub parts of one root search (lossFactor).
struct LossParts {
  PrandtlExpansion tip, hub;
};

/// Prandtl factor, getHubTipLossCorrection with BEM_Mod = 1 (BEMMod_2D):
///   F = (2/π) acos(min(1, exp(−c_tip/|sin φ|))) · (2/π) acos(min(1, exp(−c_hub/|sin φ|))), 1 when sin φ = 0.
template <class T>
T lossFactor(const StationConstants& lc, const T& sphi, const BemOptions& o, LossParts* parts = nullptr) {
  using std::acos;
  using std::exp;
  T F(1.0);
  const double sv = std::abs(valueOf(sphi));
  if (equal(sv, 0.0)) return F;
  const T sabs = absT(sphi);
  auto part = [&](double c, PrandtlExpansion* expansion) -> T {
    if constexpr (std::is_same_v<T, double>) {
      // (2/π) acos(exp(−f)) rounds to exactly 1 for f ≥ 36.3 (exp(−f) < 1.7e-16, below half an ulp
      // of π/2): the hub loss of every element away from the root and the tip loss of small inflow
      // angles, two libm calls of each induction evaluation, skipped with the same value.
      const double f = c / sv;
      if (f >= 38.0) return 1.0;
      if (expansion) return expansion->at(f);
      const double e = std::exp(-f);
      return e < 1.0 ? (2.0 / kPi) * std::acos(e) : 0.0;  // min(1, e) = 1 → acos(1) = 0
    } else {
      const double e = std::exp(-c / sv);
      if (!(e < 1.0)) return T(0.0);  // min(1, e) = 1 → acos(1) = 0 (station at or beyond the tip/root)
      if (e == 0.0) return T(1.0);    // acos(0)·2/π = 1, constant (huge or infinite constant, e.g. zHub = 0)
      return T((2.0 / kPi) * acos(exp(-c / sabs)));
    }
  };
  if (o.tip_loss) F = F * part(lc.tip, parts ? &parts->tip : nullptr);
  if (o.hub_loss) F = F * part(lc.hub, parts ? &parts->hub : nullptr);
  return F;
}

// The element's Reynolds number at relative speed W [m/s] (AeroDyn GetReynoldsNumber, ≥ 0.001).
template <class T>
T reynolds(const BemStation& s, const T& W) {
  const T re = W * (s.chord / s.kin_visc);
  return valueOf(re) > 0.001 ? re : T(0.001);
}

template <class T>
SectionLoads<T> loadsWithCoefficients(const BemStation& s, const T& x, const T& y, const T& phi, const T& alpha,
                                      const T& W2, const T& W, const Coefficients<T>& c, double rho, bool moving);

/// Relative flow (x, y) = (Vx(1−a), Vy(1+a')) → φ, α, W, coefficients and loads (AeroDyn
/// ComputePhiWithInduction, SetInputs_for_UA, BEMT_CalcOutput with AIDrag = TIDrag = true, SetOutputsFromBEMT).
template <class T>
SectionLoads<T> loadsFromFlow(const BemStation& s, const T& x, const T& y, const T& theta, double rho) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const double xv = valueOf(x), yv = valueOf(y);
  const bool still = equal(yv, 0.0) && equal(xv, 0.0);
  const T phi = still ? T(0.0) : atan2T(x, y);
  const T alpha = phi - theta;
  const T W2 = x * x + y * y;
  const T W = valueOf(W2) > 0 ? T(sqrt(W2)) : T(0.0);
  const Coefficients<T> c = s.polar->re_tables.empty() ? evaluate(*s.polar, alpha)
                                                       : evaluate(*s.polar, alpha, reynolds(s, W));
  return loadsWithCoefficients<T>(s, x, y, phi, alpha, W2, W, c, rho, !still);
}

/// The loads of a relative flow (x, y) whose angle φ, angle of attack α, W² = x² + y², W and polar
/// coefficients are known; `moving` false: no flow direction (φ = 0, sin φ = 0, cos φ = 1).
template <class T>
SectionLoads<T> loadsWithCoefficients(const BemStation& s, const T& x, const T& y, const T& phi, const T& alpha,
                                      const T& W2, const T& W, const Coefficients<T>& c, double rho, bool moving) {
  SectionLoads<T> L;
  L.phi = phi;
  L.alpha = alpha;
  L.W = W;
  L.cl = c.cl;
  L.cd = c.cd;
  L.cm = c.cm;
  // sin φ = x/W, cos φ = y/W: the flow's own direction, without evaluating the angle's sine again.
  const bool direction = moving && valueOf(W2) > 0;
  const T sphi = direction ? T(x / L.W) : T(0.0), cphi = direction ? T(y / L.W) : T(1.0);
  L.cx = c.cl * cphi + c.cd * sphi;
  L.cy = c.cl * sphi - c.cd * cphi;
  const T q = 0.5 * rho * W2;
  L.fx = L.cx * q * s.chord;
  L.fy = -L.cy * q * s.chord;
  L.mz = c.cm * q * (s.chord * s.chord);
  return L;
}

void checkStation(const BemStation& s) {
  auto fail = [&](const std::string& why) { throw InputError("BEM station at r = " + num(s.r) + " m: " + why); };
  if (s.polar == nullptr) fail("no airfoil polar");
  if (!(s.r > 0) || !std::isfinite(s.r)) fail("the radius must be positive");
  if (!(s.chord > 0) || !std::isfinite(s.chord)) fail("the chord must be positive");
  if (s.blades < 1) fail("the number of blades must be at least 1");
  if (!std::isfinite(s.theta) || !std::isfinite(s.z) || !std::isfinite(s.hub_radius) || !std::isfinite(s.tip_radius))
    fail("non-finite geometry");
  if (!(s.tip_radius > 0)) fail("the tip radius must be positive");
}

/// AeroDyn GetSolveRegionOrdering: the three brackets [lower, upper] in the order they are tried.
std::array<std::array<double, 2>, 3> solveRegions(double Vx, double phiIn) {
  const double e = kEps2, h = kPi / 2, q = kPi / 4;
  const bool small = phiIn < q && phiIn > -q;
  if (Vx > 0) {
    std::array<double, 2> b2{-q, -e}, b3{h + e, kPi - e};
    return {{{e, h - e}, small ? b2 : b3, small ? b3 : b2}};
  }
  std::array<double, 2> b2{q, e}, b3{-h - e, -kPi + e};
  return {{{-e, -h + e}, small ? b2 : b3, small ? b3 : b2}};
}

}  // namespace

double tipLossConstant(const BemStation& s) {
  const double z = stationZ(s);
  return s.blades * (s.tip_radius - z) / (2.0 * z);
}

bool hasFixedInductions(const BemStation& s, const BemOptions& o) { return stationConstants(s, o).fixed; }

double hubLossConstant(const BemStation& s) {
  if (!(s.hub_radius > 0)) return std::numeric_limits<double>::infinity();  // Fortran: x/0 = +Inf → F_hub = 1
  const double z = stationZ(s);
  return s.blades * (z - s.hub_radius) / (2.0 * s.hub_radius);
}

namespace {

/// sin and cos of an angle, and of angles near it by the angle-sum formulas: the root search's
/// evaluations after its first lie within a few 1e-3 rad of it, where sin δ and cos δ are their
/// Taylor polynomials to below round-off (libm's sincos was 6 % of an aeroelastic start-up).
struct SineCosine {
  double angle, sin, cos;
  explicit SineCosine(double a) : angle(a) { ::sincos(a, &sin, &cos); }  // glibc: both in one call
  SineCosine(double a, double s, double c) : angle(a), sin(s), cos(c) {}
  /// The pair at angle a: by rotation from this one for |a − angle| ≤ 0.01 rad (the polynomials'
  /// remainders δ⁹/9! and δ⁸/8! below 3e-24), else evaluated.
  SineCosine at(double a) const {
    const double d = a - angle;
    if (!(std::abs(d) <= 0.01)) return SineCosine(a);
    const double d2 = d * d;
    // Products with the reciprocals (constants), not divisions: |δ| ≤ 0.01, so their rounding is
    // far below that of the result.
    constexpr double k6 = 1.0 / 6, k20 = 1.0 / 20, k42 = 1.0 / 42, k12 = 1.0 / 12, k30 = 1.0 / 30;
    const double sd = d * (1.0 - d2 * k6 * (1.0 - d2 * k20 * (1.0 - d2 * k42)));
    const double cd = 1.0 - 0.5 * d2 * (1.0 - d2 * k12 * (1.0 - d2 * k30));
    return SineCosine(a, sin * cd + cos * sd, cos * cd - sin * sd);
  }
};

// inductions() written into r: the root search keeps its last evaluation in place, where a returned
// copy was read back wide from the callee's narrow stores (a stalled store forwarding per evaluation).
template <class T>
void inductionsTo(Induction<T>& r, const BemStation& s, const StationConstants& lc, const T& phi, const T& Vx,
                  const T& Vy, const T& theta, const BemOptions& o, const T* radius, const SineCosine* near = nullptr,
                  LossParts* losses = nullptr) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  r = Induction<T>{T(0.0), T(0.0), T(1.0), T(0.0), T(0.0), T(0.0), {T(0.0), T(0.0), T(0.0)}, true, false};
  const double phiv = valueOf(phi), vxv = valueOf(Vx), vyv = valueOf(Vy);
  // Special cases of BEMTU_InductionWithResidual, in its order.
  if (lc.fixed) {
    r.a = T(1.0);
    r.fixed = true;
    return;
  }
  if (equal(phiv, 0.0) || velocityIsZero(vxv) || velocityIsZero(vyv)) {
    r.fixed = true;
    return;
  }
  const T alpha = phi - theta;  // computeAirfoilOperatingAOA, BEMMod_2D
  const Coefficients<T> c = s.polar->re_tables.empty()
                                ? evaluate(*s.polar, alpha)
                                : evaluate(*s.polar, alpha, reynolds(s, T(sqrt(Vx * Vx + Vy * Vy))));
  r.coef = c;
  T sphi, cphi;
  if constexpr (std::is_same_v<T, double>) {
    const SineCosine sc = near ? near->at(phi) : SineCosine(phi);
    sphi = sc.sin;
    cphi = sc.cos;
  } else {
    sphi = sin(phi);
    cphi = cos(phi);
  }
  // Transform_ClCd_to_CxCy honouring AIDrag / TIDrag (only for the inductions).
  const T cx = o.ai_drag ? T(c.cl * cphi + c.cd * sphi) : T(c.cl * cphi);
  const T cy = o.ti_drag ? T(c.cl * sphi - c.cd * cphi) : T(c.cl * sphi);
  T F = lossFactor(lc, sphi, o, losses);
  if (valueOf(F) < kMinF) F = T(kMinF);
  r.F = F;

  // inductionFactors0 (Ning 2014, with Buhl 2005 for the high-thrust momentum state).
  // Local solidity; with `radius` it follows the deflected geometry in T.
  const T sigma = radius ? T(s.blades * s.chord / (2.0 * kPi) / *radius) : T(lc.sigma);
  const T k = sigma * cx / (4.0 * F * sphi * sphi);
  const double kv = valueOf(k);
  const bool momentum = (phiv > 0 && vxv >= 0) || (phiv < 0 && vxv < 0);
  T a(0.0);
  bool plain = false;  // a = k/(1 + k): then 1/(1 − a) = 1 + k
  if (momentum) {
    if (kv <= 2.0 / 3.0) {  // momentum state, a ≤ 0.4
      if (equal(kv, -1.0)) a = T(-fsign(kInductionLimit, 1.0 + kv));
      else a = k / (1.0 + k), plain = true;
      if (kv < -1.0) r.valid = false;  // equivalent to a > 1: no momentum-region solution
    } else {                           // Buhl 2005 empirical (Glauert) correction for 0.4 < a < 1, with the loss factor
      const T temp = 2.0 * F * k;
      const T g1 = temp - (10.0 / 9.0 - F);
      const T g2 = temp - (4.0 / 3.0 - F) * F;
      const T g3 = temp - (25.0 / 9.0 - 2.0 * F);
      if (std::abs(valueOf(g3)) < 1e-6) a = 1.0 - 0.5 / sqrt(g2);  // avoid the singularity
      else a = (g1 - sqrt(absT(g2))) / g3;
    }
  } else {  // propeller brake region
    if (equal(kv, 1.0)) {
      r.valid = false;
      a = T(kInductionLimit);
    } else {
      a = k / (k - 1.0);
    }
    if (kv <= 1.0) r.valid = false;  // equivalent to a < 1
  }

  T ap(0.0), kp(0.0);
  if (o.tan_ind) {  // getTangentialInduction with kpCorrectionFactor = H = 1, no momentum correction
    if (equal(valueOf(cphi), 0.0)) {
      ap = T(-1.0);
      kp = T(fsign(kInductionLimit, valueOf(cy) * valueOf(sphi)) * fsign(1.0, vxv));
    } else {
      kp = sigma * cy / (4.0 * F * sphi * cphi);
      if (vxv < 0) kp = -kp;
      const double kpv = valueOf(kp);
      if (equal(kpv, 1.0)) ap = T(fsign(kInductionLimit, 1.0 - kpv));
      else ap = kp / (1.0 - kp);
    }
  }

  // Residual (Ning 2014 eq. for the momentum and propeller-brake regions), λ_r = Vy/Vx: cos φ/λ_r
  // formed as cos φ · Vx/Vy, and sin φ/(1 − a) as sin φ (1 + k) where a = k/(1 + k) — the same
  // values to round-off, with two divisions fewer on the chain from φ to R.
  const T vratio = Vx / Vy;
  const T tangential = cphi * vratio * (1.0 - kp);
  T R;
  if (momentum) {
    if (plain) R = sphi * (1.0 + k) - tangential;
    else if (equal(valueOf(a), 1.0)) R = -tangential;
    else R = sphi / (1.0 - a) - tangential;
  } else {
    R = sphi * (1.0 - k) - tangential;
  }
  r.a = a;
  r.ap = ap;
  r.k = k;
  r.kp = kp;
  r.residual = R;
}

}  // namespace

template <class T>
Induction<T> inductions(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const T& theta,
                        const BemOptions& o, const T* radius) {
  Induction<T> r;
  inductionsTo(r, s, stationConstants(s, o), phi, Vx, Vy, theta, o, radius);
  return r;
}

template <class T>
Induction<T> inductions(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const BemOptions& o) {
  return inductions<T>(s, phi, Vx, Vy, T(s.theta), o);
}

template <class T>
T bemResidual(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const T& theta, const BemOptions& o,
              const T* radius) {
  return inductions<T>(s, phi, Vx, Vy, theta, o, radius).residual;
}

template <class T>
T bemResidual(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const BemOptions& o) {
  return inductions<T>(s, phi, Vx, Vy, T(s.theta), o).residual;
}

namespace {

struct SecantRoot {
  double x = 0, fx = 0;
  bool converged = false;
};

// Secant steps on from the pair (x0, f0), (x1, f1) while each next point is inside(x); every point
// is shown to seen(x, f). Converged as brent() stops: |f| < ftol, or a step below xtol. `slope`
// receives the secant slope of the last pair.
template <class F, class Inside, class Seen>
SecantRoot secantSteps(F& f, double x0, double f0, double x1, double f1, double ftol, double xtol, double& slope,
                       int& evals, Inside inside, Seen seen) {
  for (int it = 0; it < 6 && f1 != f0; ++it) {
    slope = (f1 - f0) / (x1 - x0);
    const double x2 = x1 - f1 / slope;
    if (!inside(x2)) break;
    const double f2 = f(x2);
    ++evals;
    if (f2 != f1) slope = (f2 - f1) / (x2 - x1);
    if (std::abs(f2) < ftol || std::abs(x2 - x1) <= 2.0 * DBL_EPSILON * std::abs(x2) + xtol) return {x2, f2, true};
    seen(x2, f2);
    x0 = x1, f0 = f1, x1 = x2, f1 = f2;
  }
  return {};
}

// A root of f in [a, b] (fa, fb of opposite signs) from x0 inside, by secant steps that keep a
// bracket and fall back to Brent on it when a step leaves it or stalls. Stops as brent() does.
// `slope`: f' near x0 for the first step (0: a small step measures it); receives the last secant slope.
template <class F>
BrentResult secantFrom(F&& f, double a, double b, double fa, double fb, double x0, double ftol, double xtol, int maxit,
                       double& slope) {
  int evals = 0;
  auto shrink = [&](double x, double fx) {
    if ((fx > 0) == (fa > 0)) a = x, fa = fx;
    else b = x, fb = fx;
  };
  const double f0 = f(x0);
  ++evals;
  if (std::abs(f0) < ftol) return {x0, f0, evals, true};
  shrink(x0, f0);
  // The second point: a Newton step with the neighbouring solve's slope, or else a small step towards
  // the root side, so that the slope is the local one.
  double x1 = std::isfinite(slope) && slope != 0.0 ? x0 - f0 / slope : std::nan("");
  if (!(x1 > a && x1 < b)) {
    const double h = std::max(1e-7, 1e-7 * std::abs(x0));
    x1 = (f0 > 0) == (fa > 0) ? x0 + h : x0 - h;
  }
  if (!(x1 > a && x1 < b)) x1 = 0.5 * (a + b);
  const double f1 = f(x1);
  ++evals;
  slope = f1 != f0 ? (f1 - f0) / (x1 - x0) : 0.0;
  if (std::abs(f1) < ftol) return {x1, f1, evals, true};
  shrink(x1, f1);
  const SecantRoot r = secantSteps(
      f, x0, f0, x1, f1, ftol, xtol, slope, evals, [&](double x) { return x > a && x < b; }, shrink);
  if (r.converged) return {r.x, r.fx, evals, true};
  BrentResult br = brent(f, a, b, fa, fb, ftol, xtol, maxit);
  br.evals += evals;
  return br;
}

struct UnbracketedRoot {
  double x = 0;
  int evals = 0;
  bool converged = false;
};

// Secant steps from x0 that must stay inside (a, b), with no bracket known: the first step is a
// Newton step with `slope` (if finite and non-zero), else a small step; converged as secantFrom.
// `slope` receives the last secant slope. Not converged: a step left (a, b) or stalled.
template <class F>
UnbracketedRoot secantInside(F&& f, double a, double b, double x0, double ftol, double xtol, double& slope) {
  UnbracketedRoot r;
  const double f0 = f(x0);
  ++r.evals;
  if (std::abs(f0) < ftol) return UnbracketedRoot{x0, r.evals, true};
  const double x1 = std::isfinite(slope) && slope != 0.0 ? x0 - f0 / slope : x0 + std::max(1e-7, 1e-7 * std::abs(x0));
  if (!(x1 > a && x1 < b)) return r;
  const double f1 = f(x1);
  ++r.evals;
  if (f1 != f0) slope = (f1 - f0) / (x1 - x0);
  if (std::abs(f1) < ftol) return UnbracketedRoot{x1, r.evals, true};
  const SecantRoot s = secantSteps(
      f, x0, f0, x1, f1, ftol, xtol, slope, r.evals, [&](double x) { return x > a && x < b; }, [](double, double) {});
  return s.converged ? UnbracketedRoot{s.x, r.evals, true} : r;
}

// AeroDyn's search over its brackets in order (FindTestRegion; Brent, or secant steps from a hint
// inside the bracket), when no secant steps from a hint found a valid root in the first: returns the
// root (setting out.bracket, out.slope, out.iterations), or the geometric angle with out.valid false,
// or throws listing what each bracket gave. Apart from the hot path: the record of the brackets tried
// is formed only here.
template <class RFn>
[[gnu::noinline]] double searchBrackets(RFn& R, const BemStation& s, double Vx, double Vy, const BemOptions& o,
                                        const std::array<std::array<double, 2>, 3>& regions,
                                        std::optional<double> phi_hint, double slope_hint, InflowRoot& out) {
  // What each bracket gave, formatted only for the error message: building the text on every
  // solve cost a fifth of an aeroelastic Campbell sweep.
  struct Tried {
    double lo = 0, hi = 0, f1 = 0, f2 = 0, root = 0, k = 0;
    enum class Outcome { NoSignChange, InvalidRoot, Other } outcome = Outcome::Other;
  };
  std::array<Tried, 3> tried{};
  int ntried = 0;
  bool found = false;
  double phi = 0.0;
  for (int i = 0; i < 3 && !found; ++i) {
    const double lo = regions[i][0], hi = regions[i][1];
    const Induction<double> il = R(lo);  // copies: R keeps only its last evaluation
    const Induction<double> ih = R(hi);
    out.iterations += 2;
    const double f1 = il.residual, f2 = ih.residual;
    Tried& t = tried[static_cast<std::size_t>(ntried++)];
    t.lo = lo;
    t.hi = hi;
    t.f1 = f1;
    t.f2 = f2;
    // FindTestRegion
    if (equal(f1, 0.0) && equal(f2, 0.0) && il.valid && ih.valid) {
      phi = lo > 0 ? lo : hi;
      found = true;
    } else if (std::abs(f1) < o.tolerance && ((std::abs(f2) < std::abs(f1) && ih.valid) || il.valid)) {
      phi = (std::abs(f2) < std::abs(f1) && ih.valid) ? hi : lo;
      found = true;
    } else if (std::abs(f2) < o.tolerance && ih.valid) {
      phi = hi;
      found = true;
    } else if ((f1 >= 0) != (f2 >= 0)) {
      auto Rp = [&](double p) { return R(p).residual; };
      const bool up = lo < hi;
      const bool from_hint = phi_hint && *phi_hint > std::min(lo, hi) && *phi_hint < std::max(lo, hi);
      double slope = slope_hint;
      const BrentResult b = from_hint ? secantFrom(Rp, up ? lo : hi, up ? hi : lo, up ? f1 : f2, up ? f2 : f1,
                                                   *phi_hint, o.tolerance, o.phi_tolerance, o.max_iter, slope)
                                      : brent(Rp, lo, hi, f1, f2, o.tolerance, o.phi_tolerance, o.max_iter);
      out.slope = from_hint ? slope : 0.0;
      out.iterations += b.evals;
      if (!b.converged)
        throw ComputeError("BEM at r = " + num(s.r) + " m, Vx = " + num(Vx) + " m/s, Vy = " + num(Vy) +
                           " m/s, theta = " + deg(s.theta) + " deg: the root finder did not converge in " +
                           std::to_string(o.max_iter) + " iterations in [" + deg(lo) + ", " + deg(hi) +
                           "] deg (last phi = " + deg(b.x) + " deg, R = " + num(b.fx) + ")");
      const Induction<double>& ib = R(b.x);
      if (ib.valid) {
        phi = b.x;
        found = true;
      } else {
        t.outcome = Tried::Outcome::InvalidRoot;
        t.root = b.x;
        t.k = ib.k;
      }
    } else {
      t.outcome = Tried::Outcome::NoSignChange;
    }
    if (found) out.bracket = i;
  }
  if (!found) {
    const double geo = std::atan2(Vx, Vy);
    if (!o.geometric_fallback) {
      std::string text;
      for (int i = 0; i < ntried; ++i) {
        const Tried& t = tried[static_cast<std::size_t>(i)];
        if (i > 0) text += "; ";
        text += "[" + deg(t.lo) + ", " + deg(t.hi) + "] deg: R = " + num(t.f1) + ", " + num(t.f2);
        if (t.outcome == Tried::Outcome::InvalidRoot)
          text += ": root at " + deg(t.root) + " deg is not a valid BEM solution (k = " + num(t.k) + ")";
        else if (t.outcome == Tried::Outcome::NoSignChange) text += ": no sign change";
      }
      throw ComputeError("no valid BEM inflow angle at r = " + num(s.r) + " m, Vx = " + num(Vx) +
                         " m/s, Vy = " + num(Vy) + " m/s, theta = " + deg(s.theta) + " deg; brackets tried: " + text +
                         "; geometric phi = " + deg(geo) + " deg");
    }
    phi = geo;
    out.valid = false;
  }
  return phi;
}

}  // namespace

InflowRoot findInflowRoot(const BemStation& s, double Vx, double Vy, const BemOptions& o,
                          std::optional<double> phi_hint, double slope_hint) {
  checkStation(s);
  if (!std::isfinite(Vx) || !std::isfinite(Vy))
    throw ComputeError("BEM at r = " + num(s.r) + " m: non-finite velocity (Vx = " + num(Vx) + " m/s, Vy = " + num(Vy) +
                       " m/s)");
  InflowRoot out;
  double phi = 0.0;
  // The root finder's last point is evaluated again for its validity and its inductions: keep it.
  double last_phi = std::numeric_limits<double>::quiet_NaN();
  Induction<double>& last = out.at;
  const StationConstants lc = stationConstants(s, o);
  std::optional<SineCosine> first;  // sin, cos at the search's first point; the later ones rotate from it
  LossParts losses;                 // Prandtl's parts likewise, by their Taylor polynomials
  auto R = [&](double p) -> const Induction<double>& {
    if (p != last_phi) {
      if (!first) first.emplace(p);
      inductionsTo<double>(last, s, lc, p, Vx, Vy, s.theta, o, nullptr, &*first, &losses);
      last_phi = p;
    }
    return last;
  };

  if (velocityIsZero(Vx)) {  // BEMT_UnCoupledSolve special cases
    phi = 0.0;
  } else if (velocityIsZero(Vy)) {
    phi = Vx > 0 ? kPi / 2 : -kPi / 2;
  } else {
    const auto regions = solveRegions(Vx, o.phi_guess);
    bool found = false;
    // A hint inside the first bracket (the normal operating state, a warm Newton iterate) starts
    // secant steps before the bracket's ends are evaluated: a valid root inside it ends the search in
    // two or three residuals instead of four or five. Where that bracket holds one root, this is the
    // root the bracketed search finds; steps that leave the bracket or stall fall back to it.
    // (A bracket's ends are in AeroDyn's order: lower > upper for Vx < 0.)
    // Not with the in-plane flow against the rotation (Vx > 0, Vy < 0): there the first bracket can
    // hold a pair of valid roots between ends of one sign, which AeroDyn's search passes over (to the
    // geometric angle when no other bracket holds a valid root) and the secant steps would reach.
    // Where the bracket holds several roots and its ends change sign, the hint can still reach another
    // root than Brent's (docs/theory/aerodynamics.md).
    const double first_lo = std::min(regions[0][0], regions[0][1]), first_hi = std::max(regions[0][0], regions[0][1]);
    const bool reversed = Vx > 0 && Vy < 0;
    if (phi_hint && !reversed && *phi_hint > first_lo && *phi_hint < first_hi) {
      auto Rp = [&](double p) { return R(p).residual; };
      double slope = slope_hint;
      const UnbracketedRoot r = secantInside(Rp, first_lo, first_hi, *phi_hint, o.tolerance, o.phi_tolerance, slope);
      out.iterations += r.evals;
      if (r.converged && R(r.x).valid) {
        phi = r.x;
        found = true;
        out.bracket = 0;
        out.slope = slope;
      }
    }
    if (!found) phi = searchBrackets(R, s, Vx, Vy, o, regions, phi_hint, slope_hint, out);
  }

  out.phi = phi;
  // calculate_Inductions_from_BEMT: invalid → 0, else limitInductionFactors.
  const Induction<double>& ind = R(phi);
  if (out.valid && ind.valid) {
    out.a = std::clamp(ind.a, kMinA, kMaxA);
    out.ap = std::clamp(ind.ap, kMinAp, kMaxAp);
    out.flow_at_root = out.bracket == 0 && Vx > 0 && Vy > 0 && !ind.fixed && out.a == ind.a && out.ap == ind.ap &&
                       out.a < 1.0 && out.ap > -1.0 && s.polar->re_tables.empty();
  }
  return out;
}

BemSolution solveInflow(const BemStation& s, double Vx, double Vy, const BemOptions& o, std::optional<double> phi_hint,
                        double slope_hint) {
  const InflowRoot root = findInflowRoot(s, Vx, Vy, o, phi_hint, slope_hint);
  BemSolution out;
  out.phi = root.phi;
  out.a = root.a;
  out.ap = root.ap;
  out.F = root.at.F;
  out.k = root.at.k;
  out.kp = root.at.kp;
  out.residual = root.valid ? root.at.residual : 0.0;
  out.valid = root.valid;
  out.iterations = root.iterations;
  out.slope = root.slope;
  out.bracket = root.bracket;
  const SectionLoads<double> L = loadsFromFlow<double>(s, Vx * (1.0 - out.a), Vy * (1.0 + out.ap), s.theta, 1.0);
  out.phi_out = L.phi;
  out.alpha = L.alpha;
  out.W = L.W;
  out.cl = L.cl;
  out.cd = L.cd;
  out.cm = L.cm;
  out.ax_ind_vel = -Vx * out.a;
  out.tan_ind_vel = Vy * out.ap;
  return out;
}

template <class T>
T inflowAngle(const BemStation& s, const T& Vx, const T& Vy, const T& theta, double phi0, const BemOptions& o,
              const T* radius, double* slope) {
  // The slope depends on the values only: the AD passes at one root evaluate it once (`slope`).
  double Rphi = slope ? *slope : 0.0;
  bool fixed = Rphi == HUGE_VAL;  // kept for a φ-independent special case
  if (Rphi == 0.0) {
    ADChunk p(phi0);
    p.derivatives()[0] = 1.0;
    const Induction<ADChunk> d = inductions<ADChunk>(s, p, ADChunk(valueOf(Vx)), ADChunk(valueOf(Vy)),
                                                     ADChunk(valueOf(theta)), o);
    fixed = d.fixed;
    Rphi = d.residual.derivatives()[0];
  }
  if (fixed) {
    if (slope) *slope = HUGE_VAL;
    return T(phi0);
  }
  if (!(std::abs(Rphi) > 0) || !std::isfinite(Rphi))
    throw ComputeError("BEM at r = " + num(s.r) + " m, Vx = " + num(valueOf(Vx)) + " m/s, Vy = " + num(valueOf(Vy)) +
                       " m/s, theta = " + deg(valueOf(theta)) + " deg: dR/dphi = " + num(Rphi) +
                       " at phi = " + deg(phi0) + " deg, the inflow angle is not differentiable there");
  if (slope) *slope = Rphi;
  const T R = bemResidual<T>(s, T(phi0), Vx, Vy, theta, o, radius);
  return T(phi0 - R / Rphi);
}

/// AeroDyn's limitInductionFactors (BEMTUncoupled): a within [−1, 1.5], a' within [−1, 1]. A clamped
/// value is a constant: it has no derivative.
template <class T>
void limitInductions(T& a, T& ap) {
  if (valueOf(a) < kMinA) a = T(kMinA);
  if (valueOf(a) > kMaxA) a = T(kMaxA);
  if (valueOf(ap) < kMinAp) ap = T(kMinAp);
  if (valueOf(ap) > kMaxAp) ap = T(kMaxAp);
}

/// calculate_Inductions_from_BEMT: the inductions of an invalid solution are 0, the others limited.
template <class T>
std::pair<T, T> limitedInductions(const Induction<T>& ind) {
  if (!ind.valid) return {T(0.0), T(0.0)};
  T a = ind.a, ap = ind.ap;
  limitInductions<T>(a, ap);
  return {a, ap};
}

template <class T>
SectionLoads<T> frozenLoads(const BemStation& s, const T& Vx, const T& Vy, const T& theta, double ax_ind_vel,
                            double tan_ind_vel, double rho, const BemOptions& /*o*/) {
  // BEMT_CalcOutput_Inductions with UseFrozenWake: a = −AxInd_op/Vx, a' = TnInd_op/Vy (0 when Vx, Vy = 0),
  // hence Vx(1−a) = Vx + AxInd_op and Vy(1+a') = Vy + TnInd_op.
  const T x = equal(valueOf(Vx), 0.0) ? Vx : T(Vx + ax_ind_vel);
  const T y = equal(valueOf(Vy), 0.0) ? Vy : T(Vy + tan_ind_vel);
  return loadsFromFlow<T>(s, x, y, theta, rho);
}

template <class T>
SectionLoads<T> quasiSteadyLoads(const BemStation& s, const T& Vx, const T& Vy, const T& theta, double phi0, double rho,
                                 const BemOptions& o, const T* radius, const T* weight, double* slope) {
  const T phi = inflowAngle<T>(s, Vx, Vy, theta, phi0, o, radius, slope);
  const Induction<T> ind = inductions<T>(s, phi, Vx, Vy, theta, o, radius);
  auto [a, ap] = limitedInductions<T>(ind);
  if (weight) {
    a = a * *weight;
    ap = ap * *weight;
  }
  const T x = Vx * (1.0 - a), y = Vy * (1.0 + ap);
  return loadsFromFlow<T>(s, x, y, theta, rho);
}

template <class T>
InducedVelocity<T> quasiSteadyInducedVelocity(const BemStation& s, const T& Vx, const T& Vy, const T& theta,
                                              double phi0, const BemOptions& o, const T* radius, double* slope) {
  const T phi = inflowAngle<T>(s, Vx, Vy, theta, phi0, o, radius, slope);
  const Induction<T> ind = inductions<T>(s, phi, Vx, Vy, theta, o, radius);
  auto [a, ap] = limitedInductions<T>(ind);
  return {T(-Vx * a), T(Vy * ap), stationConstants(s, o).fixed};
}

template <class T>
std::pair<T, T> inducedFlow(const T& Vx, const T& Vy, const T& ax, const T& tn, const T* weight) {
  // calculate_Inductions_from_DBEMT (BEMT.f90): the inductions of the induced velocities, limited.
  T a = equal(valueOf(Vx), 0.0) ? T(0.0) : T(-ax / Vx);
  T ap = equal(valueOf(Vy), 0.0) ? T(0.0) : T(tn / Vy);
  limitInductions<T>(a, ap);
  if (weight) {  // check_turnOffBEMT, after DBEMT
    a = a * *weight;
    ap = ap * *weight;
  }
  return {T(Vx * (1.0 - a)), T(Vy * (1.0 + ap))};
}

template <class T>
SectionLoads<T> inducedVelocityLoads(const BemStation& s, const T& Vx, const T& Vy, const T& theta, const T& ax,
                                     const T& tn, double rho, const T* weight) {
  const auto [x, y] = inducedFlow<T>(Vx, Vy, ax, tn, weight);
  return loadsFromFlow<T>(s, x, y, theta, rho);
}

SectionLoads<double> loadsAtInduction(const BemStation& s, double Vx, double Vy, double theta, double a, double ap,
                                      double rho) {
  return loadsFromFlow<double>(s, Vx * (1.0 - a), Vy * (1.0 + ap), theta, rho);
}

SectionLoads<double> loadsAtRoot(const BemStation& s, double Vx, double Vy, double theta, double phi, double a,
                                 double ap, const Coefficients<double>& coef, double rho) {
  const double x = Vx * (1.0 - a), y = Vy * (1.0 + ap), W2 = x * x + y * y;
  return loadsWithCoefficients<double>(s, x, y, phi, phi - theta, W2, std::sqrt(W2), coef, rho, true);
}

template <class T>
T inductionWeight(const T& tsr) {
  // BEMT_lowerBoundTSR = 1, BEMT_upperBoundTSR = 2 (AeroDyn BEMTUncoupled).
  const double v = valueOf(tsr);
  if (v >= 2.0) return T(1.0);
  if (v <= 1.0) return T(0.0);
  using std::cos;
  return 0.5 * (1.0 - cos((tsr - 1.0) * kPi));
}

#define WHIRL_BEM_INSTANTIATE(T)                                                                                     \
  template Induction<T> inductions<T>(const BemStation&, const T&, const T&, const T&, const T&, const BemOptions&,  \
                                      const T*);                                                                     \
  template Induction<T> inductions<T>(const BemStation&, const T&, const T&, const T&, const BemOptions&);           \
  template T bemResidual<T>(const BemStation&, const T&, const T&, const T&, const T&, const BemOptions&, const T*); \
  template T bemResidual<T>(const BemStation&, const T&, const T&, const T&, const BemOptions&);                     \
  template T inflowAngle<T>(const BemStation&, const T&, const T&, const T&, double, const BemOptions&, const T*,    \
                            double*);                                                                                \
  template SectionLoads<T> frozenLoads<T>(const BemStation&, const T&, const T&, const T&, double, double, double,   \
                                          const BemOptions&);                                                        \
  template SectionLoads<T> quasiSteadyLoads<T>(const BemStation&, const T&, const T&, const T&, double, double,      \
                                               const BemOptions&, const T*, const T*, double*);                      \
  template T inductionWeight<T>(const T&);                                                                           \
  template InducedVelocity<T> quasiSteadyInducedVelocity<T>(const BemStation&, const T&, const T&, const T&, double, \
                                                            const BemOptions&, const T*, double*);                   \
  template std::pair<T, T> inducedFlow<T>(const T&, const T&, const T&, const T&, const T*);                         \
  template SectionLoads<T> inducedVelocityLoads<T>(const BemStation&, const T&, const T&, const T&, const T&,        \
                                                   const T&, double, const T*);

WHIRL_BEM_INSTANTIATE(double)
WHIRL_BEM_INSTANTIATE(ADChunk)
#undef WHIRL_BEM_INSTANTIATE

}  // namespace whirl::aero

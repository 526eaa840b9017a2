#include "src/aero/ua_coefficients.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl::aero {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

/// NWTC EqualRealNos (double): |a − b| ≤ max(|a + b|, 1) · 50 ε.
bool equalReal(double a, double b) {
  return std::abs(a - b) <= std::max(std::abs(a + b), 1.0) * 50.0 * std::numeric_limits<double>::epsilon();
}

/// NWTC InterpStp: linear interpolation, the end values outside.
double interpStp(double x, const std::vector<double>& xs, const std::vector<double>& ys) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto it = std::upper_bound(xs.begin(), xs.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - xs.begin()) - 1;
  return (ys[i + 1] - ys[i]) * (x - xs[i]) / (xs[i + 1] - xs[i]) + ys[i];
}

void fillDocumentedDefaults(const UaGiven& g, UaConstants& c) {
  // ReadAFfile / CalculateUACoeffs: the constants AeroDyn gives fixed defaults (HGM-family values
  // are those of every model but UA_Mod 8, which whirl does not model).
  c.eta_e = g.eta_e.value_or(1.0);
  c.k0 = g.k0.value_or(0.0);
  c.k1 = g.k1.value_or(0.0);
  c.k2 = g.k2.value_or(0.0);
  c.k3 = g.k3.value_or(0.0);
  c.k1_hat = g.k1_hat.value_or(0.0);
  c.S1 = g.S1.value_or(0.0);
  c.S2 = g.S2.value_or(0.0);
  c.S3 = g.S3.value_or(0.0);
  c.S4 = g.S4.value_or(0.0);
  c.T_f0 = g.T_f0.value_or(3.0);
  c.T_V0 = g.T_V0.value_or(6.0);
  c.T_p = g.T_p.value_or(1.7);
  c.T_VL = g.T_VL.value_or(11.0);
  c.b1 = g.b1.value_or(0.14);
  c.b2 = g.b2.value_or(0.53);
  c.b5 = g.b5.value_or(5.0);
  c.A1 = g.A1.value_or(0.3);
  c.A2 = g.A2.value_or(0.7);
  c.A5 = g.A5.value_or(1.0);
  c.x_cp_bar = g.x_cp_bar.value_or(0.2);
  c.filt_cutoff = g.filt_cutoff.value_or(0.5);
  c.St_sh = g.St_sh.value_or(0.19);
  c.ua_cutout = g.ua_cutout.value_or(45.0 * kDeg);
  c.ua_cutout_delta = g.ua_cutout_delta.value_or(5.0 * kDeg);
  c.ua_cutout_blend = std::max(0.0, std::abs(c.ua_cutout) - std::abs(c.ua_cutout_delta));
  c.alpha1 = g.alpha1;
  c.alpha2 = g.alpha2;
  c.Cn1 = g.Cn1;
  c.Cn2 = g.Cn2;
}

/// Rows of the table (0-based).
struct Rows {
  const std::vector<double>& alpha;
  const std::vector<double>& cl;
  const std::vector<double>& cd;
  const std::vector<double>& cm;
  std::size_t n() const { return alpha.size(); }
};

/// alphaUpper, alphaLower from the smoothed Cn slope (CalculateUACoeffs; 1-based indices there,
/// 0-based here). Also returns the segment limits of the ±20° range.
struct SlopeScan {
  std::vector<double> mid, cn_slope;  // per segment
  std::size_t low_limit = 0, high_limit = 0;
};

SlopeScan scanSlopes(const Rows& r, const std::vector<double>& cn, double limit) {
  const std::size_t ns = r.n() - 1;
  SlopeScan s;
  std::vector<double> raw(ns);
  s.mid.resize(ns);
  for (std::size_t k = 0; k < ns; ++k) {
    raw[k] = (cn[k + 1] - cn[k]) / (r.alpha[k + 1] - r.alpha[k]);
    s.mid[k] = 0.5 * (r.alpha[k + 1] + r.alpha[k]);
  }
  s.cn_slope = triweightSmoothing(s.mid, raw, 2.0 * kDeg);
  // iHighLimit = min(maxloc(alpha_ < L) + 1, ns), iLowLimit = max(minloc(alpha_ > −L) − 1, 1) (1-based).
  std::size_t hi = 0, lo = ns - 1;
  for (std::size_t k = 0; k < ns; ++k)
    if (s.mid[k] < limit) hi = k;
  for (std::size_t k = ns; k-- > 0;)
    if (s.mid[k] > -limit) lo = k;
  s.high_limit = std::min(hi + 1, ns - 1);
  s.low_limit = lo == 0 ? 0 : lo - 1;
  if (s.high_limit < s.low_limit + 3) s.high_limit = std::min(s.low_limit + 2, ns - 1);
  if (s.high_limit < s.low_limit + 3) s.low_limit = s.high_limit >= 2 ? s.high_limit - 2 : 0;
  return s;
}

/// alphaUpper (walk up from the minimum-drag segment) and alphaLower (walk down) as AeroDyn.
void linearRegion(const UaGiven& g, const SlopeScan& s, std::size_t i_cd_min, double alpha_cd_min, UaConstants& c) {
  const std::size_t ns = s.mid.size();
  const double slope_at_cd_min = interpStp(alpha_cd_min, s.mid, s.cn_slope);
  constexpr double kThreshold = 0.9;
  std::size_t i_high2 = s.high_limit;
  if (!g.alpha_upper) {
    std::size_t i_high = s.high_limit < i_cd_min ? ns - 1 : s.high_limit;
    double max_slope = slope_at_cd_min;
    i_high2 = i_cd_min;
    for (std::size_t k = i_cd_min; k <= i_high && k < ns; ++k) {
      i_high2 = k;
      if (s.cn_slope[k] > max_slope) max_slope = s.cn_slope[k];
      else if (s.cn_slope[k] < kThreshold * max_slope) break;
    }
    if (i_high2 == i_cd_min) {
      c.alpha_upper = alpha_cd_min;
    } else {
      i_high2 = std::min(i_high2 == 0 ? 0 : i_high2 - 1, ns - 1);
      c.alpha_upper = s.mid[i_high2];
    }
  } else {
    c.alpha_upper = *g.alpha_upper;
  }
  if (!g.alpha_lower) {
    double max_slope = slope_at_cd_min;
    std::size_t i_low = s.low_limit;
    const std::size_t i_high = std::min({i_high2, i_cd_min, ns - 1});
    if (i_high < i_low) i_low = 0;
    std::size_t i_low2 = i_high;
    for (std::size_t k = i_high + 1; k-- > i_low;) {
      i_low2 = k;
      if (s.cn_slope[k] > max_slope) max_slope = s.cn_slope[k];
      else if (s.cn_slope[k] < kThreshold * max_slope) break;
    }
    if (i_low2 == i_cd_min) {
      c.alpha_lower = alpha_cd_min;
    } else {
      i_low2 = std::min(i_low2 + 1, ns - 1);
      c.alpha_lower = s.mid[i_low2];
    }
  } else {
    c.alpha_lower = *g.alpha_lower;
  }
}

/// C_nalpha, C_lalpha, alpha0 by least squares on the rows inside the linear region less a margin.
void liftSlopes(const UaGiven& g, const Rows& r, const std::vector<double>& cn, const SlopeScan& s, UaConstants& c) {
  if (g.c_nalpha && g.c_lalpha && g.alpha0) {
    c.c_nalpha = *g.c_nalpha;
    c.c_lalpha = *g.c_lalpha;
    c.alpha0 = *g.alpha0;
    return;
  }
  const double margin = 0.2 * (c.alpha_upper - c.alpha_lower);
  std::size_t lo = s.low_limit;
  while (lo + 1 < s.high_limit && r.alpha[lo] < c.alpha_lower + margin) ++lo;
  std::size_t hi = s.high_limit;
  while (hi > lo + 1 && r.alpha[hi] > c.alpha_upper - margin) --hi;
  if (hi <= lo) {  // fewer than two rows: AeroDyn's Calculate_C_alpha gives ε slopes and alpha0 = 0
    c.c_nalpha = g.c_nalpha.value_or(std::numeric_limits<double>::epsilon());
    c.c_lalpha = g.c_lalpha.value_or(std::numeric_limits<double>::epsilon());
    c.alpha0 = g.alpha0.value_or(0.0);
    return;
  }
  const Eigen::Index m = static_cast<Eigen::Index>(hi - lo + 1);
  Eigen::MatrixXd a(m, 2);
  Eigen::MatrixXd b(m, 2);
  for (Eigen::Index k = 0; k < m; ++k) {
    const std::size_t row = lo + static_cast<std::size_t>(k);
    a(k, 0) = r.alpha[row];
    a(k, 1) = 1.0;
    b(k, 0) = cn[row];
    b(k, 1) = r.cl[row];
  }
  const Eigen::MatrixXd x = a.colPivHouseholderQr().solve(b);  // LAPACK gels in AeroDyn
  c.c_nalpha = g.c_nalpha.value_or(x(0, 0));
  c.c_lalpha = g.c_lalpha.value_or(x(0, 1));
  c.alpha0 = g.alpha0 ? *g.alpha0 : (equalReal(x(0, 0), 0.0) ? 0.0 : -x(1, 0) / x(0, 0));
}

/// ComputeUASeparationFunction_zero: f_st = 0 and Cl_fs = Cl beyond the first minimum of f_st on
/// each side of the linear region.
void separationZero(const Rows& r, const UaConstants& c, std::vector<double>& f, std::vector<double>& fs,
                    std::vector<double>& fa) {
  const std::size_t n = r.n();
  std::size_t i_temp = n, i_low = 0, i_high = n;
  for (std::size_t k = 0; k < n; ++k)
    if (r.alpha[k] < c.alpha_lower && (i_temp == n || f[k] < f[i_temp])) i_temp = k;
  for (std::size_t k = 0; k < n; ++k)
    if (i_temp < n && r.alpha[k] < c.alpha_lower && f[k] == f[i_temp]) i_low = k;
  for (std::size_t k = 0; k < n; ++k)
    if (r.alpha[k] > c.alpha_upper && (i_high == n || f[k] < f[i_high])) i_high = k;
  if (i_temp == n || i_high == n) return;  // no row beyond the linear region on one side
  const double a_up = r.alpha[i_high], a_lo = r.alpha[i_low];
  const double cn_up = fa[i_high], cn_lo = fa[i_low];
  // The wrap-around slope from the upper break (−2π) to the lower one; 0 when they coincide (a table of
  // three rows, −180°, 0, 180°), where AeroDyn divides by zero (the column is not used by UA_Mod 4 or 6).
  const double span = (a_up - 2 * kPi) - a_lo;
  const double rate = span != 0.0 ? (cn_up - cn_lo) / span : 0.0;
  for (std::size_t k = 0; k <= i_low; ++k) {
    fa[k] = (r.alpha[k] - a_lo) * rate + cn_lo;
    fs[k] = r.cl[k];
    f[k] = 0.0;
  }
  for (std::size_t k = i_high; k < n; ++k) {
    fa[k] = (r.alpha[k] - a_up) * rate + cn_up;
    fs[k] = r.cl[k];
    f[k] = 0.0;
  }
}

/// ComputeUASeparationFunction_onCl [Hansen, Gaunaa & Madsen 2004, eqs. 59–64].
void separationOnCl(const Rows& r, const UaConstants& c, std::vector<double>& f, std::vector<double>& fs,
                    std::vector<double>& fa) {
  const std::size_t n = r.n();
  f.assign(n, 0.0);
  fs = r.cl;
  fa.assign(n, 0.0);
  if (equalReal(c.c_lalpha, 0.0)) {
    separationZero(r, c, f, fs, fa);
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double cl_fa = c.c_lalpha * (r.alpha[k] - c.alpha0);
    fa[k] = cl_fa;
    if (equalReal(r.alpha[k], c.alpha0)) {
      f[k] = 1.0;
      fs[k] = r.cl[k] / 2.0;
      continue;
    }
    const double ratio = std::max(0.0, r.cl[k] / cl_fa);
    const double fk = (2.0 * std::sqrt(ratio) - 1.0) * (2.0 * std::sqrt(ratio) - 1.0);
    if (fk < 1.0) {
      f[k] = std::max(0.0, fk);
      fs[k] = (r.cl[k] - cl_fa * f[k]) / (1.0 - f[k]);
    } else {
      f[k] = 1.0;
      fs[k] = r.cl[k] / 2.0;
    }
  }
  separationZero(r, c, f, fs, fa);
  for (std::size_t k = 0; k < n; ++k) {  // "in harmony": Cl = f Cl_fa + (1 − f) Cl_fs on every row
    const double cl_inv = c.c_lalpha * (r.alpha[k] - c.alpha0);
    f[k] = equalReal(cl_inv, fs[k]) ? 1.0 : std::clamp((r.cl[k] - fs[k]) / (cl_inv - fs[k]), 0.0, 1.0);
  }
}

}  // namespace

std::vector<double> triweightSmoothing(const std::vector<double>& x, const std::vector<double>& f, double r) {
  const double radius = std::max(std::abs(r), std::numeric_limits<double>::epsilon());
  std::vector<double> out(x.size(), 0.0);
  for (std::size_t j = 0; j < x.size(); ++j) {
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = std::clamp((x[i] - x[j]) / radius, -1.0, 1.0);
      const double w = 1.0 - u * u;
      const double k = 35.0 / 32.0 * w * w * w;
      sum += k;
      out[j] += k * f[i];
    }
    if (sum > 0.0) out[j] /= sum;
  }
  return out;
}

UaTable uaTable(const UaGiven& g, const std::vector<double>& alpha, const std::vector<double>& cl,
                const std::vector<double>& cd, const std::vector<double>& cm, PolarInterp interp, int ua_mod,
                const std::string& source) {
  if (ua_mod == 5)
    throw InputError(source + ": UA_Mod 5 (separation function on Cn, AeroDyn's ComputeUA360_*) is not implemented");
  UaTable t;
  fillDocumentedDefaults(g, t.c);
  const Rows r{alpha, cl, cd, cm};
  const double limit = 20.0 * kDeg;
  std::size_t i_cd_min = r.n();
  double cd_max = -1e300, cl_max = -1e300;
  for (std::size_t k = 0; k < r.n(); ++k) {
    if (std::abs(alpha[k]) > limit) continue;
    if (i_cd_min == r.n() || cd[k] < cd[i_cd_min]) i_cd_min = k;
    cd_max = std::max(cd_max, cd[k]);
    cl_max = std::max(cl_max, cl[k]);
  }
  if (i_cd_min == r.n() || r.n() < 3)
    throw InputError(source + ": unsteady aerodynamics need table rows with |alpha| <= 20 deg (none found)");
  t.included = true;
  UaConstants& c = t.c;
  std::vector<double> f, fs, fa;
  t.cylinder = cd_max == cd[i_cd_min] || cl_max < 0.01;
  if (t.cylinder) {
    c.Cd0 = g.Cd0.value_or(cd[i_cd_min]);
    c.alpha0 = g.alpha0.value_or(0.0);
    c.c_nalpha = g.c_nalpha.value_or(0.0);
    c.c_lalpha = g.c_lalpha.value_or(0.0);
    c.Cm0 = g.Cm0.value_or(0.0);
    c.alpha1 = g.alpha1.value_or(10.0 * kDeg);
    c.alpha2 = g.alpha2.value_or(-10.0 * kDeg);
    c.Cn1 = g.Cn1.value_or(0.0);
    c.Cn2 = g.Cn2.value_or(0.0);
    c.alpha_lower = g.alpha_lower.value_or(-5.0 * kDeg);
    c.alpha_upper = g.alpha_upper.value_or(5.0 * kDeg);
  } else {
    c.Cd0 = g.Cd0.value_or(cd[i_cd_min]);
    std::vector<double> cn(r.n());
    for (std::size_t k = 0; k < r.n(); ++k) cn[k] = cl[k] * std::cos(alpha[k]) + (cd[k] - c.Cd0) * std::sin(alpha[k]);
    const SlopeScan s = scanSlopes(r, cn, limit);
    linearRegion(g, s, i_cd_min, alpha[i_cd_min], c);
    liftSlopes(g, r, cn, s, c);
    c.Cm0 = g.Cm0 ? *g.Cm0 : (cm.empty() ? 0.0 : interpStp(c.alpha0, alpha, cm));
  }
  separationOnCl(r, c, f, fs, fa);
  t.columns = makePolar("UA columns", alpha, std::move(f), std::move(fs), std::move(fa), interp, source);
  return t;
}

}  // namespace whirl::aero

#include "src/aero/polar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "src/base/error.hpp"
#include "src/base/scalar.hpp"

namespace whirl::aero {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kCoverTol = 1e-3;  // rad: how close the table's ends must be to ∓π

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

/// NWTC CubicLinSplineInitM: piecewise linear coefficients.
std::vector<std::array<double, 4>> linearCoefs(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<std::array<double, 4>> c(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) c[i] = {y[i], (y[i + 1] - y[i]) / (x[i + 1] - x[i]), 0.0, 0.0};
  return c;
}

/// NWTC CubicSplineInitM (NWTC_Num.f90), transcribed with 0-based indices: DelX[i] = h_i, Slope[i] = s_i for
/// i = 0..n−2; U, V the forward-eliminated diagonal and right-hand side of rows 0..n−2; back substitution
/// from M_{n−1} = 0 (ZHi) down to M_0 (ZLo). Row 0 is 2(h_0+h_1) M_0 + h_0 M_1 = 6(s_1 − s_0), as in the Fortran.
std::vector<std::array<double, 4>> nwtcCubicCoefs(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();  // n >= 3 (checked by the caller)
  std::vector<double> h(n - 1), s(n - 1), u(n - 1), v(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x[i + 1] - x[i];
    s[i] = (y[i + 1] - y[i]) / h[i];
  }
  u[0] = 2.0 * (h[1] + h[0]);
  v[0] = 6.0 * (s[1] - s[0]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    u[i] = 2.0 * (h[i - 1] + h[i]) - h[i - 1] * h[i - 1] / u[i - 1];
    v[i] = 6.0 * (s[i] - s[i - 1]) - h[i - 1] * v[i - 1] / u[i - 1];
  }
  std::vector<std::array<double, 4>> c(n - 1);
  double zhi = 0.0;
  for (std::size_t k = n - 1; k-- > 0;) {
    const double zlo = (v[k] - h[k] * zhi) / u[k];
    c[k] = {y[k], s[k] - h[k] * (zhi / 6.0 + zlo / 3.0), 0.5 * zlo, (zhi - zlo) / (6.0 * h[k])};
    zhi = zlo;
  }
  return c;
}

template <class T>
T poly(const std::array<double, 4>& c, const T& x) {
  return c[0] + x * (c[1] + x * (c[2] + x * c[3]));
}

}  // namespace

double wrapMPi2Pi(double a) {
  // Fortran MODULO(a, p) = a − floor(a/p)·p (result has the sign of p).
  const double twoPi = 2.0 * kPi;
  double m = a - std::floor(a / twoPi) * twoPi;
  if (m > kPi) m -= twoPi;
  return m;
}

Polar makePolar(std::string name, std::vector<double> alpha, std::vector<double> cl, std::vector<double> cd,
                std::vector<double> cm, PolarInterp interp, const std::string& source) {
  const std::string who = "airfoil '" + name + "': ";
  auto fail = [&](const std::string& reason) { throw InputError(where(source, 0, "", who + reason)); };
  const std::size_t n = alpha.size();
  if (n == 0) fail("the polar table is empty");
  if (cl.size() != n || cd.size() != n || cm.size() != n)
    fail("the columns have different lengths (alpha " + std::to_string(n) + ", cl " + std::to_string(cl.size()) +
         ", cd " + std::to_string(cd.size()) + ", cm " + std::to_string(cm.size()) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(alpha[i]) || !std::isfinite(cl[i]) || !std::isfinite(cd[i]) || !std::isfinite(cm[i]))
      fail("row " + std::to_string(i + 1) + " has a non-finite value");
    if (i > 0 && !(alpha[i] > alpha[i - 1]))
      fail("alpha must be strictly increasing: row " + std::to_string(i + 1) + " (" + fmt(alpha[i] * 180.0 / kPi) +
           " deg) follows " + fmt(alpha[i - 1] * 180.0 / kPi) + " deg");
  }
  if (alpha.front() > -kPi + kCoverTol || alpha.back() < kPi - kCoverTol)
    fail("the table must cover -180..180 deg (it spans " + fmt(alpha.front() * 180.0 / kPi) + ".." +
         fmt(alpha.back() * 180.0 / kPi) + " deg)");

  Polar p;
  p.name = std::move(name);
  p.interp = interp;
  // AeroDyn ReadAFfile: ConstData when NumAlf < 3 or all rows equal (EqualRealNos, ~1e-14 relative).
  auto eq = [](double a, double b) { return std::abs(a - b) <= std::max(std::abs(a + b), 1.0) * 50.0 * 2.22e-16; };
  p.constant = n < 3;
  if (!p.constant) {
    p.constant = true;
    for (std::size_t i = 0; i + 1 < n && p.constant; ++i)
      p.constant = eq(cl[i], cl[i + 1]) && eq(cd[i], cd[i + 1]) && eq(cm[i], cm[i + 1]);
  }
  if (!p.constant) {
    auto coefs = interp == PolarInterp::CubicSpline ? nwtcCubicCoefs : linearCoefs;
    p.ccl = coefs(alpha, cl);
    p.ccd = coefs(alpha, cd);
    p.ccm = coefs(alpha, cm);
  }
  p.alpha = std::move(alpha);
  p.cl = std::move(cl);
  p.cd = std::move(cd);
  p.cm = std::move(cm);
  return p;
}

template <class T>
Coefficients<T> evaluate(const Polar& p, const T& alpha) {
  if (p.constant) return {T(p.cl[0]), T(p.cd[0]), T(p.cm[0])};
  const double a0 = valueOf(alpha);
  const double aw = wrapMPi2Pi(a0);
  if (aw <= p.alpha.front()) return {T(p.cl.front()), T(p.cd.front()), T(p.cm.front())};
  if (aw >= p.alpha.back()) return {T(p.cl.back()), T(p.cd.back()), T(p.cm.back())};
  // LocateBin: alpha[i] <= aw < alpha[i+1].
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(p.alpha.begin(), p.alpha.end(), aw) -
                                                 p.alpha.begin()) -
                        1;
  const T x = alpha + ((aw - a0) - p.alpha[i]);  // wrapped alpha minus the knot; the shift is a constant
  return {poly(p.ccl[i], x), poly(p.ccd[i], x), poly(p.ccm[i], x)};
}

template Coefficients<double> evaluate<double>(const Polar&, const double&);
template Coefficients<ADChunk> evaluate<ADChunk>(const Polar&, const ADChunk&);

Polar reynoldsPolar(std::vector<Polar> tables, const std::vector<double>& re, ReynoldsInterp interp,
                    const std::vector<std::string>& sources) {
  if (tables.empty() || tables.size() != re.size() || sources.size() != re.size())
    throw InputError("airfoil tables on the Reynolds number: " + std::to_string(tables.size()) + " tables, " +
                     std::to_string(re.size()) + " Reynolds numbers");
  for (std::size_t k = 0; k < re.size(); ++k) {
    if (!(re[k] > 0) || !std::isfinite(re[k]))
      throw InputError(sources[k] + ": Re: the Reynolds number of a table interpolated on it must be positive (is " +
                       fmt(re[k]) + ")");
    if (k > 0 && !(re[k] > re[k - 1]))
      throw InputError(sources[k] + ": Re: the tables' Reynolds numbers must increase strictly (" + fmt(re[k]) +
                       " follows " + fmt(re[k - 1]) + "), as AeroDyn requires for interpolating on them");
  }
  Polar p = tables.front();
  if (interp == ReynoldsInterp::None || tables.size() == 1) return p;
  p.re_log = interp == ReynoldsInterp::Log;
  for (double r : re) p.re_axis.push_back(p.re_log ? std::log(r) : r);
  p.re_tables = std::move(tables);
  return p;
}

template <class T>
Coefficients<T> evaluate(const Polar& p, const T& alpha, const T& re) {
  if (p.re_tables.empty()) return evaluate(p, alpha);
  using std::log;
  const T x = p.re_log ? T(log(re)) : re;
  const double xv = valueOf(x);
  const std::vector<double>& ax = p.re_axis;
  if (!(xv > ax.front())) return evaluate(p.re_tables.front(), alpha);  // AeroDyn: <= the first (and NaN)
  if (xv >= ax.back()) return evaluate(p.re_tables.back(), alpha);
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(ax.begin(), ax.end(), xv) - ax.begin()) - 1;
  const T w = (x - ax[i]) / (ax[i + 1] - ax[i]);
  const Coefficients<T> lo = evaluate(p.re_tables[i], alpha), hi = evaluate(p.re_tables[i + 1], alpha);
  return {T(lo.cl + w * (hi.cl - lo.cl)), T(lo.cd + w * (hi.cd - lo.cd)), T(lo.cm + w * (hi.cm - lo.cm))};
}

template Coefficients<double> evaluate<double>(const Polar&, const double&, const double&);
template Coefficients<ADChunk> evaluate<ADChunk>(const Polar&, const ADChunk&, const ADChunk&);

}  // namespace whirl::aero

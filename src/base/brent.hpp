#pragma once
/// \file
/// Brent's method for a scalar root in a bracket (Brent 1973, "Algorithms for Minimization without
/// Derivatives", ch. 4): the solver of every bracketed one-variable problem in whirl (BEM inflow angle,
/// trim of rotor speed and pitch).
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace whirl {

struct BrentResult {
  double x, fx;
  int evals;
  bool converged;
};

/// Brent's method (Brent 1973, "Algorithms for Minimization without Derivatives", ch. 4) on a bracket [a, b]
/// whose end residuals fa, fb differ in sign. Stops when |f| < ftol or the bracket half-width falls below
/// 2 ε |b| + xtol.
template <class F>
BrentResult brent(F&& f, double a, double b, double fa, double fb, double ftol, double xtol, int maxit) {
  double c = a, fc = fa, d = b - a, e = d;
  int evals = 0;
  for (int it = 0; it < maxit; ++it) {
    if ((fb > 0) == (fc > 0)) {  // b and c on the same side: the bracket is [a, b]
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {  // keep b the best guess
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * DBL_EPSILON * std::abs(b) + xtol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return {b, fb, evals, true};
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {  // secant
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {  // inverse quadratic interpolation
        const double qq = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0) q = -q;
      else p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {  // interpolation rejected: bisect
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
    ++evals;
    if (std::abs(fb) < ftol) return {b, fb, evals, true};
  }
  return {b, fb, evals, false};
}

}  // namespace whirl

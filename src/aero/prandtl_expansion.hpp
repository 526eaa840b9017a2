#pragma once
/// \file
/// Prandtl's tip or hub loss part near a point, for the evaluations of one BEM root search.
#include <cmath>
#include <numbers>

namespace whirl::aero {

/// One Prandtl part G(f) = (2/π) acos(e^(−f)) of a root search: evaluated at a point f0 of the search,
/// and at its later points f = f0 + Δ by its Taylor polynomial of degree 3 where that is exact to
/// below round-off (else evaluated, and expanded about that point). With u = e^(−f0), w = √(1 − u²):
/// G′ = (2/π) u/w, G″ = −(2/π) u/w³, G‴ = (2/π) u (w² + 3u²)/w⁵, and the next term,
/// −(2/π) u (w⁴ + 12u²w² + 15u⁴)/w⁷ · Δ⁴/24, bounds the remainder while |Δ| ≤ 1e-3 w² (the derivatives
/// change by less than 0.3 % over the step): the polynomial is taken when that bound is below 1e-18.
/// Saves exp and acos (a tenth of an aeroelastic start-up) at most evaluations of a search.
struct PrandtlExpansion {
  bool ready = false;
  double f0 = 0, g0 = 0, d1 = 0, d2 = 0, d3 = 0, d4 = 0, reach = 0;
  /// G(f) for 0 ≤ f < 38 (0 where e^(−f) rounds to 1, as AeroDyn's min(1, ·)).
  double at(double f) {
    if (ready) {
      const double d = f - f0, dd = d * d;
      if (std::abs(d) <= reach && std::abs(d4) * (dd * dd) <= 24e-18)
        return g0 + d * (d1 + d * (0.5 * d2 + d * (1.0 / 6) * d3));
    }
    const double u = std::exp(-f);
    if (!(u < 1.0)) return 0.0;
    const double g = (2.0 / std::numbers::pi) * std::acos(u);
    {  // the expansion about the latest point evaluated: the search's points close in on its root
      const double u2 = u * u, w2 = 1.0 - u2, w = std::sqrt(w2), iw = 1.0 / w, iw2 = iw * iw;
      ready = true;
      f0 = f;
      g0 = g;
      d1 = (2.0 / std::numbers::pi) * u * iw;
      d2 = -d1 * iw2;
      d3 = (2.0 / std::numbers::pi) * u * (w2 + 3.0 * u2) * iw2 * iw2 * iw;
      d4 = -(2.0 / std::numbers::pi) * u * (w2 * w2 + 12.0 * u2 * w2 + 15.0 * u2 * u2) * iw2 * iw2 * iw2 * iw;
      reach = 1e-3 * w2;
    }
    return g;
  }
};

}  // namespace whirl::aero

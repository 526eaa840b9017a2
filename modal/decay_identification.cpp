#include "modal/decay_identification.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "src/base/error.hpp"

namespace whirl {
namespace {

// Slope of the least-squares line through (a_k, b_k).
double slope(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double sa = 0, sb = 0, saa = 0, sab = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    sa += a[k];
    sb += b[k];
    saa += a[k] * a[k];
    sab += a[k] * b[k];
  }
  return (n * sab - sa * sb) / (n * saa - sa * sa);
}

}  // namespace

IdentifiedDecay identifyDecay(const std::vector<double>& t, const std::vector<double>& x, double center) {
  std::vector<size_t> after;  // sample index just after each crossing
  std::vector<double> crossings, index;
  for (size_t k = 1; k < x.size(); ++k) {
    const double a = x[k - 1] - center, b = x[k] - center;
    if ((a < 0 && b >= 0) || (a > 0 && b <= 0)) {
      crossings.push_back(t[k - 1] + (t[k] - t[k - 1]) * a / (a - b));
      index.push_back(static_cast<double>(crossings.size() - 1));
      after.push_back(k);
    }
  }
  if (crossings.size() < 4)
    throw ComputeError("decay identification: fewer than 4 zero crossings (" + std::to_string(crossings.size()) +
                       "): simulate longer, or the signal does not oscillate");
  IdentifiedDecay d;
  d.half_periods = static_cast<int>(crossings.size()) - 1;
  const double half_period = slope(index, crossings);
  d.damped_freq_hz = 1 / (2 * half_period);
  // One extremum between each pair of crossings, refined by the parabola through its neighbours.
  std::vector<double> tp, lp;
  for (size_t c = 0; c + 1 < after.size(); ++c) {
    size_t best = after[c];
    for (size_t k = after[c]; k < after[c + 1]; ++k)
      if (std::abs(x[k] - center) > std::abs(x[best] - center)) best = k;
    double tk = t[best], xk = x[best] - center;
    if (best > 0 && best + 1 < x.size()) {
      const double y0 = x[best - 1] - center, y1 = xk, y2 = x[best + 1] - center, h = t[best + 1] - t[best];
      const double den = y0 - 2 * y1 + y2;
      if (den != 0 && std::abs(t[best] - t[best - 1] - h) < 1e-9 * h) {
        const double s = 0.5 * (y0 - y2) / den;  // offset of the vertex in samples, |s| ≤ 1/2
        tk += s * h;
        xk = y1 - 0.25 * (y0 - y2) * s;
      }
    }
    if (xk != 0) {
      tp.push_back(tk);
      lp.push_back(std::log(std::abs(xk)));
    }
  }
  const double sigma = tp.size() >= 2 ? -slope(tp, lp) : 0.0;
  const double w = 2 * std::numbers::pi * d.damped_freq_hz;
  d.damping_ratio = sigma / std::hypot(sigma, w);
  d.freq_hz = d.damped_freq_hz / std::sqrt(1 - d.damping_ratio * d.damping_ratio);
  return d;
}

}  // namespace whirl

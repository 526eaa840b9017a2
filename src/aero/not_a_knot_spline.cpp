#include "src/aero/not_a_knot_spline.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace whirl::aero {

// Second-derivative form (M_i = s''(x_i)): the interior rows are the C² continuity conditions
//   h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (Δ_i − Δ_{i−1}),  Δ_i = (y_{i+1} − y_i)/h_i,
// the two end rows the not-a-knot conditions (s''' continuous at x₁ and x_{n−2}):
//   (M₁ − M₀)/h₀ = (M₂ − M₁)/h₁  and the mirror at the far end.
NotAKnotSpline::NotAKnotSpline(std::vector<double> x) : x_(std::move(x)) {
  const int n = static_cast<int>(x_.size());
  if (n < 4) throw std::invalid_argument("not-a-knot spline: needs at least 4 points");
  for (int i = 1; i < n; ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("not-a-knot spline: abscissae not increasing");
  MatX S = MatX::Zero(n, n), R = MatX::Zero(n, n);
  std::vector<double> h(n - 1);
  for (int i = 0; i + 1 < n; ++i) h[i] = x_[i + 1] - x_[i];
  S(0, 0) = -h[1];
  S(0, 1) = h[0] + h[1];
  S(0, 2) = -h[0];
  S(n - 1, n - 3) = -h[n - 2];
  S(n - 1, n - 2) = h[n - 3] + h[n - 2];
  S(n - 1, n - 1) = -h[n - 3];
  for (int i = 1; i + 1 < n; ++i) {
    S(i, i - 1) = h[i - 1];
    S(i, i) = 2 * (h[i - 1] + h[i]);
    S(i, i + 1) = h[i];
    R(i, i - 1) = 6 / h[i - 1];
    R(i, i) = -6 / h[i - 1] - 6 / h[i];
    R(i, i + 1) = 6 / h[i];
  }
  G_ = S.fullPivLu().solve(R);
}

VecX NotAKnotSpline::weights(double x) const {
  const int n = static_cast<int>(x_.size());
  int i = 0;
  while (i < n - 2 && x >= x_[i + 1]) ++i;
  const double h = x_[i + 1] - x_[i], a = (x_[i + 1] - x) / h, b = (x - x_[i]) / h;
  // s(x) = a y_i + b y_{i+1} + ((a³ − a) M_i + (b³ − b) M_{i+1}) h²/6.
  VecX w = ((a * a * a - a) * h * h / 6) * G_.row(i).transpose() +
           ((b * b * b - b) * h * h / 6) * G_.row(i + 1).transpose();
  w(i) += a;
  w(i + 1) += b;
  return w;
}

}  // namespace whirl::aero

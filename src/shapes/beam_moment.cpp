#include "src/shapes/beam_moment.hpp"

#include <cmath>

namespace whirl {
namespace {

double interpolate(const VecX& x, const VecX& v, double xi) {
  if (v.size() == 0) return 0.0;
  const int n = static_cast<int>(x.size());
  if (n == 1) return v(0);
  int i = 0;
  while (i < n - 2 && xi > x(i + 1)) ++i;
  const double w = (xi - x(i)) / (x(i + 1) - x(i));
  return (1 - w) * v(i) + w * v(i + 1);
}

}  // namespace

MatX beamMomentGains(const BeamProperties& p, const std::vector<ShapePtr>& shapes, double x) {
  const int ne = static_cast<int>(shapes.size());
  const double th = interpolate(p.x, p.twist, x), ct = std::cos(th), st = std::sin(th);
  const double EIy = interpolate(p.x, p.EIy, x), EIz = interpolate(p.x, p.EIz, x);
  MatX G(2, ne);
  for (int j = 0; j < ne; ++j) {
    const ShapeValue v = shapes[j]->eval(x);
    const double m1 = EIy * (ct * v.uy2 + st * v.uz2), m2 = EIz * (-st * v.uy2 + ct * v.uz2);
    G(0, j) = ct * m1 - st * m2;
    G(1, j) = st * m1 + ct * m2;
  }
  return G;
}

}  // namespace whirl

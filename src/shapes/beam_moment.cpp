#include "src/shapes/beam_moment.hpp"

#include "src/shapes/interpolate.hpp"

#include <cmath>

namespace whirl {
MatX beamMomentGains(const BeamProperties& p, const std::vector<ShapePtr>& shapes, double x) {
  const int ne = static_cast<int>(shapes.size());
  const double th = interpolateStations(p.x, p.twist, x), ct = std::cos(th), st = std::sin(th);
  const double EIy = interpolateStations(p.x, p.EIy, x), EIz = interpolateStations(p.x, p.EIz, x);
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

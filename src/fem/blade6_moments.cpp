#include "src/fem/blade6_moments.hpp"

#include <algorithm>

#include "src/fem/element6.hpp"
#include "src/fem/section6.hpp"

namespace whirl::fem {

MatX blade6MomentGains(const Blade6Body& blade, double x) {
  const Beam6Model& m = blade.model;
  const auto node = [&](int i) -> const Vec3& { return m.nodes[static_cast<std::size_t>(i)]; };
  std::size_t e = 0;
  while (e + 1 < m.elements.size() && x > node(m.elements[e].n2).x()) ++e;
  const Beam6Element& el = m.elements[e];
  const Vec3 &x1 = node(el.n1), &x2 = node(el.n2);
  const double len = (x2 - x1).norm();
  const Vec3 t = (x2 - x1) / len;
  const double s = std::clamp((x - x1.x()) / (x2.x() - x1.x()), 0.0, 1.0) * len;
  const Mat6s C = lerp6(el.s1, el.s2, 0.5).C;
  const Eigen::Matrix<double, 6, 12> B = strainMatrix6(x1, x2);
  const Eigen::Index ne = blade.modes.cols();
  MatX G(2, ne);
  for (Eigen::Index j = 0; j < ne; ++j) {
    const Eigen::Matrix<double, 6, 1> strain = B.leftCols<6>() * blade.modes.block(6 * el.n1, j, 6, 1) +
                                               B.rightCols<6>() * blade.modes.block(6 * el.n2, j, 6, 1);
    const Eigen::Matrix<double, 6, 1> sigma = C * strain;
    const Vec3 F = sigma.head<3>();
    const Vec3 M = Vec3(sigma.tail<3>()) - (s - 0.5 * len) * t.cross(F);
    G(0, j) = M.z();   // κ_z = θ_z' = u_y''
    G(1, j) = -M.y();  // κ_y = θ_y' = −u_z''
  }
  return G;
}

}  // namespace whirl::fem

#include "src/fem/element6.hpp"

#include "src/base/skew.hpp"

namespace whirl::fem {

Eigen::Matrix<double, 6, 12> strainMatrix6(const Vec3& x1, const Vec3& x2) {
  const Vec3 d = x2 - x1;
  const double L = d.norm();
  const Mat3 t = skew(Vec3(d / L));  // t × θ
  const Mat3 I = Mat3::Identity() / L;
  Eigen::Matrix<double, 6, 12> B = Eigen::Matrix<double, 6, 12>::Zero();
  B.block<3, 3>(0, 0) = -I;
  B.block<3, 3>(0, 3) = 0.5 * t;
  B.block<3, 3>(0, 6) = I;
  B.block<3, 3>(0, 9) = 0.5 * t;
  B.block<3, 3>(3, 3) = -I;
  B.block<3, 3>(3, 9) = I;
  return B;
}

Mat12e elementStiffness6(const Vec3& x1, const Vec3& x2, const Mat6s& C) {
  const Eigen::Matrix<double, 6, 12> B = strainMatrix6(x1, x2);
  const Mat12e K = (x2 - x1).norm() * B.transpose() * C * B;
  return 0.5 * (K + K.transpose());
}

Mat12e elementMass6(const Vec3& x1, const Vec3& x2, const Mat6s& M1, const Mat6s& M2) {
  // 3-point Gauss–Legendre on [0, 1].
  static constexpr double xg[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
  static constexpr double wg[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  const double L = (x2 - x1).norm();
  Mat12e M = Mat12e::Zero();
  for (int g = 0; g < 3; ++g) {
    const double n1 = 1 - xg[g], n2 = xg[g];
    const Mat6s Mg = n1 * M1 + n2 * M2;
    const double w = wg[g] * L;
    M.block<6, 6>(0, 0) += w * n1 * n1 * Mg;
    M.block<6, 6>(0, 6) += w * n1 * n2 * Mg;
    M.block<6, 6>(6, 0) += w * n2 * n1 * Mg;
    M.block<6, 6>(6, 6) += w * n2 * n2 * Mg;
  }
  return 0.5 * (M + M.transpose());
}

}  // namespace whirl::fem

#include "src/fem/section6.hpp"

#include "src/base/skew.hpp"

namespace whirl::fem {

Section6 rotated(const Section6& s, const Mat3& R) {
  Mat6s T = Mat6s::Zero();
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = R;
  Section6 out;
  out.C = T * s.C * T.transpose();
  out.M = T * s.M * T.transpose();
  out.D = T * s.D * T.transpose();
  return out;
}

Section6 lerp6(const Section6& a, const Section6& b, double t) {
  Section6 s;
  s.C = (1 - t) * a.C + t * b.C;
  s.M = (1 - t) * a.M + t * b.M;
  s.D = (1 - t) * a.D + t * b.D;
  return s;
}

SectionMass sectionMass(const Mat6s& M) {
  SectionMass s;
  s.m = M(0, 0);
  if (s.m > 0) {
    // m c̃ is the lower-left block: c̃ = [0 −c3 c2; c3 0 −c1; −c2 c1 0].
    const Mat3 mc = 0.5 * (M.bottomLeftCorner<3, 3>() - M.topRightCorner<3, 3>());
    s.c = Vec3(mc(2, 1), mc(0, 2), mc(1, 0)) / s.m;
  }
  const Mat3 J = M.bottomRightCorner<3, 3>();
  s.J_cm = J - s.m * (s.c.squaredNorm() * Mat3::Identity() - s.c * s.c.transpose());
  return s;
}

Section6 isotropicSection(double EA, double GAy, double GAz, double GJ, double EIy, double EIz, double m, double jx,
                          double iy, double iz) {
  Section6 s;
  s.C.diagonal() << EA, GAy, GAz, GJ, EIy, EIz;
  s.M.diagonal() << m, m, m, jx, iy, iz;
  return s;
}

}  // namespace whirl::fem

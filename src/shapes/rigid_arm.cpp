#include "src/shapes/rigid_arm.hpp"

namespace whirl {

void offsetOnRigidArm(BodyPoint& pt, const Vec3& d) {
  pt.P.col(0) += d;
  for (Eigen::Index k = 0; k < pt.theta.cols(); ++k) pt.P.col(1 + k) += Vec3(pt.theta.col(k)).cross(d);
}

}  // namespace whirl

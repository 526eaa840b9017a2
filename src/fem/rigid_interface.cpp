#include "src/fem/rigid_interface.hpp"

#include <string>

#include "src/base/error.hpp"

namespace whirl::fem {

MatX rigidTie(const BeamModel& model, const DofMap& map, const std::vector<int>& nodes, const Vec3& reference) {
  MatX T = MatX::Zero(map.nfree(), 6);
  for (int node : nodes) {
    const Vec3 d = model.nodes[node] - reference;
    // u_j = u_R + θ_R × d = u_R − d̃ θ_R.
    Eigen::Matrix<double, 6, 6> t = Eigen::Matrix<double, 6, 6>::Identity();
    t.block<3, 3>(0, 3) << 0, d(2), -d(1), -d(2), 0, d(0), d(1), -d(0), 0;
    for (int k = 0; k < kNodeDofs; ++k) {
      const int f = map.index[kNodeDofs * node + k];
      if (f < 0)
        throw ComputeError("rigid interface: node " + std::to_string(node) + " (" + kNodeDofNames[k] +
                           ") is fixed, it cannot follow the interface's reference point");
      T.row(f) = t.row(k);
    }
  }
  return T;
}

BodyPoint rigidInterfacePoint(const std::string& name, const Vec3& reference, int ne) {
  BodyPoint p;
  p.name = name;
  p.P = Mat3X::Zero(3, 1 + ne);
  p.P.col(0) = reference;
  p.P.block(0, 1, 3, 3).setIdentity();
  p.theta = Mat3X::Zero(3, ne);
  p.theta.block(0, 3, 3, 3).setIdentity();
  return p;
}

}  // namespace whirl::fem

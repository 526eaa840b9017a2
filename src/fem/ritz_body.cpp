#include "src/fem/ritz_body.hpp"

namespace whirl::fem {

RitzBody ritzBody(const BeamModel& model, const Assembly& a, const DofMap& map, const MatX& basis,
                  const SpMat& stiffness, const std::vector<std::pair<std::string, int>>& points) {
  const int n = map.nfull, ne = static_cast<int>(basis.cols());
  std::vector<Eigen::Triplet<double>> t;
  t.emplace_back(0, 0, 1.0);
  for (int i = 0; i < map.nfree(); ++i)
    for (int k = 0; k < ne; ++k)
      if (basis(i, k) != 0.0) t.emplace_back(1 + map.free[i], 1 + k, basis(i, k));
  SpMat T(n + 1, 1 + ne);
  T.setFromTriplets(t.begin(), t.end());
  const SpMat Tt = T.transpose();
  RitzBody out;
  BodyInertia& in = out.inertia;
  in.ne = ne;
  in.quadratic = false;
  in.mass = a.integrals.mass;
  in.m1 = a.integrals.m1 * T;
  for (int k = 0; k < 9; ++k) in.S[k] = MatX(Tt * (a.integrals.S[k] * T));
  const MatX Kp = basis.transpose() * (stiffness * basis);
  out.elastic.K = 0.5 * (Kp + Kp.transpose());
  out.elastic.D = MatX::Zero(ne, ne);
  for (const auto& [name, node] : points) {
    BodyPoint p;
    p.name = name;
    p.P = Mat3X::Zero(3, 1 + ne);
    p.theta = Mat3X::Zero(3, ne);
    p.P.col(0) = model.nodes[node];
    for (int j = 0; j < 3; ++j) {
      const int ut = map.index[kNodeDofs * node + j], ur = map.index[kNodeDofs * node + 3 + j];
      if (ut >= 0) p.P.block(j, 1, 1, ne) = basis.row(ut);
      if (ur >= 0) p.theta.row(j) = basis.row(ur);
    }
    out.points.push_back(std::move(p));
  }
  return out;
}

MatX elasticMass(const BodyInertia& in) {
  MatX M = MatX::Zero(in.ne, in.ne);
  for (int k = 0; k < 3; ++k) M += in.S[4 * k].block(1, 1, in.ne, in.ne);
  return M;
}

}  // namespace whirl::fem

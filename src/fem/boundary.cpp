#include "src/fem/boundary.hpp"

namespace whirl::fem {

DofMap freeDofs(const BeamModel& m) {
  DofMap d;
  d.nfull = m.ndof();
  d.index.assign(d.nfull, -1);
  for (int i = 0; i < m.nnodes(); ++i)
    for (int k = 0; k < kNodeDofs; ++k) {
      if (!m.fixed.empty() && m.fixed[i][k]) continue;
      const int full = kNodeDofs * i + k;
      d.index[full] = d.nfree();
      d.free.push_back(full);
    }
  return d;
}

void clamp(BeamModel& m, int node) {
  if (m.fixed.empty()) m.fixed.assign(m.nodes.size(), {false, false, false, false, false, false});
  m.fixed[node].fill(true);
}

void keepOnly(BeamModel& m, const std::array<bool, 6>& active) {
  if (m.fixed.empty()) m.fixed.assign(m.nodes.size(), {false, false, false, false, false, false});
  for (auto& f : m.fixed)
    for (int k = 0; k < kNodeDofs; ++k) f[k] = f[k] || !active[k];
}

SpMat restrictTo(const SpMat& A, const DofMap& map) {
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c)
    for (SpMat::InnerIterator it(A, c); it; ++it) {
      const int r = map.index[it.row()], cc = map.index[it.col()];
      if (r >= 0 && cc >= 0) t.emplace_back(r, cc, it.value());
    }
  SpMat B(map.nfree(), map.nfree());
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

std::string dofName(int full) { return "n" + std::to_string(full / kNodeDofs) + " " + kNodeDofNames[full % kNodeDofs]; }

}  // namespace whirl::fem

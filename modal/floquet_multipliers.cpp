#include "modal/floquet_multipliers.hpp"

#include <cmath>
#include <numbers>

#include "modal/eigen.hpp"
#include "src/base/error.hpp"

namespace whirl {

LiftedMultipliers liftedMultipliers(const std::vector<MatX>& factors) {
  const int G = static_cast<int>(factors.size());
  if (G < 1) throw ComputeError("Floquet multipliers: no propagator");
  const Eigen::Index nx = factors.front().rows();
  MatX C = MatX::Zero(G * nx, G * nx);
  for (int g = 0; g < G; ++g) {
    if (factors[g].rows() != nx || factors[g].cols() != nx || !factors[g].allFinite())
      throw ComputeError("Floquet multipliers: propagator " + std::to_string(g) + " has another size or is not finite");
    C.block(((g + 1) % G) * nx, g * nx, nx, nx) = factors[g];
  }
  const EigenDecomposition ed = eigenStandard(C);
  // The G roots of each μ differ by e^{2πi/G}: keep the one with arg λ ∈ (−π/G, π/G]. All other roots
  // lie at |arg λ| ≥ π/G, so only roots near the boundary |arg λ| = π/G need care: C is real, so its
  // eigenvalues come in exact conjugate pairs, and of the roots near the boundary (a negative μ: r e^{±iπ/G};
  // a pair μ, μ̄ next to the negative axis: four roots) those with Im λ > 0 are one per multiplier.
  // A state that decays by more than 1e-12 within one factor (a fast real root: a heavily overdamped
  // coordinate) has μ below round-off and roots that are noise around 0: it is dead within a
  // revolution, root 0 (no oscillation to name).
  const double half = std::numbers::pi / G;
  const double dead = G == 1 ? 0.0 : 1e-12 * ed.values.cwiseAbs().maxCoeff();
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < ed.values.size(); ++i) {
    if (G == 1) {  // every eigenvalue of Φ(T) is its own root
      keep.push_back(i);
      continue;
    }
    if (std::abs(ed.values(i)) <= dead) continue;
    const double a = std::abs(std::arg(ed.values(i)));
    const bool boundary = std::abs(a - half) <= 1e-3 * half;
    if (boundary ? ed.values(i).imag() > 0 : a < half) keep.push_back(i);
  }
  if (static_cast<Eigen::Index>(keep.size()) > nx)
    throw ComputeError("Floquet multipliers: " + std::to_string(keep.size()) +
                       " principal roots of the cyclic "
                       "eigenproblem for " +
                       std::to_string(nx) + " multipliers");
  LiftedMultipliers out;
  out.groups = G;
  out.root = Eigen::VectorXcd::Zero(nx);
  out.blocks.assign(G, Eigen::MatrixXcd::Zero(nx, nx));
  for (Eigen::Index j = 0; j < static_cast<Eigen::Index>(keep.size()); ++j) {
    const Eigen::Index i = keep[j];
    out.root(j) = ed.values(i);
    for (int g = 0; g < G; ++g) out.blocks[g].col(j) = ed.vectors.col(i).segment(g * nx, nx);
  }
  return out;
}

}  // namespace whirl

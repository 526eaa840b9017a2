#include "src/fem/beam6_model.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "src/base/error.hpp"

namespace whirl::fem {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

void scatter(Triplets& t, const Mat12e& k, int n1, int n2) {
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      if (k(i, j) != 0.0) t.emplace_back((i < 6 ? 6 * n1 : 6 * n2 - 6) + i, (j < 6 ? 6 * n1 : 6 * n2 - 6) + j, k(i, j));
}

}  // namespace

Beam6Matrices assemble6(const Beam6Model& m) {
  Triplets tk, tm, td;
  const int nn = static_cast<int>(m.nodes.size());
  for (std::size_t k = 0; k < m.elements.size(); ++k) {
    const Beam6Element& e = m.elements[k];
    if (e.n1 < 0 || e.n2 < 0 || e.n1 >= nn || e.n2 >= nn || e.n1 == e.n2)
      throw InputError("6x6 beam model: element " + std::to_string(k + 1) + ": bad nodes");
    const Vec3 &x1 = m.nodes[static_cast<std::size_t>(e.n1)], &x2 = m.nodes[static_cast<std::size_t>(e.n2)];
    if (!((x2 - x1).norm() > 0)) throw InputError("6x6 beam model: element " + std::to_string(k + 1) + ": zero length");
    const Section6 mid = lerp6(e.s1, e.s2, 0.5);
    scatter(tk, elementStiffness6(x1, x2, mid.C), e.n1, e.n2);
    scatter(tm, elementMass6(x1, x2, e.s1.M, e.s2.M), e.n1, e.n2);
    if (!mid.D.isZero(0)) scatter(td, elementStiffness6(x1, x2, 0.5 * (mid.D + mid.D.transpose())), e.n1, e.n2);
  }
  Beam6Matrices out;
  const int n = m.ndof();
  out.K.resize(n, n);
  out.K.setFromTriplets(tk.begin(), tk.end());
  out.M.resize(n, n);
  out.M.setFromTriplets(tm.begin(), tm.end());
  out.D.resize(n, n);
  out.D.setFromTriplets(td.begin(), td.end());
  return out;
}

Modes6 clampedModes6(const Beam6Matrices& mats, int clamped_node, int count) {
  const int n = static_cast<int>(mats.K.rows());
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (i / 6 != clamped_node) free.push_back(i);
  const int nf = static_cast<int>(free.size());
  if (count < 1 || count > nf)
    throw ComputeError("6x6 beam modes: " + std::to_string(count) + " modes asked of " + std::to_string(nf) + " DOFs");
  const MatX Kd = MatX(mats.K), Md = MatX(mats.M);
  MatX K(nf, nf), M(nf, nf);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nf; ++j) {
      K(i, j) = Kd(free[i], free[j]);
      M(i, j) = Md(free[i], free[j]);
    }
  // K = L Lᵀ; A = L⁻¹ M L⁻ᵀ; A y = λ y with λ = 1/ω², φ = L⁻ᵀ y.
  const Eigen::LLT<MatX> llt(K);
  if (llt.info() != Eigen::Success)
    throw ComputeError("6x6 beam modes: the clamped stiffness is not positive definite (a mechanism)");
  MatX A = llt.matrixL().solve(M);
  A = llt.matrixL().solve(MatX(A.transpose()));
  const Eigen::SelfAdjointEigenSolver<MatX> eig(0.5 * (A + A.transpose()));
  if (eig.info() != Eigen::Success) throw ComputeError("6x6 beam modes: eigenvalue solver failed");
  Modes6 out;
  out.omega2.resize(count);
  out.vectors = MatX::Zero(n, count);
  for (int k = 0; k < count; ++k) {
    const double lambda = eig.eigenvalues()(nf - 1 - k);
    if (!(lambda > 0)) throw ComputeError("6x6 beam modes: fewer than " + std::to_string(count) + " modes with mass");
    const VecX phi = llt.matrixU().solve(VecX(eig.eigenvectors().col(nf - 1 - k))) / std::sqrt(lambda);
    out.omega2(k) = 1.0 / lambda;
    for (int i = 0; i < nf; ++i) out.vectors(free[i], k) = phi(i);
  }
  return out;
}

}  // namespace whirl::fem

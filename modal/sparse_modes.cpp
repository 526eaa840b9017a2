#include "modal/sparse_modes.hpp"

#include <cmath>

#include "modal/eigen.hpp"

namespace whirl {
namespace {

bool isSymmetric(const SparseMatrix& A) {
  const SparseMatrix At = A.transpose();
  const double scale = std::max(A.norm(), 1e-300);
  return (A - At).norm() <= 1e-12 * scale;
}

}  // namespace

std::vector<Mode> computeModesSparse(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K,
                                     const std::vector<std::string>& names, int nmodes, SparseEigenOptions opt,
                                     SparseModesInfo* info) {
  const int n = static_cast<int>(M.rows());
  if (n == 0 || nmodes <= 0) return {};
  const bool undamped = C.nonZeros() == 0 || C.norm() == 0.0;
  const bool symmetric = undamped && isSymmetric(K) && isSymmetric(M);
  EigenDecomposition ed;
  std::vector<double> residuals;
  SparseEigenResult r;
  if (symmetric) {
    // ω² → the pair λ = ±iω (or a real pair ±√−ω² for a rigid mode's round-off), as the dense
    // pencil returns them, so that the dense path's pairing and naming apply unchanged.
    opt.nev = nmodes;
    r = sparseGeneralizedEigen(K, M, opt);
    ed.values.resize(2 * static_cast<Eigen::Index>(r.pairs.size()));
    ed.vectors.resize(n, ed.values.size());
    for (size_t k = 0; k < r.pairs.size(); ++k) {
      const double w2 = r.pairs[k].value.real();
      const std::complex<double> l = w2 >= 0 ? std::complex<double>(0, std::sqrt(w2)) : std::sqrt(-w2);
      const auto j = static_cast<Eigen::Index>(2 * k);
      ed.values(j) = l;
      ed.values(j + 1) = w2 >= 0 ? std::conj(l) : -l;
      ed.vectors.col(j) = r.pairs[k].vector;
      ed.vectors.col(j + 1) = r.pairs[k].vector.conjugate();
      residuals.push_back(r.pairs[k].residual);
      residuals.push_back(r.pairs[k].residual);
    }
  } else {
    opt.nev = 2 * nmodes;  // a mode is a conjugate pair (or two real roots)
    r = sparseQuadraticEigen(M, C, K, opt);
    ed.values.resize(static_cast<Eigen::Index>(r.pairs.size()));
    ed.vectors.resize(n, ed.values.size());
    for (size_t k = 0; k < r.pairs.size(); ++k) {
      ed.values(static_cast<Eigen::Index>(k)) = r.pairs[k].value;
      ed.vectors.col(static_cast<Eigen::Index>(k)) = r.pairs[k].vector;
      residuals.push_back(r.pairs[k].residual);
    }
  }
  if (info) *info = {r.method, r.target, r.iterations};
  std::vector<Mode> modes = modesFromEigen(ed, n, M, names, residuals);
  if (static_cast<int>(modes.size()) > nmodes) modes.resize(static_cast<size_t>(nmodes));
  return modes;
}

}  // namespace whirl

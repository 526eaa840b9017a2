#include "modal/eigen.hpp"

#include <lapacke.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "src/base/error.hpp"

namespace whirl {
namespace {

void requireSquareFinite(const Eigen::MatrixXd& X, const char* what, const char* name) {
  if (X.rows() != X.cols())
    throw ComputeError(where("", 0, what,
                             std::string(name) + " is " + std::to_string(X.rows()) + " x " + std::to_string(X.cols()) +
                                 ", not square"));
  for (Eigen::Index j = 0; j < X.cols(); ++j)
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      if (!std::isfinite(X(i, j)))
        throw ComputeError(where("", 0, what,
                                 std::string(name) + "(" + std::to_string(i) + "," + std::to_string(j) +
                                     ") is not finite (" + std::to_string(X(i, j)) + ")"));
}

/// LAPACK real-format eigenvectors → complex columns of unit norm. A complex pair (j, j+1) with
/// imag(j) > 0 is stored as VR(:,j) ± i VR(:,j+1). (Scalar loops: GCC 12 warns falsely on Eigen's
/// AVX-512 complex packets here.)
Eigen::MatrixXcd unpackVectors(const Eigen::MatrixXd& VR, const Eigen::VectorXd& imag) {
  const Eigen::Index n = VR.cols(), m = VR.rows();
  Eigen::MatrixXcd V(m, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const bool pair = imag(j) != 0.0 && j + 1 < n;
    const double norm = pair ? std::hypot(VR.col(j).norm(), VR.col(j + 1).norm()) : VR.col(j).norm();
    const double s = norm > 0.0 ? 1.0 / norm : 1.0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const std::complex<double> v(s * VR(i, j), pair ? s * VR(i, j + 1) : 0.0);
      V(i, j) = v;
      if (pair) V(i, j + 1) = std::conj(v);
    }
    if (pair) ++j;
  }
  return V;
}

}  // namespace

EigenDecomposition eigenStandard(const Eigen::MatrixXd& A, bool with_left) {
  requireSquareFinite(A, "eigenStandard", "A");
  const lapack_int n = static_cast<lapack_int>(A.rows());
  EigenDecomposition out;
  if (n == 0) return out;
  Eigen::MatrixXd a = A;  // dgeev overwrites its input
  Eigen::VectorXd wr(n), wi(n);
  Eigen::MatrixXd vr(n, n), vl(with_left ? n : 1, with_left ? n : 1);
  const lapack_int info = LAPACKE_dgeev(LAPACK_COL_MAJOR, with_left ? 'V' : 'N', 'V', n, a.data(), n, wr.data(),
                                        wi.data(), vl.data(), with_left ? n : 1, vr.data(), n);
  if (info != 0)
    throw ComputeError(where("", 0, "eigenStandard",
                             "LAPACKE_dgeev failed (info = " + std::to_string(info) +
                                 (info > 0 ? ", QR iteration did not converge)" : ", illegal argument)")));
  out.values.resize(n);
  for (lapack_int j = 0; j < n; ++j) out.values(j) = {wr(j), wi(j)};
  out.vectors = unpackVectors(vr, wi);
  if (with_left) out.left = unpackVectors(vl, wi);  // same real format as the right vectors
  return out;
}

EigenDecomposition eigenSecondOrder(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K) {
  requireSquareFinite(M, "eigenSecondOrder", "M");
  requireSquareFinite(C, "eigenSecondOrder", "C");
  requireSquareFinite(K, "eigenSecondOrder", "K");
  const Eigen::Index n = M.rows();
  if (C.rows() != n || K.rows() != n)
    throw ComputeError(where("", 0, "eigenSecondOrder",
                             "M, C, K sizes differ (" + std::to_string(n) + ", " + std::to_string(C.rows()) + ", " +
                                 std::to_string(K.rows()) + ")"));
  EigenDecomposition out;
  if (n == 0) return out;
  const Eigen::Index n2 = 2 * n;
  // Pencil (Ap, Bp): Ap x = λ Bp x with x = [q; λq].
  Eigen::MatrixXd Ap = Eigen::MatrixXd::Zero(n2, n2), Bp = Eigen::MatrixXd::Zero(n2, n2);
  Ap.topRightCorner(n, n).setIdentity();
  Ap.bottomLeftCorner(n, n) = -K;
  Ap.bottomRightCorner(n, n) = -C;
  Bp.topLeftCorner(n, n).setIdentity();
  Bp.bottomRightCorner(n, n) = M;
  const double bnorm = Bp.norm();  // before dggev overwrites Bp

  const lapack_int nn = static_cast<lapack_int>(n2);
  Eigen::VectorXd ar(n2), ai(n2), beta(n2);
  Eigen::MatrixXd vr(n2, n2);
  double vl_dummy = 0;
  const lapack_int info = LAPACKE_dggev(LAPACK_COL_MAJOR, 'N', 'V', nn, Ap.data(), nn, Bp.data(), nn, ar.data(),
                                        ai.data(), beta.data(), &vl_dummy, 1, vr.data(), nn);
  if (info != 0)
    throw ComputeError(where("", 0, "eigenSecondOrder",
                             "LAPACKE_dggev failed (info = " + std::to_string(info) +
                                 (info > 0 ? ", QZ iteration did not converge)" : ", illegal argument)")));

  // β is a diagonal entry of the triangular factor of Bp: relative to ‖Bp‖ it is zero only when
  // Bp = diag(I, M) is singular, i.e. when M is.
  const double tol = 100.0 * static_cast<double>(n2) * std::numeric_limits<double>::epsilon() * bnorm;
  out.values.resize(n2);
  for (Eigen::Index j = 0; j < n2; ++j) {
    if (std::abs(beta(j)) <= tol)
      throw ComputeError(where("", 0, "eigenSecondOrder",
                               "infinite eigenvalue (beta = " + std::to_string(beta(j)) +
                                   "): the mass matrix M is singular, some DOF has no inertia"));
    out.values(j) = std::complex<double>(ar(j), ai(j)) / beta(j);
  }
  out.vectors = unpackVectors(vr, ai);
  return out;
}

ModalFrequency modalFrequency(std::complex<double> lambda) {
  const double mag = std::abs(lambda);
  const double two_pi = 2.0 * std::numbers::pi;
  return {mag / two_pi, std::abs(lambda.imag()) / two_pi, mag > 0.0 ? -lambda.real() / mag : 0.0};
}

}  // namespace whirl

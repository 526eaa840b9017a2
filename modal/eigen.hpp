#pragma once
/// \file
/// Dense eigenanalysis (LAPACK) of first-order systems ẋ = A x and of second-order systems
/// M q̈ + C q̇ + K q = 0.
///
/// Conventions (notation, docs/dev/architecture.md): state x = [q; q̇]; for an eigenvalue λ the natural frequency is
/// f = |λ|/2π, the damped frequency f_d = |Im λ|/2π and the damping ratio ζ = −Re λ/|λ|.
/// Eigenvalues come in the order LAPACK returns them (unsorted; a complex pair is adjacent,
/// positive imaginary part first). Eigenvectors are the columns of `vectors`, scaled to unit
/// Euclidean norm. Non-finite input or an infinite eigenvalue throws whirl::ComputeError.
#include <Eigen/Dense>
#include <complex>

namespace whirl {

/// Eigenvalues and right eigenvectors (columns), `vectors.col(j)` belongs to `values(j)`.
struct EigenDecomposition {
  Eigen::VectorXcd values;   ///< (dim n)
  Eigen::MatrixXcd vectors;  ///< (dim n × n), unit-norm columns
  /// Left eigenvectors u_j (uᴴA = λ u ᴴ), unit-norm columns, when asked for; else empty.
  Eigen::MatrixXcd left;
};

/// Solves A x = λ x (LAPACKE_dgeev, balancing on).
/// \param[in] A square state matrix (dim n × n), finite.
/// \param[in] with_left also the left eigenvectors (EigenDecomposition::left).
/// \throws ComputeError if A is not square, has a non-finite entry, or LAPACK does not converge.
EigenDecomposition eigenStandard(const Eigen::MatrixXd& A, bool with_left = false);

/// Solves (λ²M + λC + K) q = 0 through the 2n pencil
/// [[I, 0], [0, M]] λ x = [[0, I], [−K, −C]] x (LAPACKE_dggev): M is never inverted, so the
/// conditioning of M does not spoil the other eigenvalues.
/// \param[in] M mass matrix (dim n × n), non-singular.
/// \param[in] C damping (and gyroscopic) matrix (dim n × n).
/// \param[in] K stiffness matrix (dim n × n).
/// \return 2n eigenvalues; vectors are the 2n state vectors x = [q; λq].
/// \throws ComputeError on mismatched sizes, non-finite entries, non-convergence, or an infinite
///         eigenvalue (β ≈ 0), which means M is singular (a DOF without inertia).
EigenDecomposition eigenSecondOrder(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K);

/// Frequencies and damping of one eigenvalue.
struct ModalFrequency {
  double freq_hz;         ///< natural frequency |λ|/2π
  double damped_freq_hz;  ///< damped frequency |Im λ|/2π
  double damping_ratio;   ///< −Re λ/|λ| (0 for λ = 0)
};

/// Natural and damped frequency (Hz) and damping ratio of eigenvalue `lambda` (rad/s).
ModalFrequency modalFrequency(std::complex<double> lambda);

}  // namespace whirl

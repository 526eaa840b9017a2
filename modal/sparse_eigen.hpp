#pragma once
/// \file
/// Sparse eigenanalysis with SLEPc, for models too large for the dense LAPACK path
/// (modal/eigen.hpp): only the eigenvalues nearest a target are computed, by shift-and-invert
/// (a sparse direct factorization, MUMPS, of the shifted operator) and a Krylov method.
///
/// - Undamped: the generalized symmetric problem K x = ω² M x (SLEPc EPS, Krylov–Schur,
///   problem type GHEP), K symmetric, M symmetric positive definite.
/// - Damped and gyroscopic: the quadratic problem (λ²M + λC + K) x = 0 (SLEPc PEP, TOAR), solved
///   on the n × n matrices: no 2n state matrix is formed.
///
/// Every eigenpair comes with its backward error ‖P(λ)x‖ / ((Σ|λ|ʲ‖Aⱼ‖)‖x‖) (SLEPc's
/// EPS/PEPComputeError with ERROR_BACKWARD). Options in PETSc's database override the defaults set
/// here (-eps_*, -pep_*, -st_*, -st_pc_factor_mat_solver_type …; whirl passes them from its
/// command line). Matrices are plain Eigen sparse matrices: PETSc stays inside the .cpp.
/// Built without PETSc (WHIRL_WITH_PETSC=OFF) both functions throw ComputeError "unavailable".
#include <Eigen/Sparse>
#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace whirl {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct SparseEigenOptions {
  /// Eigenvalues wanted: ω² values (EPS) or λ values (PEP, where a complex pair counts twice).
  int nev = 20;
  /// Shift σ of shift-and-invert: (rad/s)² for EPS, rad/s (real) for PEP. Empty: automatic, just
  /// below the spectrum (see sparseAutoTarget) so that K − σM is non-singular even with rigid-body
  /// modes, and the lowest modes converge first.
  std::optional<double> target;
  double tol = 1e-12;  ///< convergence tolerance on the relative residual
  int max_it = 0;      ///< 0: SLEPc's default
  /// true: the problem is spread over PETSC_COMM_WORLD (every rank passes the same matrices and
  /// gets every result); false: solved on this rank alone (PETSC_COMM_SELF), e.g. inside a sweep
  /// that already spreads its points over the ranks.
  bool distributed = false;
};

struct SparseEigenpair {
  std::complex<double> value;  ///< ω² (EPS, real) or λ (PEP)
  Eigen::VectorXcd vector;     ///< x (dim n), unit Euclidean norm
  double residual = 0;         ///< backward error of (value, vector)
};

struct SparseEigenResult {
  std::vector<SparseEigenpair> pairs;  ///< the converged pairs nearest the target, ascending |value − σ|
  double target = 0;                   ///< σ used
  int iterations = 0;                  ///< outer Krylov iterations (restarts)
  std::string method;                  ///< e.g. "EPS krylovschur, ST sinvert (MUMPS)"
};

/// K x = ω² M x for the `nev` eigenvalues nearest the target.
/// \param[in] K stiffness (dim n × n), symmetric.
/// \param[in] M mass (dim n × n), symmetric positive definite.
/// \throws ComputeError on mismatched sizes, a failed factorization (K − σM singular: move the
///         target) or fewer than nev converged pairs.
SparseEigenResult sparseGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M, const SparseEigenOptions& opt);

/// (λ²M + λC + K) x = 0 for the `nev` eigenvalues nearest the (real) target.
/// TOAR needs n well above its subspace size (SLEPc's default ncv = max(2·nev, nev + 15)): on
/// tiny models (e.g. n = 20 for 12 eigenvalues) it can stagnate; those belong to the dense path.
/// \param[in] M mass (dim n × n), non-singular; C damping + gyroscopic; K stiffness (any symmetry).
/// \throws ComputeError as sparseGeneralizedEigen.
SparseEigenResult sparseQuadraticEigen(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K,
                                       const SparseEigenOptions& opt);

/// The automatic shift, just below zero: σ = −1e-10 · max_i K_ii/M_ii in (rad/s)² for EPS (the
/// largest diagonal ratio is a Rayleigh quotient, of the order of ω_max² on FE meshes), and
/// σ = −√(1e-10 · max_i K_ii/M_ii) rad/s for PEP. Near zero, so the lowest modes are nearest and
/// well separated after inversion; below zero, so K − σM stays non-singular (σ²M − σC + K for
/// PEP) when rigid-body modes make K singular. A target far from the wanted eigenvalues (e.g.
/// min K_ii/M_ii, which can exceed ω_1² by orders of magnitude on a fine mesh) clusters them after
/// inversion and costs accuracy.
double sparseAutoTarget(const SparseMatrix& K, const SparseMatrix& M, bool quadratic);

/// Below this many coordinates `--solver auto` uses the dense LAPACK path (all eigenvalues, exact
/// to round-off, and faster there); at and above it SLEPc.
constexpr int kSparseSolverThreshold = 400;

}  // namespace whirl

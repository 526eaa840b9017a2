#pragma once
/// \file
/// Modes of a linear second-order model M q̈ + C q̇ + K q = 0: frequency, damped frequency, damping
/// ratio, shape, and a name from the dominant coordinates.
///
/// Eigenvalues come from the generalized 2n pencil (modal/eigen.hpp, no M⁻¹). A complex pair
/// (λ, λ̄) is one mode: f = |λ|/2π, f_d = |Im λ|/2π, ζ = −Re λ/|λ|. Real roots are paired, smallest
/// first, into one mode each: f = √(λ₁λ₂)/2π, ζ = −(λ₁+λ₂)/(2√(λ₁λ₂)) (> 1: overdamped); a pair
/// with a zero root is a rigid-body mode (f = 0, ζ = 0), e.g. a free azimuth or a free yaw.
#include <Eigen/Sparse>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "modal/mode_motion.hpp"
#include "src/base/types.hpp"

namespace whirl {

struct Mode {
  double freq_hz = 0;         ///< undamped natural frequency
  double damped_freq_hz = 0;  ///< |Im λ|/2π
  double damping_ratio = 0;
  bool rigid_body = false;
  /// Carried mostly (over half the participation) by first-order states, e.g. HydroDyn's radiation
  /// memory: a root of the fit, not a structural mode (Campbell plots leave it out by default).
  bool first_order = false;
  std::string name;  ///< from the dominant coordinates
  /// Evidence for the name (issue 45): the participation share of what the name stands for (a
  /// coordinate, or a rotor's coordinate group), the next one and its share; `ambiguous` when that
  /// runner-up carries at least 80 % of the leader's share (within 20 %), see setNameEvidence.
  double name_share = 0;
  std::string runner_up;
  double runner_up_share = 0;
  bool ambiguous = false;
  Eigen::VectorXcd shape;  ///< coordinate part of the eigenvector, dim n, largest entry = 1
  VecX participation;      ///< kinetic-energy share per coordinate |Re(φ_i* (Mφ)_i)| / Σ, sums to 1
  /// Backward error of the eigenpair, ‖P(λ)x‖ / ((Σ|λ|ʲ‖Aⱼ‖) ‖x‖), when an iterative solver
  /// (SLEPc, modal/sparse_eigen.hpp) computed it; empty for the direct LAPACK path.
  std::optional<double> residual;
  /// Physical motion of the nodes (modal/mode_shapes.hpp); empty unless computed.
  ModeMotion motion;
};

/// Modes sorted by frequency. names: one per coordinate (dim n).
std::vector<Mode> computeModes(const MatX& M, const MatX& C, const MatX& K, const std::vector<std::string>& names);

struct EigenDecomposition;
/// Modes from the eigenpairs of a first-order system with state x = [q; q̇] (dim 2n): pairing as
/// above, shape = q part. M (n × n) weighs the participations: the mass matrix of the shape's
/// coordinates, or a diagonal approximation of it.
/// residuals (optional, one per eigenvalue of ed): backward errors carried into Mode::residual
/// (the larger of the two roots for a mode made of two real roots).
std::vector<Mode> modesFromEigen(const EigenDecomposition& ed, int n, const MatX& M,
                                 const std::vector<std::string>& names, const std::vector<double>& residuals = {});
/// The same with a sparse weighting matrix (large finite-element models, modal/sparse_modes.hpp).
std::vector<Mode> modesFromEigen(const EigenDecomposition& ed, int n, const Eigen::SparseMatrix<double>& M,
                                 const std::vector<std::string>& names, const std::vector<double>& residuals = {});

/// Sets Mode::name_share, runner_up, runner_up_share and ambiguous from the shares of the candidates
/// a name is chosen from (name, share), in any order: the largest leads, the second is the runner-up.
void setNameEvidence(Mode& mode, std::vector<std::pair<std::string, double>> shares);

/// A runner-up with at least this fraction of the leader's share makes a name ambiguous.
constexpr double kAmbiguousRunnerUp = 0.8;

/// Name from participations: the dominant coordinate, joined by " / " with the next ones that
/// carry at least half of its share.
std::string nameFromParticipation(const VecX& participation, const std::vector<std::string>& names);

}  // namespace whirl

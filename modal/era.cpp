#include "modal/era.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "src/base/error.hpp"

namespace whirl {

std::vector<IdentifiedPole> identifyPoles(const MatX& y, double dt, const EraOptions& o) {
  const auto N = y.rows(), p = y.cols();
  if (!(dt > 0) || !std::isfinite(dt)) throw InputError("pole identification: sampling interval must be positive");
  if (p < 1) throw InputError("pole identification: no channel");
  const Eigen::Index r = o.block_rows > 0 ? o.block_rows : std::max<Eigen::Index>(20, (40 + p - 1) / p);
  const Eigen::Index s = N - r;
  if (r < 2 || s < r * p)
    throw InputError("pole identification: " + std::to_string(N) + " samples are too few for " + std::to_string(r) +
                     " block rows of " + std::to_string(p) + " channels");
  // One Hankel matrix of s + 1 columns: H0 is its first s columns, the shifted H1 its last s.
  MatX H(r * p, s + 1);
  for (Eigen::Index j = 0; j <= s; ++j)
    for (Eigen::Index i = 0; i < r; ++i) H.block(i * p, j, p, 1) = y.row(i + j).transpose();
  const auto H0 = H.leftCols(s), H1 = H.rightCols(s);
  const Eigen::BDCSVD<MatX> svd(H0, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const VecX& sv = svd.singularValues();
  if (sv.size() == 0 || !(sv(0) > 0)) return {};
  const Eigen::Index cap = o.max_order > 0 ? o.max_order : r * p / 2;
  Eigen::Index n = 0;
  while (n < sv.size() && n < cap && sv(n) > o.rank_tolerance * sv(0)) ++n;
  const MatX U = svd.matrixU().leftCols(n), V = svd.matrixV().leftCols(n);
  const VecX root = sv.head(n).cwiseSqrt(), inv_root = root.cwiseInverse();
  const MatX A = inv_root.asDiagonal() * (U.transpose() * H1 * V) * inv_root.asDiagonal();
  const MatX C = U.topRows(p) * root.asDiagonal();           // output map of the realization
  const VecX x0 = root.asDiagonal() * V.row(0).transpose();  // its state at t = 0
  const Eigen::ComplexEigenSolver<MatX> es(A);
  const Eigen::MatrixXcd& Phi = es.eigenvectors();
  const Eigen::VectorXcd modal_x0 = Phi.partialPivLu().solve(x0.cast<std::complex<double>>());
  std::vector<IdentifiedPole> poles;
  double largest = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::complex<double> z = es.eigenvalues()(k);
    const bool real = std::abs(z.imag()) <= 1e-12 * std::abs(z);
    if (!real && z.imag() < 0) continue;  // the conjugate of a pair counted with its partner
    const std::complex<double> lambda = std::log(real ? std::complex<double>(z.real(), 0.0) : z) / dt;
    IdentifiedPole pole;
    pole.freq_hz = std::abs(lambda) / (2 * std::numbers::pi);
    pole.damped_freq_hz = std::abs(lambda.imag()) / (2 * std::numbers::pi);
    pole.damping_ratio = std::abs(lambda) > 0 ? -lambda.real() / std::abs(lambda) : 1.0;
    // Mean amplitude over the record: |C φ| |φ⁺ x0| times the mean of |z|^k over the N samples.
    const double a = (C * Phi.col(k)).norm() * std::abs(modal_x0(k)) * (real ? 1.0 : 2.0);
    const double m = std::abs(z), mean = std::abs(m - 1) < 1e-12 ? 1.0 : (std::pow(m, N) - 1) / (N * (m - 1));
    pole.share = a * mean;
    largest = std::max(largest, pole.share);
    poles.push_back(pole);
  }
  if (largest > 0)
    for (IdentifiedPole& q : poles) q.share /= largest;
  std::sort(poles.begin(), poles.end(), [](const auto& a, const auto& b) { return a.share > b.share; });
  return poles;
}

const IdentifiedPole* nearestPole(const std::vector<IdentifiedPole>& poles, double damped_freq_hz) {
  const IdentifiedPole* best = nullptr;
  for (const IdentifiedPole& p : poles)
    if (!best || std::abs(p.damped_freq_hz - damped_freq_hz) < std::abs(best->damped_freq_hz - damped_freq_hz))
      best = &p;
  return best;
}

}  // namespace whirl

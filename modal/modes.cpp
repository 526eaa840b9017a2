#include "modal/modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "modal/eigen.hpp"

namespace whirl {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

template <class Weights>
Mode fromEigenvector(const Eigen::VectorXcd& v, const Weights& M, const std::vector<std::string>& names) {
  const int n = static_cast<int>(M.rows());
  Mode mode;
  mode.shape = v.head(n);
  Eigen::Index imax = 0;
  mode.shape.cwiseAbs().maxCoeff(&imax);
  if (std::abs(mode.shape(imax)) > 0) mode.shape /= mode.shape(imax);
  mode.participation = VecX(n);
  // Kinetic energy ½ φᴴ M φ split by coordinate; couplings (a floater's surge and pitch) count.
  const VecX Mre = M * mode.shape.real(), Mim = M * mode.shape.imag();
  Eigen::VectorXcd Mphi(n);
  for (int i = 0; i < n; ++i) Mphi(i) = {Mre(i), Mim(i)};
  for (int i = 0; i < n; ++i) mode.participation(i) = std::abs((std::conj(mode.shape(i)) * Mphi(i)).real());
  const double total = mode.participation.sum();
  if (total > 0) mode.participation /= total;
  mode.name = nameFromParticipation(mode.participation, names);
  std::vector<std::pair<std::string, double>> shares;
  for (int i = 0; i < n; ++i) shares.emplace_back(names.at(i), mode.participation(i));
  setNameEvidence(mode, std::move(shares));
  return mode;
}

}  // namespace

void setNameEvidence(Mode& mode, std::vector<std::pair<std::string, double>> shares) {
  std::stable_sort(shares.begin(), shares.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  mode.name_share = shares.empty() ? 0 : shares[0].second;
  mode.runner_up = shares.size() > 1 ? shares[1].first : "";
  mode.runner_up_share = shares.size() > 1 ? shares[1].second : 0;
  mode.ambiguous = shares.size() > 1 && mode.name_share > 0 &&
                   mode.runner_up_share >= kAmbiguousRunnerUp * mode.name_share;
}

std::string nameFromParticipation(const VecX& p, const std::vector<std::string>& names) {
  std::vector<int> order(p.size());
  for (int i = 0; i < p.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return p(a) > p(b); });
  std::string name = names.at(order[0]);
  for (size_t k = 1; k < order.size() && k < 3; ++k) {
    if (p(order[k]) < 0.5 * p(order[0])) break;
    name += " / " + names.at(order[k]);
  }
  return name;
}

std::vector<Mode> computeModes(const MatX& M, const MatX& C, const MatX& K, const std::vector<std::string>& names) {
  if (M.rows() == 0) return {};
  return modesFromEigen(eigenSecondOrder(M, C, K), static_cast<int>(M.rows()), M, names);
}

template <class Weights>
std::vector<Mode> modesFromEigenImpl(const EigenDecomposition& ed, int n, const Weights& w,
                                     const std::vector<std::string>& names, const std::vector<double>& residuals) {
  const bool with_res = residuals.size() == static_cast<size_t>(ed.values.size());
  std::vector<Mode> modes;
  if (n == 0) return modes;
  // Scale for "zero": the largest |λ| with a floor, so rigid-body roots (numerically ~1e-8) are caught.
  const double lmax = std::max(1.0, ed.values.cwiseAbs().maxCoeff());
  const double zero = 1e-7 * lmax;
  std::vector<int> real;
  for (int k = 0; k < ed.values.size(); ++k) {
    const std::complex<double> l = ed.values(k);
    if (std::abs(l.imag()) > zero && std::abs(l.imag()) > 1e-9 * std::abs(l)) {
      if (l.imag() < 0) continue;  // the conjugate carries the same mode
      Mode mode = fromEigenvector(ed.vectors.col(k), w, names);
      mode.freq_hz = std::abs(l) / two_pi;
      mode.damped_freq_hz = std::abs(l.imag()) / two_pi;
      mode.damping_ratio = -l.real() / std::abs(l);
      if (with_res) mode.residual = residuals[k];
      modes.push_back(mode);
    } else {
      real.push_back(k);
    }
  }
  std::sort(real.begin(), real.end(), [&](int a, int b) { return std::abs(ed.values(a)) < std::abs(ed.values(b)); });
  for (size_t k = 0; k + 1 < real.size(); k += 2) {
    const double l1 = ed.values(real[k]).real(), l2 = ed.values(real[k + 1]).real();
    Mode mode = fromEigenvector(ed.vectors.col(real[k]), w, names);
    if (std::abs(l1) <= zero) {
      mode.rigid_body = true;
      mode.freq_hz = 0;
      mode.damping_ratio = 0;
    } else {
      const double omega = std::sqrt(std::abs(l1 * l2));
      mode.freq_hz = omega / two_pi;
      mode.damping_ratio = -(l1 + l2) / (2 * omega);
    }
    mode.damped_freq_hz = 0;
    if (with_res) mode.residual = std::max(residuals[real[k]], residuals[real[k + 1]]);
    modes.push_back(mode);
  }
  std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  return modes;
}

std::vector<Mode> modesFromEigen(const EigenDecomposition& ed, int n, const MatX& M,
                                 const std::vector<std::string>& names, const std::vector<double>& residuals) {
  return modesFromEigenImpl(ed, n, M, names, residuals);
}

std::vector<Mode> modesFromEigen(const EigenDecomposition& ed, int n, const Eigen::SparseMatrix<double>& M,
                                 const std::vector<std::string>& names, const std::vector<double>& residuals) {
  return modesFromEigenImpl(ed, n, M, names, residuals);
}

}  // namespace whirl

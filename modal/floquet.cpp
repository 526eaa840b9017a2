#include "modal/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "modal/eigen.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace {

using MatX = Eigen::MatrixXd;
constexpr double kTwoPi = 2 * std::numbers::pi;

/// Dirichlet kernel of N equally spaced samples: 1 at x = 0 (mod 2π), 0 at the other samples.
double dirichlet(int N, double x) {
  const double s = std::sin(0.5 * x);
  if (std::abs(s) < 1e-14) return 1.0;
  const double d = std::sin(0.5 * N * x) / (N * s);
  return N % 2 == 1 ? d : d * std::cos(0.5 * x);
}

/// A at azimuth ψ, trigonometric interpolation of the samples.
MatX interpolate(const std::vector<MbcSample>& samples, double psi) {
  const int N = static_cast<int>(samples.size());
  MatX A = MatX::Zero(samples.front().A.rows(), samples.front().A.cols());
  for (int j = 0; j < N; ++j) {
    const double w = dirichlet(N, psi - samples[j].azimuth);
    if (w != 0.0) A += w * samples[j].A;
  }
  return A;
}

/// T⁻¹(ψ) of the states (multiblade transform with its rate terms): B_NR = T⁻¹ B with B = I and no
/// rotating inputs.
MatX inverseStateTransform(const MbcLayout& layout, double psi, double omega) {
  MbcLayout L = layout;
  L.input_blade.clear();
  L.output_blade.clear();
  const Eigen::Index n = static_cast<Eigen::Index>(layout.state_blade.size());
  MbcSample s;
  s.azimuth = psi;
  s.rotor_speed = omega;
  s.A = MatX::Zero(n, n);
  s.B = MatX::Identity(n, n);
  return mbcTransform(L, s).B;
}

}  // namespace

FloquetResult floquetAnalysis(const MbcLayout& layout, const std::vector<MbcSample>& samples, int steps) {
  if (samples.empty()) throw InputError(where("", 0, "Floquet", "no azimuth sample"));
  const int N = static_cast<int>(samples.size());
  const double omega = samples.front().rotor_speed, psi0 = samples.front().azimuth;
  const Eigen::Index n = samples.front().A.rows();
  if (!(omega > 0) || !std::isfinite(omega))
    throw InputError(where("", 0, "Floquet", "rotor speed must be positive (a parked rotor is time invariant: plain eigen)"));
  for (int j = 0; j < N; ++j) {
    if (samples[j].A.rows() != n || samples[j].A.cols() != n || samples[j].rotor_speed != omega)
      throw InputError(where("", 0, "Floquet", "sample " + std::to_string(j + 1) + " differs in size or rotor speed"));
    if (std::abs(std::remainder(samples[j].azimuth - psi0 - kTwoPi * j / N, kTwoPi)) > 1e-9)
      throw InputError(where("", 0, "Floquet", "azimuths must be ψ₀ + 2πj/N in order (sample " + std::to_string(j + 1) + ")"));
  }
  if (steps < 1) throw InputError(where("", 0, "Floquet", "steps must be at least 1"));

  // Steps: at least `steps` per sample interval, and small enough that the fastest root turns by at
  // most 0.05 rad per step (|λ| h / Ω ≤ 0.05: Runge–Kutta's phase error stays ~1e-9 per revolution).
  double rho = 0;
  for (const auto& smp : samples) rho = std::max(rho, eigenStandard(smp.A).values.cwiseAbs().maxCoeff());
  const double needed = std::ceil(rho / omega * (kTwoPi / N) / 0.05);
  // The harmonics resolvable from the stored points (below) must reach the fastest root's.
  if (rho / omega > 255)
    throw ComputeError(where("", 0, "Floquet",
                             "the fastest root (" + std::to_string(rho) + " rad/s) is more than 255 times the rotor speed (" +
                                 std::to_string(omega) + " rad/s): its frequency cannot be resolved from one revolution"));
  steps = std::max(steps, static_cast<int>(needed));
  // Monodromy by classical Runge–Kutta in ψ: dX/dψ = A(ψ) X / Ω. X is kept at Ms points per
  // revolution (a multiple of N, about 512) for the shapes' harmonics, every s-th step.
  const int per = std::max(1, 512 / N), Ms = N * per;
  const int s = std::max(1, static_cast<int>(std::ceil(static_cast<double>(N) * steps / Ms)));
  const int M = Ms * s;
  const double h = kTwoPi / M;
  std::vector<MatX> X(static_cast<size_t>(Ms) + 1);
  X[0] = MatX::Identity(n, n);
  MatX x = X[0];
  MatX A0 = interpolate(samples, psi0) / omega;
  for (int m = 0; m < M; ++m) {
    const double psi = psi0 + m * h;
    const MatX Ah = interpolate(samples, psi + 0.5 * h) / omega, A1 = interpolate(samples, psi + h) / omega;
    const MatX k1 = A0 * x, k2 = Ah * (x + 0.5 * h * k1), k3 = Ah * (x + 0.5 * h * k2), k4 = A1 * (x + h * k3);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    A0 = A1;
    if ((m + 1) % s == 0) X[(m + 1) / s] = x;
  }
  FloquetResult r;
  r.monodromy = X[Ms];
  if (!r.monodromy.allFinite()) throw ComputeError(where("", 0, "Floquet", "the monodromy matrix is not finite"));
  const EigenDecomposition ed = eigenStandard(r.monodromy);
  r.multipliers = ed.values;
  r.initial_vectors = ed.vectors;
  const double T = kTwoPi / omega;

  // Where the harmonic content is measured (floquet.hpp): multiblade or fixed-frame states.
  const bool multiblade = layout.num_blades >= 3 &&
                          std::any_of(layout.state_blade.begin(), layout.state_blade.end(), [](int b) { return b >= 0; });
  const double hs = kTwoPi / Ms;  // between stored points
  std::vector<MatX> Tinv;
  if (multiblade)
    for (int m = 0; m < Ms; ++m) Tinv.push_back(inverseStateTransform(layout, psi0 + m * hs, omega));
  // Harmonics up to what the stored points resolve: ln μ folds a frequency by any multiple of Ω.
  const int H = Ms / 2 - 1;
  r.exponents.resize(n);
  r.harmonic.assign(static_cast<size_t>(n), 0);
  for (Eigen::Index k = 0; k < n; ++k) {
    std::complex<double> eta = std::log(r.multipliers(k)) / T;
    // Periodic part p(ψ_m) = X_m v e^{−η t_m}, in the observer's coordinates.
    std::vector<Eigen::VectorXcd> p(static_cast<size_t>(Ms));
    for (int m = 0; m < Ms; ++m) {
      p[m] = X[m].cast<std::complex<double>>() * ed.vectors.col(k) * std::exp(-eta * (m * hs / omega));
      if (multiblade) p[m] = Tinv[m].cast<std::complex<double>>() * p[m];
    }
    std::vector<bool> use(static_cast<size_t>(n), true);
    if (!multiblade) {
      double fixed = 0, total = 0;
      for (int m = 0; m < Ms; ++m)
        for (Eigen::Index i = 0; i < n; ++i) {
          total += std::norm(p[m](i));
          if (layout.state_blade[i] < 0) fixed += std::norm(p[m](i));
        }
      if (fixed > 1e-6 * total)
        for (Eigen::Index i = 0; i < n; ++i) use[i] = layout.state_blade[i] < 0;
    }
    double best = -1;
    int best_h = 0;
    for (int j = 0; j <= 2 * H; ++j) {
      const int hm = j % 2 == 1 ? (j + 1) / 2 : -(j / 2);  // 0, 1, −1, 2, −2 …: a tie keeps the lower harmonic
      double energy = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        if (!use[i]) continue;
        std::complex<double> c = 0;
        for (int m = 0; m < Ms; ++m) c += p[m](i) * std::polar(1.0, -hm * m * hs);
        energy += std::norm(c);
      }
      if (energy > best * (1 + 1e-9)) best = energy, best_h = hm;
    }
    r.harmonic[k] = best_h;
    r.exponents(k) = eta + std::complex<double>(0, best_h * omega);
  }
  return r;
}

}  // namespace whirl

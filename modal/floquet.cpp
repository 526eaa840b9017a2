#include "modal/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>

#include "src/model/error.hpp"

namespace whirl {
namespace {

using cd = std::complex<double>;
using MatXc = Eigen::MatrixXcd;
using VecXc = Eigen::VectorXcd;
constexpr double pi = std::numbers::pi;
/// Bound on the Magnus steps per revolution (a slow rotor under a stiff structure).
constexpr double kMaxFloquetSteps = 20000;

/// Periodic interpolation kernel of N equally spaced samples (Dirichlet kernel; the even-N form
/// splits the Nyquist harmonic evenly): D(0) = 1, D(2πj/N) = 0 for j ≠ 0.
double kernel(double x, int N) {
  const double s = std::sin(0.5 * x);
  if (std::abs(s) < 1e-14) return 1.0;
  return N % 2 ? std::sin(0.5 * N * x) / (N * s) : std::sin(0.5 * N * x) * std::cos(0.5 * x) / (N * s);
}

/// The fixed-frame view of the n displacement coordinates: fixed ones as they are, each set of blade
/// coordinates (the j-th coordinate of every blade) as collective, cos and sin components.
struct FixedFrameView {
  int n = 0, nblades = 0;
  std::vector<int> fixed;                  ///< coordinate index of each fixed row
  std::vector<std::vector<int>> sets;      ///< sets[j][b]: coordinate of blade b in set j
  std::vector<NamingCoordinate> coords;    ///< one per row
  std::vector<std::string> names;
  VecX weights;                            ///< per row
  std::vector<bool> azimuth, held;

  int rows() const { return static_cast<int>(fixed.size() + 3 * sets.size()); }

  /// P(ψ): rows × n, ψ the azimuth of blade 1.
  MatX projection(double psi) const {
    MatX P = MatX::Zero(rows(), n);
    int r = 0;
    for (int i : fixed) P(r++, i) = 1.0;
    for (const auto& set : sets) {
      for (int b = 0; b < nblades; ++b) {
        const double pb = psi + 2 * pi * b / nblades;
        P(r, set[b]) = 1.0 / nblades;
        P(r + 1, set[b]) = 2.0 / nblades * std::cos(pb);
        P(r + 2, set[b]) = 2.0 / nblades * std::sin(pb);
      }
      r += 3;
    }
    return P;
  }
};

FixedFrameView fixedFrameView(const RotorCoordinates& c) {
  FixedFrameView v;
  v.n = static_cast<int>(c.names.size());
  for (int b : c.blade) v.nblades = std::max(v.nblades, b + 1);
  std::vector<std::vector<int>> per_blade(v.nblades);
  for (int i = 0; i < v.n; ++i) {
    if (c.blade[i] >= 0) {
      per_blade[c.blade[i]].push_back(i);
      continue;
    }
    v.fixed.push_back(i);
    v.coords.push_back({c.names[i], {}});
    v.names.push_back(c.names[i]);
    v.weights.conservativeResize(v.weights.size() + 1);
    v.weights(v.weights.size() - 1) = std::abs(c.weights(i, i));
    v.azimuth.push_back(i < static_cast<int>(c.azimuth.size()) && c.azimuth[i]);
    v.held.push_back(i < static_cast<int>(c.held.size()) && c.held[i]);
  }
  for (const auto& list : per_blade)
    if (list.size() != per_blade[0].size())
      throw InputError("Floquet analysis: every blade needs the same coordinates");
  const std::size_t nsets = v.nblades > 0 ? per_blade[0].size() : 0;
  for (std::size_t j = 0; j < nsets; ++j) {
    std::vector<int> set;
    for (int b = 0; b < v.nblades; ++b) set.push_back(per_blade[b][j]);
    v.sets.push_back(set);
    const std::string group = bladeBaseName(c.names[set[0]]);
    const MbcCoordinate kinds[3] = {{MbcKind::Collective, 0}, {MbcKind::Cosine, 1}, {MbcKind::Sine, 1}};
    for (const MbcCoordinate& k : kinds) {
      v.coords.push_back({group, k});
      v.names.push_back(group + " " + toString(k));
      v.weights.conservativeResize(v.weights.size() + 1);
      v.weights(v.weights.size() - 1) = std::abs(c.weights(set[0], set[0]));
      v.azimuth.push_back(false);
      v.held.push_back(false);
    }
  }
  return v;
}

/// ‖W^{1/2} x‖² with the view's weights.
double energy(const VecX& w, const VecXc& x) { return (w.array() * x.array().abs2()).sum(); }

}  // namespace

RotorModes floquetModes(const RotorCoordinates& c, const std::vector<MbcSample>& samples_in, const FloquetOptions& opt) {
  const int N = static_cast<int>(samples_in.size());
  if (N < 2) throw InputError("Floquet analysis: needs at least 2 azimuths");
  std::vector<MbcSample> samples = samples_in;
  std::sort(samples.begin(), samples.end(), [](const MbcSample& a, const MbcSample& b) { return a.azimuth < b.azimuth; });
  const double omega = samples.front().rotor_speed;
  if (!(std::abs(omega) > 0) || !std::isfinite(omega))
    throw InputError("Floquet analysis: needs a turning rotor (rotor speed is 0)");
  const Eigen::Index nx = samples.front().A.rows();
  const int n = static_cast<int>(c.names.size());
  if (nx < 2 * n) throw InputError("Floquet analysis: the state matrix is smaller than 2 × the coordinates");
  const double psi0 = samples.front().azimuth;
  for (int k = 0; k < N; ++k) {
    if (samples[k].A.rows() != nx || samples[k].A.cols() != nx || !samples[k].A.allFinite())
      throw InputError("Floquet analysis: state matrix " + std::to_string(k) + " has another size or is not finite");
    if (std::abs(samples[k].azimuth - psi0 - 2 * pi * k / N) > 1e-6)
      throw InputError("Floquet analysis: the azimuths must be equally spaced over one revolution");
  }
  const FixedFrameView view = fixedFrameView(c);
  const int nf = view.rows();

  // Monodromy by the fourth-order Magnus scheme on the trigonometric interpolant of A(ψ). The grid
  // also samples the solutions for their harmonics, which reach the highest frequency of the system
  // over the rotor speed: at least 4 points per period of the fastest mode (the averaged A's largest
  // eigenvalue), so that no harmonic aliases onto another.
  const double T = 2 * pi / std::abs(omega);
  MatX mean = MatX::Zero(nx, nx);
  for (const MbcSample& s : samples) mean += s.A / N;
  const double fastest = Eigen::EigenSolver<MatX>(mean, false).eigenvalues().cwiseAbs().maxCoeff();
  const double wanted = std::max<double>(N * std::max(1, opt.steps_per_sample), std::ceil(4 * fastest / std::abs(omega)) + 8);
  if (!(wanted <= kMaxFloquetSteps))
    throw InputError("Floquet analysis: the rotor turns too slowly for its fastest mode (" +
                     std::to_string(fastest / (2 * pi)) + " Hz at " + std::to_string(std::abs(omega) * 30 / pi) +
                     " rpm would need " + std::to_string(wanted) + " steps per revolution, limit " +
                     std::to_string(kMaxFloquetSteps) + ")");
  const int M = static_cast<int>(wanted);
  const double h = T / M;
  auto A = [&](double t) {
    MatX a = MatX::Zero(nx, nx);
    const double psi = psi0 + omega * t;
    for (int k = 0; k < N; ++k) a += kernel(psi - samples[k].azimuth, N) * samples[k].A;
    return a;
  };
  const double c1 = 0.5 - std::sqrt(3.0) / 6, c2 = 0.5 + std::sqrt(3.0) / 6;
  MatX Phi = MatX::Identity(nx, nx);
  std::vector<MatX> Y(M);  // P(ψ(t_m)) · (q rows of Φ(t_m)): the fixed-frame view of every solution
  for (int m = 0; m < M; ++m) {
    Y[m] = view.projection(psi0 + omega * m * h) * Phi.topRows(n);
    const MatX A1 = A((m + c1) * h), A2 = A((m + c2) * h);
    const MatX Om = 0.5 * h * (A1 + A2) + std::sqrt(3.0) / 12 * h * h * (A2 * A1 - A1 * A2);
    Phi = MatX(Om.exp()) * Phi;
  }
  Eigen::EigenSolver<MatX> es(Phi);
  if (es.info() != Eigen::Success) throw ComputeError("Floquet analysis: the eigenvalues of the monodromy matrix failed");
  const VecXc mu = es.eigenvalues();
  const MatXc V = es.eigenvectors();

  // Harmonics k = −M/2 … M/2−1 (index k mod M) of the fixed-frame view of the solutions Φ(t) V a
  // without e^{ηt}, frequencies k|Ω|: one FFT per entry.
  const double wr = std::abs(omega);
  Eigen::FFT<double> fft;
  auto harmonics = [&](const cd& eta, const MatXc& basis) {
    std::vector<MatXc> H(M, MatXc::Zero(nf, basis.cols()));
    std::vector<MatXc> z(M);
    for (int m = 0; m < M; ++m) z[m] = std::exp(-eta * (m * h)) * (Y[m].cast<cd>() * basis);
    std::vector<cd> series(M), spectrum;
    for (int r = 0; r < nf; ++r)
      for (Eigen::Index a = 0; a < basis.cols(); ++a) {
        for (int m = 0; m < M; ++m) series[m] = z[m](r, a);
        fft.fwd(spectrum, series);
        for (int k = 0; k < M; ++k) H[k](r, a) = spectrum[k] / double(M);
      }
    return H;
  };
  auto harmonic = [&](int index) { return index <= M / 2 ? index : index - M; };

  RotorModes out;
  out.coordinates = view.names;
  out.num_blades = view.nblades;
  std::vector<bool> done(nx, false);
  for (Eigen::Index j = 0; j < nx; ++j) {
    if (done[j]) continue;
    // The multipliers equal to μ_j: one eigenspace, split by harmonic below.
    std::vector<Eigen::Index> cluster;
    for (Eigen::Index i = j; i < nx; ++i)
      if (!done[i] && std::abs(mu(i) - mu(j)) <= 1e-7 * std::max(1.0, std::abs(mu(j)))) {
        cluster.push_back(i);
        done[i] = true;
      }
    if (std::abs(mu(j)) == 0) continue;  // a state that dies within a revolution: no oscillation to name
    const cd eta = std::log(mu(j)) / T;
    MatXc basis(nx, static_cast<Eigen::Index>(cluster.size()));
    for (std::size_t k = 0; k < cluster.size(); ++k) basis.col(k) = V.col(cluster[k]);
    const std::vector<MatXc> H = harmonics(eta, basis);
    const Eigen::Index d = basis.cols();
    MatXc Nm = MatXc::Zero(d, d), G = MatXc::Zero(d, d);
    for (int k = 0; k < M; ++k) {
      const MatXc WH = view.weights.cast<cd>().asDiagonal() * H[k];
      Nm += H[k].adjoint() * WH;
      G += double(harmonic(k)) * H[k].adjoint() * WH;
    }
    MatXc dirs = MatXc::Identity(d, d);
    if (d > 1) {
      // Directions of a single harmonic: G a = κ N a (N Hermitian positive definite when the
      // eigenspace has a fixed-frame response; a tiny shift keeps it so otherwise).
      const double shift = 1e-12 * std::max(1e-300, Nm.norm());
      Eigen::GeneralizedSelfAdjointEigenSolver<MatXc> ges(0.5 * (G + G.adjoint()),
                                                         0.5 * (Nm + Nm.adjoint()) + shift * MatXc::Identity(d, d));
      if (ges.info() == Eigen::Success) dirs = ges.eigenvectors();
    }
    for (Eigen::Index a = 0; a < d; ++a) {
      const VecXc dir = dirs.col(a);
      int best = 0;
      double best_e = -1;
      for (int k = 0; k < M; ++k) {
        const double e = energy(view.weights, H[k] * dir);
        // Ties (a 2-bladed rotor's standing cyclic pattern) go to the smaller |harmonic|.
        if (e > best_e * (1 + 1e-9) || (e >= best_e * (1 - 1e-9) && std::abs(harmonic(k)) < std::abs(harmonic(best)))) {
          best_e = std::max(best_e, e);
          best = k;
        }
      }
      const int kbest = harmonic(best);
      cd lambda = eta + cd(0, kbest * wr);
      VecXc shape = H[best] * dir;
      const bool real_multiplier = std::abs(mu(j).imag()) <= 1e-12 * std::abs(mu(j));
      if (lambda.imag() < 0) {
        if (!real_multiplier) continue;  // its conjugate multiplier gives the same mode
        lambda = std::conj(lambda);
        shape = shape.conjugate();
      }
      Mode md;
      md.freq_hz = std::abs(lambda) / (2 * pi);
      md.damped_freq_hz = std::abs(lambda.imag()) / (2 * pi);
      md.damping_ratio = std::abs(lambda) > 0 ? -lambda.real() / std::abs(lambda) : 0.0;
      Eigen::Index imax = 0;
      shape.cwiseAbs().maxCoeff(&imax);
      if (std::abs(shape(imax)) > 0) shape /= shape(imax);
      md.shape = shape;
      VecX e = view.weights.array() * shape.array().abs2();
      md.participation = e.sum() > 0 ? VecX(e / e.sum()) : e;
      nameRotorMode(md, view.coords, view.azimuth, view.held, omega);
      out.modes.push_back(std::move(md));
    }
  }
  std::sort(out.modes.begin(), out.modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  return out;
}

}  // namespace whirl

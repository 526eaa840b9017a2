#include "modal/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>

#include "modal/eigen.hpp"
#include "modal/floquet_harmonic.hpp"
#include "modal/floquet_multipliers.hpp"
#include "src/base/error.hpp"

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
  std::vector<int> fixed;                ///< coordinate index of each fixed row
  std::vector<int> teeter;               ///< coordinate of each teeter (two rows each: cos, sin)
  std::vector<std::vector<int>> sets;    ///< sets[j][b]: coordinate of blade b in set j
  std::vector<NamingCoordinate> coords;  ///< one per row
  std::vector<std::string> names;
  VecX weights;            ///< per row
  VecX cyclic_weights;     ///< weights of the cyclic rows (blade cos/sin, teeter), 0 elsewhere
  std::vector<int> rotor;  ///< the rotor's own coordinates (blades, teeter), as they are
  VecX rotor_weights;      ///< their weights
  std::vector<bool> azimuth, held;

  /// Selects the rotor's own coordinates: rotor.size() × n.
  MatX rotorRows() const {
    MatX S = MatX::Zero(static_cast<Eigen::Index>(rotor.size()), n);
    for (std::size_t r = 0; r < rotor.size(); ++r) S(static_cast<Eigen::Index>(r), rotor[r]) = 1.0;
    return S;
  }

  int rows() const { return static_cast<int>(fixed.size() + 2 * teeter.size() + 3 * sets.size()); }

  /// P(ψ): rows × n, ψ the azimuth of blade 1.
  MatX projection(double psi) const {
    MatX P = MatX::Zero(rows(), n);
    int r = 0;
    for (int i : fixed) P(r++, i) = 1.0;
    // A teeter β as the differential pattern q1 = β, q2 = −β of a 2-bladed rotor's cyclic rows.
    const double dpsi = nblades > 0 ? 2 * pi / nblades : pi;
    const double scale = 2.0 / std::max(nblades, 2);
    for (int i : teeter) {
      P(r++, i) = scale * (std::cos(psi) - std::cos(psi + dpsi));
      P(r++, i) = scale * (std::sin(psi) - std::sin(psi + dpsi));
    }
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
    if (i < static_cast<int>(c.teeter.size()) && c.teeter[i]) continue;  // rows after the fixed ones
    v.fixed.push_back(i);
    v.coords.push_back({c.names[i], {}});
    v.names.push_back(c.names[i]);
    v.weights.conservativeResize(v.weights.size() + 1);
    v.weights(v.weights.size() - 1) = std::abs(c.weights(i, i));
    v.azimuth.push_back(i < static_cast<int>(c.azimuth.size()) && c.azimuth[i]);
    v.held.push_back(i < static_cast<int>(c.held.size()) && c.held[i]);
  }
  // Teeter rows: weighed as the two blades' differential pattern, each blade carrying half its inertia.
  for (int i = 0; i < v.n; ++i) {
    if (i >= static_cast<int>(c.teeter.size()) || !c.teeter[i]) continue;
    v.teeter.push_back(i);
    const MbcCoordinate kinds[2] = {{MbcKind::Cosine, 1}, {MbcKind::Sine, 1}};
    for (const MbcCoordinate& k : kinds) {
      v.coords.push_back({c.names[i], k});
      v.names.push_back(c.names[i] + " " + toString(k));
      v.weights.conservativeResize(v.weights.size() + 1);
      v.weights(v.weights.size() - 1) = std::abs(c.weights(i, i)) / std::max(v.nblades, 2);
      v.azimuth.push_back(false);
      v.held.push_back(i < static_cast<int>(c.held.size()) && c.held[i]);
    }
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
  v.cyclic_weights = VecX::Zero(v.weights.size());
  for (Eigen::Index r = 0; r < v.weights.size(); ++r) {
    const MbcKind k = v.coords[r].kind.kind;
    if (k == MbcKind::Cosine || k == MbcKind::Sine) v.cyclic_weights(r) = v.weights(r);
  }
  for (int i = 0; i < v.n; ++i)
    if (c.blade[i] >= 0 || (i < static_cast<int>(c.teeter.size()) && c.teeter[i])) v.rotor.push_back(i);
  v.rotor_weights.resize(static_cast<Eigen::Index>(v.rotor.size()));
  for (std::size_t r = 0; r < v.rotor.size(); ++r) v.rotor_weights(r) = std::abs(c.weights(v.rotor[r], v.rotor[r]));
  return v;
}

/// ‖W^{1/2} x‖² with the view's weights.
double energy(const VecX& w, const VecXc& x) { return (w.array() * x.array().abs2()).sum(); }

}  // namespace

namespace {

/// The samples sorted by azimuth, checked: at least 2, a turning rotor, one size, finite, equally spaced
/// over one revolution.
std::vector<MbcSample> checkedSamples(const RotorCoordinates& c, const std::vector<MbcSample>& samples_in) {
  const int N = static_cast<int>(samples_in.size());
  if (N < 2) throw InputError("Floquet analysis: needs at least 2 azimuths");
  std::vector<MbcSample> samples = samples_in;
  std::sort(samples.begin(), samples.end(),
            [](const MbcSample& a, const MbcSample& b) { return a.azimuth < b.azimuth; });
  const double omega = samples.front().rotor_speed;
  if (!(std::abs(omega) > 0) || !std::isfinite(omega))
    throw InputError("Floquet analysis: needs a turning rotor (rotor speed is 0)");
  const Eigen::Index nx = samples.front().A.rows();
  if (nx < 2 * static_cast<Eigen::Index>(c.names.size()))
    throw InputError("Floquet analysis: the state matrix is smaller than 2 × the coordinates");
  const double psi0 = samples.front().azimuth;
  for (int k = 0; k < N; ++k) {
    if (samples[k].A.rows() != nx || samples[k].A.cols() != nx || !samples[k].A.allFinite())
      throw InputError("Floquet analysis: state matrix " + std::to_string(k) + " has another size or is not finite");
    if (std::abs(samples[k].azimuth - psi0 - 2 * pi * k / N) > 1e-6)
      throw InputError("Floquet analysis: the azimuths must be equally spaced over one revolution");
  }
  return samples;
}

/// The time grid of the monodromy: M = G·L steps of h over the period T, in G groups of L steps.
struct FloquetGrid {
  double T = 0, h = 0;
  int G = 1, L = 1, M = 1;
};

/// The grid samples the solutions for their harmonics, which reach the highest frequency of the system
/// over the rotor speed: at least 4 points per period of the fastest oscillating mode (the averaged A's
/// largest complex eigenvalue), so that no harmonic aliases onto another. The revolution is cut into G
/// equal groups of steps, enough that no group spans more than a decay of e^20 between the system's
/// slowest mode and its fastest decaying oscillating one (the averaged A's eigenvalues; at most 64
/// groups, and a real root that decays faster dies within a group): the multipliers come from the G
/// group propagators (modal/floquet_multipliers.hpp), each solution is sampled from its value at the
/// start of its group, and a well-damped mode of a slow rotor stays resolved.
FloquetGrid floquetGrid(const std::vector<MbcSample>& samples, double omega, const FloquetOptions& opt) {
  const int N = static_cast<int>(samples.size());
  const Eigen::Index nx = samples.front().A.rows();
  FloquetGrid g;
  g.T = 2 * pi / std::abs(omega);
  MatX mean = MatX::Zero(nx, nx);
  for (const MbcSample& s : samples) mean += s.A / N;
  const VecXc mean_eig = Eigen::EigenSolver<MatX>(mean, false).eigenvalues();
  // The oscillating modes set the sampling and the decay range over a revolution; a real root (a
  // heavily overdamped coordinate) is integrated exactly by the exponential of each step, and one that
  // decays faster than the range dies within a group.
  double fastest = 0, slowest = mean_eig.real().maxCoeff(), fastest_decay = slowest;
  for (const cd& l : mean_eig)
    if (std::abs(l.imag()) > 1e-6 * std::abs(l)) {
      fastest = std::max(fastest, std::abs(l));
      fastest_decay = std::min(fastest_decay, l.real());
    }
  const double spread = (slowest - fastest_decay) * g.T;
  const double wanted = std::max<double>(N * std::max(1, opt.steps_per_sample),
                                         std::ceil(4 * fastest / std::abs(omega)) + 8);
  if (!(wanted <= kMaxFloquetSteps))
    throw InputError("Floquet analysis: the rotor turns too slowly for its fastest mode (" +
                     std::to_string(fastest / (2 * pi)) + " Hz at " + std::to_string(std::abs(omega) * 30 / pi) +
                     " rpm would need " + std::to_string(wanted) + " steps per revolution, limit " +
                     std::to_string(kMaxFloquetSteps) + ")");
  g.G = static_cast<int>(std::clamp(std::ceil(spread / 20.0), 1.0, 64.0));
  g.L = static_cast<int>(std::ceil(wanted / g.G));  // steps per group
  g.M = g.G * g.L;
  g.h = g.T / g.M;
  return g;
}

/// The group propagators and the sampled solutions: Y[m] = P(ψ(t_m)) · (q rows of Φ(t_m, t_g)), the
/// propagator from the start t_g of step m's group — the fixed-frame view of every solution started
/// there; Yr[m] the rotor's own coordinates (blades, teeter) of the same solutions, as they are (the
/// rotating frame), kept for a rotor of at most 2 blades, whose cyclic modes stand (floquet_harmonic.hpp).
struct Propagation {
  std::vector<MatX> factors, Y, Yr;
};

/// Monodromy by the fourth-order Magnus scheme on the trigonometric interpolant of A(ψ).
Propagation propagate(const std::vector<MbcSample>& samples, const FixedFrameView& view, const FloquetGrid& g, int n,
                      bool standing) {
  const int N = static_cast<int>(samples.size());
  const Eigen::Index nx = samples.front().A.rows();
  const double psi0 = samples.front().azimuth, omega = samples.front().rotor_speed;
  auto A = [&](double t) {
    MatX a = MatX::Zero(nx, nx);
    const double psi = psi0 + omega * t;
    for (int k = 0; k < N; ++k) a += kernel(psi - samples[k].azimuth, N) * samples[k].A;
    return a;
  };
  const double c1 = 0.5 - std::sqrt(3.0) / 6, c2 = 0.5 + std::sqrt(3.0) / 6;
  Propagation p;
  p.factors.resize(g.G);
  p.Y.resize(g.M);
  p.Yr.resize(standing ? g.M : 0);
  for (int grp = 0; grp < g.G; ++grp) {
    MatX Phi = MatX::Identity(nx, nx);
    for (int m = grp * g.L; m < (grp + 1) * g.L; ++m) {
      p.Y[m] = view.projection(psi0 + omega * m * g.h) * Phi.topRows(n);
      if (standing) p.Yr[m] = view.rotorRows() * Phi.topRows(n);
      const MatX A1 = A((m + c1) * g.h), A2 = A((m + c2) * g.h);
      const MatX Om = 0.5 * g.h * (A1 + A2) + std::sqrt(3.0) / 12 * g.h * g.h * (A2 * A1 - A1 * A2);
      Phi = MatX(Om.exp()) * Phi;
    }
    p.factors[grp] = std::move(Phi);
  }
  return p;
}

/// Harmonics k = −M/2 … M/2−1 (index k mod M) of the solutions `source` started at the columns `cols`
/// of each group's basis (lifted.blocks), without e^{ηt}, frequencies k|Ω|: one FFT per entry. With
/// η = G ln λ / T the solution at t_m in group g is λ^g Y[m] x_g and e^{−η t_m} λ^g = e^{−η (t_m − t_g)}.
std::vector<MatXc> solutionHarmonics(const cd& eta, const std::vector<Eigen::Index>& cols,
                                     const std::vector<MatX>& source, const LiftedMultipliers& lifted,
                                     const FloquetGrid& g) {
  const Eigen::Index d = static_cast<Eigen::Index>(cols.size());
  const Eigen::Index rows = source.front().rows(), nx = lifted.blocks.front().rows();
  std::vector<MatXc> H(g.M, MatXc::Zero(rows, d));
  std::vector<MatXc> z(g.M);
  for (int grp = 0; grp < g.G; ++grp) {
    MatXc basis(nx, d);
    for (Eigen::Index a = 0; a < d; ++a) basis.col(a) = lifted.blocks[grp].col(cols[a]);
    for (int m = grp * g.L; m < (grp + 1) * g.L; ++m)
      z[m] = std::exp(-eta * ((m - grp * g.L) * g.h)) * (source[m].cast<cd>() * basis);
  }
  Eigen::FFT<double> fft;
  std::vector<cd> series(g.M), spectrum;
  for (Eigen::Index r = 0; r < rows; ++r)
    for (Eigen::Index a = 0; a < d; ++a) {
      for (int m = 0; m < g.M; ++m) series[m] = z[m](r, a);
      fft.fwd(spectrum, series);
      for (int k = 0; k < g.M; ++k) H[k](r, a) = spectrum[k] / double(g.M);
    }
  return H;
}

/// The modes of one eigenspace of the monodromy (the multipliers equal to one root), split by harmonic:
/// each direction's harmonic that gives it its frequency (floquet_harmonic.hpp), named like the
/// multiblade modes.
void clusterModes(const cd& root, const std::vector<Eigen::Index>& cluster, const Propagation& prop,
                  const LiftedMultipliers& lifted, const FloquetGrid& g, const FixedFrameView& view, double omega,
                  bool standing, RotorModes& out) {
  const int M = g.M;
  auto harmonic = [M](int index) { return index <= M / 2 ? index : index - M; };
  const double wr = std::abs(omega);
  const cd eta = double(g.G) * std::log(root) / g.T;
  const std::vector<MatXc> H = solutionHarmonics(eta, cluster, prop.Y, lifted, g);
  const std::vector<MatXc> Hr = standing ? solutionHarmonics(eta, cluster, prop.Yr, lifted, g) : std::vector<MatXc>{};
  const Eigen::Index d = static_cast<Eigen::Index>(cluster.size());
  MatXc Nm = MatXc::Zero(d, d), Gk = MatXc::Zero(d, d);
  for (int k = 0; k < M; ++k) {
    const MatXc WH = view.weights.cast<cd>().asDiagonal() * H[k];
    Nm += H[k].adjoint() * WH;
    Gk += double(harmonic(k)) * H[k].adjoint() * WH;
  }
  MatXc dirs = MatXc::Identity(d, d);
  if (d > 1) {
    // Directions of a single harmonic: Gk a = κ N a (N Hermitian positive definite when the
    // eigenspace has a fixed-frame response; a tiny shift keeps it so otherwise).
    const double shift = 1e-12 * std::max(1e-300, Nm.norm());
    Eigen::GeneralizedSelfAdjointEigenSolver<MatXc> ges(0.5 * (Gk + Gk.adjoint()),
                                                        0.5 * (Nm + Nm.adjoint()) + shift * MatXc::Identity(d, d));
    if (ges.info() == Eigen::Success) dirs = ges.eigenvectors();
  }
  for (Eigen::Index a = 0; a < d; ++a) {
    const VecXc dir = dirs.col(a);
    SolutionSpectrum spectrum;
    spectrum.fixed.resize(M);
    spectrum.cyclic.resize(M);
    if (standing) spectrum.rotating.resize(M);
    for (int k = 0; k < M; ++k) {
      const VecXc hk = H[k] * dir;
      spectrum.fixed[k] = energy(view.weights, hk);
      spectrum.cyclic[k] = energy(view.cyclic_weights, hk);
      if (standing) spectrum.rotating[k] = energy(view.rotor_weights, Hr[k] * dir);
    }
    const int best = floquetHarmonic(spectrum, eta.imag(), wr, standing);
    cd lambda = eta + cd(0, harmonic(best) * wr);
    VecXc shape = H[best] * dir;
    const bool real_multiplier = std::abs(std::sin(g.G * std::arg(root))) <= 1e-12;
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
    const std::string fw = " FW";
    if (standingCyclicMode(spectrum, standing) && md.name.size() > fw.size() &&
        md.name.compare(md.name.size() - fw.size(), fw.size(), fw) == 0)
      md.name.replace(md.name.size() - fw.size(), fw.size(), " BW");  // reported at its backward whirl
    out.modes.push_back(std::move(md));
  }
}

}  // namespace

RotorModes floquetModes(const RotorCoordinates& c, const std::vector<MbcSample>& samples_in,
                        const FloquetOptions& opt) {
  const std::vector<MbcSample> samples = checkedSamples(c, samples_in);
  const double omega = samples.front().rotor_speed;
  const Eigen::Index nx = samples.front().A.rows();
  const FixedFrameView view = fixedFrameView(c);
  const FloquetGrid grid = floquetGrid(samples, omega, opt);
  const bool standing = view.nblades <= 2 && !view.rotor.empty();
  const Propagation prop = propagate(samples, view, grid, static_cast<int>(c.names.size()), standing);
  const LiftedMultipliers lifted = liftedMultipliers(prop.factors);
  RotorModes out;
  out.coordinates = view.names;
  out.num_blades = view.nblades;
  std::vector<bool> done(nx, false);
  const VecXc& root = lifted.root;
  for (Eigen::Index j = 0; j < nx; ++j) {
    if (done[j]) continue;
    // The multipliers equal to μ_j (equal principal roots): one eigenspace, split by harmonic.
    std::vector<Eigen::Index> cluster;
    for (Eigen::Index i = j; i < nx; ++i)
      if (!done[i] && std::abs(root(i) - root(j)) <= 1e-7 * std::abs(root(j))) {
        cluster.push_back(i);
        done[i] = true;
      }
    if (std::abs(root(j)) == 0) continue;  // a state that dies within a revolution: no oscillation to name
    clusterModes(root(j), cluster, prop, lifted, grid, view, omega, standing, out);
  }
  std::sort(out.modes.begin(), out.modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  return out;
}

RotorModes parkedRotorModes(const RotorCoordinates& c, const MbcSample& sample) {
  const int n = static_cast<int>(c.names.size());
  if (sample.A.rows() < 2 * n || sample.A.cols() != sample.A.rows() || !sample.A.allFinite())
    throw InputError("parked rotor modes: the state matrix is not square, finite and at least 2 × the coordinates");
  const FixedFrameView view = fixedFrameView(c);
  const MatX P = view.projection(sample.azimuth);
  RotorModes out;
  out.coordinates = view.names;
  out.num_blades = view.nblades;
  out.A = sample.A;
  out.modes = modesFromEigen(eigenStandard(sample.A), n, c.weights, c.names);
  for (Mode& md : out.modes) {
    VecXc shape = P.cast<cd>() * md.shape;
    Eigen::Index imax = 0;
    shape.cwiseAbs().maxCoeff(&imax);
    if (std::abs(shape(imax)) > 0) shape /= shape(imax);
    const VecX e = view.weights.array() * shape.array().abs2();
    md.shape = shape;
    md.participation = e.sum() > 0 ? VecX(e / e.sum()) : e;
    nameRotorMode(md, view.coords, view.azimuth, view.held, 0.0);
  }
  return out;
}

}  // namespace whirl

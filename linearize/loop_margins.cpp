#include "linearize/loop_margins.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace whirl {
namespace {

using cd = std::complex<double>;
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The root of f between a and b (f(a), f(b) of opposite signs), by bisection in log ω.
double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int k = 0; k < 60; ++k) {
    const double m = std::sqrt(a * b), fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return std::sqrt(a * b);
}

}  // namespace

cd sensitivityAt(const LoopSensitivity& s, double omega) {
  Eigen::MatrixXcd M = -s.A.cast<cd>();
  M.diagonal().array() += cd(0, omega);
  const Eigen::VectorXcd x = M.partialPivLu().solve(s.b.cast<cd>());
  return (s.c.cast<cd>().transpose() * x)(0) + s.d;
}

LoopMargins loopMargins(const std::function<cd(double)>& S, const MarginOptions& opt) {
  auto L = [&](double w) { return 1.0 / S(w) - 1.0; };
  std::vector<double> w(static_cast<size_t>(opt.points));
  std::vector<cd> l(w.size());
  LoopMargins m;
  m.gain_margin = m.phase_margin = m.delay_margin = kInf;
  const double step = std::log(opt.max_frequency / opt.min_frequency) / (opt.points - 1);
  for (size_t i = 0; i < w.size(); ++i) {
    w[i] = opt.min_frequency * std::exp(step * static_cast<double>(i));
    const cd s = S(w[i]);
    l[i] = 1.0 / s - 1.0;
    if (std::abs(s) > m.peak_sensitivity) {
      m.peak_sensitivity = std::abs(s);
      m.peak_frequency = w[i];
    }
  }
  for (size_t i = 1; i < w.size(); ++i) {
    // Gain crossings: |L| − 1 changes sign.
    if ((std::abs(l[i - 1]) - 1 < 0) != (std::abs(l[i]) - 1 < 0)) {
      const double wc = bisect([&](double x) { return std::abs(L(x)) - 1; }, w[i - 1], w[i]);
      const double pm = 180 + std::arg(L(wc)) * 180 / kPi;  // ∠L in (−180°, 180°]
      const double pm_wrapped = pm > 180 ? pm - 360 : pm;
      if (pm_wrapped < m.phase_margin) {
        m.phase_margin = pm_wrapped;
        m.phase_crossover = wc;
      }
      const double dm = (pm_wrapped < 0 ? pm_wrapped + 360 : pm_wrapped) * kPi / 180 / wc;
      m.delay_margin = std::min(m.delay_margin, dm);
    }
    // Phase crossings of −180°: Im L changes sign where Re L < 0.
    if ((l[i - 1].imag() < 0) != (l[i].imag() < 0) && (l[i - 1].real() < 0 || l[i].real() < 0)) {
      const double wp = bisect([&](double x) { return L(x).imag(); }, w[i - 1], w[i]);
      const cd lp = L(wp);
      if (lp.real() < 0 && 1 / std::abs(lp) < m.gain_margin) {
        m.gain_margin = 1 / std::abs(lp);
        m.gain_crossover = wp;
      }
    }
  }
  return m;
}

namespace {

/// S(jω) = Σ (cᵀv_i)(w_iᵀb)/(jω − λ_i) + d from one eigendecomposition A = V Λ V⁻¹: O(n) per frequency
/// instead of an LU of jωI − A (the grid and the bisections evaluate S a few thousand times). Trusted
/// only where it agrees with the LU at both ends and the middle of the grid and at every resonance to
/// kModalTolerance · max(1, |S|) (an ill-conditioned V, a defective A fail): otherwise the LU is used
/// throughout. Absolute where |S| < 1: at the lowest frequencies an integrator makes |S| ~ 1e-4 and the
/// modal sum cancels terms of order 1 (measured on the NREL 5MW: ≤ 1e-8 there), which moves no crossing.
constexpr double kModalTolerance = 1e-7;

class ModalSensitivity {
 public:
  ModalSensitivity(const LoopSensitivity& s, const MarginOptions& opt) : s_(s) {
    Eigen::EigenSolver<MatX> es(s.A);
    if (es.info() != Eigen::Success) return;
    const Eigen::MatrixXcd V = es.eigenvectors();
    Eigen::PartialPivLU<Eigen::MatrixXcd> lu(V);
    lambda_ = es.eigenvalues();
    right_ = lu.solve(s.b.cast<cd>());
    left_ = V.transpose() * s.c.cast<cd>();
    check(opt);
  }
  /// From right and left eigenvectors: V⁻¹ b has the entries (u_iᴴ b)/(u_iᴴ v_i).
  ModalSensitivity(const LoopSensitivity& s, const ModalBasis& basis, const MarginOptions& opt) : s_(s) {
    if (basis.values.size() != s.A.rows() || basis.right.rows() != s.A.rows() || basis.left.rows() != s.A.rows())
      return;
    lambda_ = basis.values;
    right_ = Eigen::VectorXcd(lambda_.size());
    for (Eigen::Index i = 0; i < lambda_.size(); ++i)
      right_(i) = basis.left.col(i).dot(s.b.cast<cd>()) / basis.left.col(i).dot(basis.right.col(i));
    left_ = basis.right.transpose() * s.c.cast<cd>();
    check(opt);
  }
  void check(const MarginOptions& opt) {
    const LoopSensitivity& s = s_;
    if (!right_.allFinite() || !left_.allFinite()) return;
    modal_ = true;
    for (int k = 0; k <= 2 && modal_; ++k) {
      const double w = opt.min_frequency * std::pow(opt.max_frequency / opt.min_frequency, k / 2.0);
      const cd exact = sensitivityAt(s, w);
      modal_ = std::abs((*this)(w)-exact) <= kModalTolerance * std::max(1.0, std::abs(exact));
    }
    if (!modal_) return;
    for (Eigen::Index i = 0; i < lambda_.size() && modal_; ++i) {
      const double w = lambda_(i).imag();  // next to each resonance (one of a pair), where cancellation is worst
      if (w < opt.min_frequency || w > opt.max_frequency) continue;
      const cd exact = sensitivityAt(s, w);
      modal_ = std::abs((*this)(w)-exact) <= kModalTolerance * std::max(1.0, std::abs(exact));
    }
  }
  cd operator()(double w) const {
    if (!modal_) return sensitivityAt(s_, w);
    cd sum = s_.d;
    for (Eigen::Index i = 0; i < lambda_.size(); ++i) sum += left_(i) * right_(i) / (cd(0, w) - lambda_(i));
    return sum;
  }

 private:
  const LoopSensitivity& s_;
  bool modal_ = false;
  Eigen::VectorXcd lambda_, right_, left_;
};

}  // namespace

LoopMargins loopMargins(const LoopSensitivity& s, const MarginOptions& opt) {
  const ModalSensitivity S(s, opt);
  return loopMargins([&](double w) { return S(w); }, opt);
}

LoopMargins loopMargins(const LoopSensitivity& s, const ModalBasis& basis, const MarginOptions& opt) {
  const ModalSensitivity S(s, basis, opt);
  return loopMargins([&](double w) { return S(w); }, opt);
}

}  // namespace whirl

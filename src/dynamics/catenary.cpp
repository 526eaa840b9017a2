// The Newton solve of the catenary equations and the instantiations of catenary.hxx.
#include <algorithm>
#include <cmath>

#include "src/dynamics/catenary.hxx"
#include <fmt/format.h>

namespace whirl {
namespace detail {
namespace {

using AD2 = Eigen::AutoDiffScalar<Eigen::Vector2d>;
constexpr double kMaxStrain = 0.2;

// Starting tensions of FAST's quasi-static mooring solver [Jonkman2007], after
// Peyrot and Goulois (1979).
void initialGuess(const MooringLine& ln, double l, double h, double& H, double& V) {
  const double w = ln.weight, L = ln.length;
  double lambda;
  if (l == 0.0)
    lambda = 1e6;
  else if (std::hypot(l, h) >= L)
    lambda = 0.2;
  else
    lambda = std::sqrt(3.0 * ((L * L - h * h) / (l * l) - 1.0));
  H = std::max(std::abs(0.5 * w * l / lambda), 1e-3 * w * L);
  V = 0.5 * w * (h / std::tanh(lambda) + L);
}

}  // namespace

CatenaryNewton solveCatenaryNewton(const MooringLine& ln, double l, double h) {
  if (!(l > 1e-9 * ln.length) || !std::isfinite(l) || !std::isfinite(h))
    throw ComputeError(fmt::format("{}: fairlead straight above its anchor (horizontal distance {:.6g} m): the "
                                   "catenary equations have no horizontal direction", ln.name, l));
  CatenaryNewton s;
  initialGuess(ln, l, h, s.H, s.V);
  const double tol = 1e-10 * (ln.length + std::abs(l) + std::abs(h));
  double best = HUGE_VAL;
  for (int it = 0; it < 100; ++it) {
    AD2 H(s.H, 2, 0), V(s.V, 2, 1), x, z;
    catenaryProfile<AD2>(ln, H, V, x, z);
    s.J.row(0) = x.derivatives().transpose();
    s.J.row(1) = z.derivatives().transpose();
    const Eigen::Vector2d r(x.value() - l, z.value() - h);
    best = std::min(best, r.norm());
    if (r.norm() <= tol && it > 0) {
      // A steel or fibre line does not stretch by a fifth: the elastic catenary is not a line any more.
      const double strain = std::hypot(s.H, s.V) / ln.EA;
      if (strain > kMaxStrain)
        throw ComputeError(fmt::format("{}: the line cannot reach its anchor (horizontal distance {:.6g} m, height "
                                       "{:.6g} m, unstretched length {:.6g} m): it would stretch by {:.3g} %",
                                       ln.name, l, h, ln.length, 100 * strain));
      return s;
    }
    Eigen::Vector2d step = s.J.partialPivLu().solve(r);
    if (!step.allFinite()) break;
    // Keep H > 0 (the equations divide by it): at most a 90 % cut of H per step.
    double a = 1.0;
    if (s.H - step(0) < 0.1 * s.H) a = 0.9 * s.H / step(0);
    s.H -= a * step(0);
    s.V -= a * step(1);
  }
  throw ComputeError(fmt::format("{}: the catenary does not converge (horizontal distance {:.6g} m, height {:.6g} m, "
                                 "unstretched length {:.6g} m; residual {:.3g} m): the line cannot reach its anchor",
                                 ln.name, l, h, ln.length, best));
}

}  // namespace detail

Eigen::Vector2d catenaryResidual(const MooringLine& ln, double H, double V, double l, double h) {
  double x, z;
  detail::catenaryProfile<double>(ln, H, V, x, z);
  return {x - l, z - h};
}

double catenarySeabedLength(const MooringLine& ln, double V) {
  return ln.seabed ? std::max(0.0, ln.length - V / ln.weight) : 0.0;
}

template CatenaryTension<double> catenaryTension<double>(const MooringLine&, const double&, const double&);
template CatenaryTension<ADChunk> catenaryTension<ADChunk>(const MooringLine&, const ADChunk&, const ADChunk&);

}  // namespace whirl

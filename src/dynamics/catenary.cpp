// The Newton solve of the catenary equations and the instantiations of catenary.hxx.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include "src/dynamics/catenary.hxx"

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
  if (l == 0.0) lambda = 1e6;
  else if (std::hypot(l, h) >= L) lambda = 0.2;
  else lambda = std::sqrt(3.0 * ((L * L - h * h) / (l * l) - 1.0));
  H = std::max(std::abs(0.5 * w * l / lambda), 1e-3 * w * L);
  V = 0.5 * w * (h / std::tanh(lambda) + L);
}

}  // namespace

CatenaryNewton solveCatenaryNewton(const MooringLine& ln, double l, double h) {
  if (!(l > 1e-9 * ln.length) || !std::isfinite(l) || !std::isfinite(h))
    throw ComputeError(
        fmt::format("{}: fairlead straight above its anchor (horizontal distance {:.6g} m): the "
                    "catenary equations have no horizontal direction",
                    ln.name, l));
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
        throw ComputeError(
            fmt::format("{}: the line cannot reach its anchor (horizontal distance {:.6g} m, height "
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
  throw ComputeError(
      fmt::format("{}: the catenary does not converge (horizontal distance {:.6g} m, height {:.6g} m, "
                  "unstretched length {:.6g} m; residual {:.3g} m): the line cannot reach its anchor",
                  ln.name, l, h, ln.length, best));
}

CatenaryNewton solveTautLineNewton(const MooringLine& ln, double s, double h) {
  const double w = ln.weight, L = ln.length, EA = ln.EA;
  // Taut means the anchor's tension points up (V > w L); straight up, that needs h above the height at
  // V = w L, L + w L² / (2 EA).
  if (!(h > L + w * L * L / (2 * EA)))
    throw ComputeError(
        fmt::format("{}: the line straight below its fairlead is slack (height {:.6g} m, unstretched "
                    "length {:.6g} m): a vertical line must be taut",
                    ln.name, h, L));
  CatenaryNewton n;
  // Start from the straight weightless-free-end solution: z(0, V) = h gives V; q = 1 / X(0, V).
  n.V = std::max(EA * (h - L) / L + 0.5 * w * L, 1.5 * w * L);
  n.H = 1.0 / (std::log(n.V / (n.V - w * L)) / w + L / EA);
  const double tol = 1e-12;
  double best = HUGE_VAL;
  for (int it = 0; it < 100; ++it) {
    AD2 q(n.H, 2, 0), V(n.V, 2, 1), r1, r2;
    tautLineResidual<AD2>(ln, q, V, AD2(s), AD2(h), r1, r2);
    n.J.row(0) = r1.derivatives().transpose();
    n.J.row(1) = r2.derivatives().transpose();
    const Eigen::Vector2d r(r1.value(), r2.value() / L);
    best = std::min(best, r.norm());
    if (r.norm() <= tol && it > 0) {
      if (!(n.V - w * L > 0))
        throw ComputeError(
            fmt::format("{}: the line straight below its fairlead is slack (height {:.6g} m, unstretched "
                        "length {:.6g} m): a vertical line must be taut",
                        ln.name, h, L));
      const double strain = n.V / EA;
      if (strain > kMaxStrain)
        throw ComputeError(
            fmt::format("{}: the line cannot reach its anchor (height {:.6g} m, unstretched length "
                        "{:.6g} m): it would stretch by {:.3g} %",
                        ln.name, h, L, 100 * strain));
      return n;
    }
    Eigen::Matrix2d Js = n.J;
    Js.row(1) /= L;
    const Eigen::Vector2d step = Js.partialPivLu().solve(r);
    if (!step.allFinite()) break;
    // Keep V above w L (the anchor's tension upwards): at most a 90 % cut of the margin per step.
    double a = 1.0;
    const double margin = n.V - w * L;
    if (margin > 0 && n.V - step(1) - w * L < 0.1 * margin) a = 0.9 * margin / step(1);
    n.H -= a * step(0);
    n.V -= a * step(1);
  }
  throw ComputeError(
      fmt::format("{}: the line straight below its fairlead does not converge (height {:.6g} m, "
                  "unstretched length {:.6g} m; residual {:.3g}): is it slack?",
                  ln.name, h, L, best));
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
template CatenaryTension<double> tautLineTension<double>(const MooringLine&, const double&, const double&);
template CatenaryTension<ADChunk> tautLineTension<ADChunk>(const MooringLine&, const ADChunk&, const ADChunk&);
template Vec3T<double> mooringFairleadForce<double>(const MooringLine&, const Vec3T<double>&);
template Vec3T<ADChunk> mooringFairleadForce<ADChunk>(const MooringLine&, const Vec3T<ADChunk>&);

}  // namespace whirl

#include "linearize/load_jump.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "linearize/unrestrained.hpp"
#include "src/aero/bem.hpp"
#include "src/dynamics/aero_inflow.hpp"

namespace whirl {
namespace {

bool crosses(double a, double b, double limit) {
  return std::min(std::abs(a), std::abs(b)) < limit && std::max(std::abs(a), std::abs(b)) >= limit;
}

}  // namespace

LoadJump loadJump(const std::vector<int>& solved, const VecX& qa, const VecX& qb, const VecX& ea, const VecX& eb,
                  const AeroRecord* rec_a, const AeroRecord* rec_b) {
  LoadJump j;
  const VecX d = ea - eb;
  const double d2 = d.squaredNorm();
  if (!(d2 > 0) || solved.empty()) return j;
  // The combination of the two sides' loads nearest zero: λ e_a + (1 − λ) e_b = e_b + λ d, λ ∈ [0, 1].
  const double lambda = std::clamp(-eb.dot(d) / d2, 0.0, 1.0);
  if (!((eb + lambda * d).norm() <= 1e-2 * std::sqrt(d2))) return j;
  Eigen::Index worst = 0;
  d.cwiseAbs().maxCoeff(&worst);
  j.dof = solved[static_cast<size_t>(worst)];
  j.below = std::min(ea(worst), eb(worst));
  j.above = std::max(ea(worst), eb(worst));
  j.size = std::sqrt(d2);
  j.span = (qa - qb).lpNorm<Eigen::Infinity>();
  if (rec_a && rec_b && rec_a->elements.size() == rec_b->elements.size()) {
    double most = 0;
    for (size_t k = 0; k < rec_a->elements.size(); ++k) {
      const AeroElementState &a = rec_a->elements[k], &b = rec_b->elements[k];
      const double change = std::hypot(a.fx - b.fx, a.fy - b.fy);
      if (change > most) {
        most = change;
        j.element = static_cast<int>(k);
        j.vx_a = a.vx, j.vx_b = b.vx, j.vy_a = a.vy, j.vy_b = b.vy;
        j.bem_valid_a = a.bem_valid, j.bem_valid_b = b.bem_valid;
      }
    }
  }
  return j;
}

std::string describe(const Model& m, const LoadJump& j) {
  if (j.dof < 0) return "";
  const std::string unit = loadUnit(m, j.dof);
  std::string s = fmt::format("the load on DOF '{}' jumps from {:.4g} to {:.4g} {} across {:.3g} {}",
                              m.dofs[j.dof].name, j.below, j.above, unit, j.span, unit == "N m" ? "rad" : "m");
  if (j.element < 0) return s;
  int blade = 0, element = j.element;
  while (blade < static_cast<int>(m.aero.blades.size()) &&
         element >= static_cast<int>(m.aero.blades[static_cast<size_t>(blade)].stations.size()))
    element -= static_cast<int>(m.aero.blades[static_cast<size_t>(blade++)].stations.size());
  s += blade < static_cast<int>(m.aero.blades.size()) ? fmt::format(": blade {} element {} ", blade + 1, element + 1)
                                                      : fmt::format(": element {} ", j.element + 1);
  if (crosses(j.vx_a, j.vx_b, aero::kZeroVelocity))
    return s + fmt::format(
                   "crosses AeroDyn's zero-velocity limit of its normal velocity (|Vx| = {:g} m/s, here "
                   "{:.6g} and {:.6g} m/s), below which BEM is not solved",
                   aero::kZeroVelocity, j.vx_a, j.vx_b);
  if (crosses(j.vy_a, j.vy_b, aero::kZeroVelocity))
    return s + fmt::format(
                   "crosses AeroDyn's zero-velocity limit of its in-plane velocity (|Vy| = {:g} m/s, here "
                   "{:.6g} and {:.6g} m/s), below which BEM is not solved",
                   aero::kZeroVelocity, j.vy_a, j.vy_b);
  if (j.bem_valid_a != j.bem_valid_b)
    return s + "loses its valid BEM inflow angle on one side (the geometric inflow, as AeroDyn takes it)";
  return s + "switches between two BEM roots";
}

}  // namespace whirl

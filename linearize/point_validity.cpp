#include "linearize/point_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace whirl {

std::vector<std::string> checkPointValidity(const Model& m, const OperatingPoint& op, const ValidityLimits& lim) {
  std::vector<std::string> problems;
  for (const Body& b : m.bodies) {
    const int ne = b.inertia.ne;
    if (ne == 0 || b.elastic_dof < 0 || b.elastic_dof + ne > op.q.size()) continue;
    const VecX qe = op.q.segment(b.elastic_dof, ne);
    double length = 0, deflection = 0, slope = 0;
    for (const BodyPoint& p : b.points) {
      if (p.P.cols() < 1 + ne) continue;
      length = std::max(length, p.P.col(0).norm());
      deflection = std::max(deflection, (p.P.middleCols(1, ne) * qe).norm());
      if (p.theta.cols() == ne) slope = std::max(slope, (p.theta * qe).lpNorm<Eigen::Infinity>());
    }
    if (!std::isfinite(deflection) || (length > 0 && deflection > lim.max_deflection_fraction * length))
      problems.push_back(fmt::format("{}: elastic deflection {:.3g} m is {:.3g} × its length {:.3g} m (limit {:g})",
                                     b.name, deflection, length > 0 ? deflection / length : 0.0, length,
                                     lim.max_deflection_fraction));
    if (!std::isfinite(slope) || slope > lim.max_slope)
      problems.push_back(fmt::format("{}: elastic slope {:.3g} rad breaks the small-angle assumption (limit {:g} rad)",
                                     b.name, slope, lim.max_slope));
  }
  const double scale = std::max(op.load_scale, 1.0);
  if (!op.solved.empty() && !(op.residual_norm <= lim.max_relative_residual * scale))
    problems.push_back(fmt::format("equilibrium residual {:.3g} is not small against the loads {:.3g} (limit {:g} "
                                   "relative)",
                                   op.residual_norm, scale, lim.max_relative_residual));
  return problems;
}

}  // namespace whirl

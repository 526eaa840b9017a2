#include "linearize/point_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "linearize/unrestrained.hpp"

namespace whirl {
namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

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
  // A joint rotation solved for equilibrium more than half a turn from where it started has swung
  // round: a coordinate too weakly restrained for the loads on it (a parked teeter whose spring cannot
  // carry the rotor's weight), not a state of the turbine.
  for (int i : op.solved) {
    if (i < 0 || i >= op.q.size() || m.dofs[i].kind != DofKind::Joint || loadUnit(m, i) != "N m") continue;
    const double turn = op.q(i) - m.dofs[i].value;
    if (!(std::abs(turn) <= kPi))
      problems.push_back(
          fmt::format("{}: turned {:.4g} rad from its start {:.4g} rad, more than half a turn: too "
                      "weakly restrained for the loads on it; {}",
                      m.dofs[i].name, turn, m.dofs[i].value, holdAdvice(m, i)));
  }
  // A spring law linearized on one piece (a teeter stop, src/model/model.hpp DofSpring): the point
  // must lie on that piece, else the linear model has the wrong stiffness or damping there.
  for (const DofSpring& s : m.springs) {
    if (s.dof < 0 || s.dof >= op.q.size() || m.dofs[s.dof].frozen) continue;
    const double q = op.q(s.dof);
    if (!(q >= s.q_min && q <= s.q_max))
      problems.push_back(
          fmt::format("{}: {:.6g} lies outside [{:.6g}, {:.6g}], the piece of its spring law the model "
                      "was linearized on ({})",
                      m.dofs[s.dof].name, q, s.q_min, s.q_max, s.law));
  }
  const double scale = std::max(op.load_scale, 1.0);
  // On a jump of the loads (a Filippov equilibrium) the residual is that of one side, within the jump.
  const double allowed = std::max(lim.max_relative_residual * scale, op.load_jump.dof >= 0 ? op.load_jump.size : 0.0);
  if (!op.solved.empty() && !(op.residual_norm <= allowed))
    problems.push_back(
        fmt::format("equilibrium residual {:.3g} is not small against the loads {:.3g} (limit {:g} "
                    "relative)",
                    op.residual_norm, scale, lim.max_relative_residual));
  return problems;
}

}  // namespace whirl

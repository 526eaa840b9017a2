#include "linearize/unrestrained.hpp"

#include <algorithm>
#include <cmath>

#include "linearize/jacobian.hpp"

namespace whirl {
namespace {

// A spring of the model acts along coordinate i.
bool hasSpring(const Model& m, int i) {
  for (const DofSpring& s : m.springs)
    if (s.dof == i && s.k != 0.0) return true;
  for (const BodyMatrices& bm : m.body_matrices) {
    const int local = i - m.bodies[bm.body].joint_dof;
    if (local < 0 || local >= 6) continue;
    if (bm.K.row(local).cwiseAbs().maxCoeff() > 0 || bm.K.col(local).cwiseAbs().maxCoeff() > 0) return true;
  }
  return false;
}

}  // namespace

std::vector<int> unrestrainedCoordinates(const Model& m, const VecX& q, const VecX& qd, const VecX& u) {
  std::vector<int> solved, candidates;
  for (int i : m.activeDofs()) {
    if (m.dofs[i].rotating) continue;
    solved.push_back(i);
    if (m.dofs[i].kind == DofKind::Joint && !hasSpring(m, i)) candidates.push_back(i);
  }
  if (candidates.empty()) return {};
  // The structural model at the reference configuration: the undeflected turbine, no aerodynamics.
  Model s = m;
  s.aero = AeroModel{};
  VecX q0 = q;
  for (int i = 0; i < s.ndof(); ++i)
    if (s.dofs[i].kind == DofKind::Elastic) q0(i) = 0.0;
  const VecX qdd = VecX::Zero(s.ndof());
  JacobianWorkspace jw(s);
  const MatX J = residualJacobian(s, jw, q0, qd, qdd, u, Wrt::Q, solved);  // ∂e/∂q = −K
  double scale = 0;
  for (size_t k = 0; k < solved.size(); ++k)
    scale = std::max(scale, std::abs(J(solved[k], static_cast<Eigen::Index>(k))));
  std::vector<int> free;
  for (int i : candidates) {
    const auto k = static_cast<Eigen::Index>(std::find(solved.begin(), solved.end(), i) - solved.begin());
    const double kii = std::abs(J(i, k));
    if (!std::isfinite(kii)) continue;  // the solve reports the NaN
    if (kii <= kUnrestrainedTolerance * scale) free.push_back(i);
  }
  return free;
}

std::string holdAdvice(const Model& m, int dof) {
  if (dof == m.roles.yaw_dof)
    return "hold it with --set YawDOF=False, or a yaw spring (ServoDyn YawSpr with CompServo = 1)";
  if (dof == m.roles.teeter_dof)
    return "hold it with --set TeetDOF=False (the teeter locked at TeetDefl), or a teeter spring that carries the "
           "load (TeetMod = 1: TeetSSSp beyond TeetSStP)";
  return "hold it: freeze the coordinate or add a spring along it";
}

std::string loadUnit(const Model& m, int dof) {
  const Dof& d = m.dofs[dof];
  if (d.kind == DofKind::Elastic || d.body < 0) return "N";
  switch (m.bodies[d.body].joint) {
    case JointType::Revolute: return "N m";
    case JointType::Free: return d.local >= 3 ? "N m" : "N";
    default: return "N";
  }
}

}  // namespace whirl

#include "src/dynamics/energy.hpp"

#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/mass_matrix.hpp"

namespace whirl {

MechanicalEnergy mechanicalEnergy(const Model& m, Workspace<double>& ws, const VecX& q, const VecX& qd) {
  MechanicalEnergy E;
  MatX M;
  massMatrix(m, ws, q, M);
  E.kinetic = 0.5 * qd.dot(M * qd);
  const VecX qdd = VecX::Zero(m.ndof());
  forwardKinematics(m, ws, q, qd, qdd);
  for (size_t b = 0; b < m.bodies.size(); ++b) {
    const Body& body = m.bodies[b];
    const FrameState<double>& f = ws.frames[b];
    const Vec3 first_moment = body.inertia.mass * f.r + f.R * (body.inertia.m1 * ws.basis[b].c);
    E.gravity -= m.gravity.dot(first_moment);
    const int ne = body.inertia.ne;
    if (ne > 0 && body.elastic.K.rows() == ne) {
      const VecX qe = q.segment(body.elastic_dof, ne);
      E.elastic += 0.5 * qe.dot(body.elastic.K * qe);
    }
  }
  for (const DofSpring& s : m.springs) E.elastic += 0.5 * s.k * (q(s.dof) - s.q0) * (q(s.dof) - s.q0);
  for (const BodyMatrices& bm : m.body_matrices) {
    Eigen::Matrix<double, 6, 1> dx;
    for (int c = 0; c < 6; ++c) dx(c) = q(m.bodies[bm.body].joint_dof + c) - bm.x0(c);
    E.elastic += 0.5 * dx.dot(bm.K * dx);
  }
  return E;
}

}  // namespace whirl

#include "src/dynamics/gravity_loads.hpp"

#include "src/dynamics/kinematics.hpp"

namespace whirl {

GravityAtRest gravityAtRest(const Model& m) {
  Workspace<double> ws(m);
  VecX q(m.ndof());
  for (int k = 0; k < m.ndof(); ++k) q(k) = m.dofs[k].value;
  const VecX zero = VecX::Zero(m.ndof());
  forwardKinematics(m, ws, q, zero, zero);
  GravityAtRest g;
  // Parents come before children (finalize()): one pass from the leaves up.
  g.carried.resize(m.bodies.size());
  for (std::size_t i = 0; i < m.bodies.size(); ++i) g.carried[i] = m.bodies[i].inertia.mass;
  for (int i = static_cast<int>(m.bodies.size()) - 1; i >= 0; --i)
    if (m.bodies[i].parent >= 0) g.carried[m.bodies[i].parent] += g.carried[i];
  for (std::size_t i = 0; i < m.bodies.size(); ++i) g.gravity_body.push_back(ws.frames[i].R.transpose() * m.gravity);
  return g;
}

}  // namespace whirl

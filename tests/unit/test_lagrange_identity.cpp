// Kane's residual against Lagrange's equations, through independent paths:
//   e(q, q̇, 0) − e(q, 0, 0) = −Ṁ q̇ + ½ ∇_q(q̇ᵀ M q̇)     (quadratic velocity forces from the mass matrix)
//   e(q, 0, 0)              = −∇_q V                   (gravity, elastic and spring potential)
// with M from the double assembly and V from the body positions; derivatives by central
// differences. This catches wrong Coriolis/centrifugal/gyroscopic terms that a self-consistent
// AD-vs-FD check cannot.
#include <gtest/gtest.h>

#include <random>

#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"
#include "tests/support/rich_model.hpp"

namespace whirl {
namespace {

// The rich model without dissipation and without non-potential loads.
Model conservativeModel(bool axial_shortening) {
  Model m = test::richModel(axial_shortening);
  for (auto& b : m.bodies) b.elastic.D.setZero();
  for (auto& s : m.springs) s.c = 0;
  for (auto& bm : m.body_matrices) {
    bm.C.setZero();
    bm.A.setZero();  // added mass enters M but not the kinetic energy of the bodies
  }
  m.point_loads.clear();
  m.dof_loads.clear();
  return m;
}

double potential(const Model& m, Workspace<double>& ws, const VecX& q) {
  const VecX z = VecX::Zero(m.ndof());
  forwardKinematics(m, ws, q, z, z);
  double V = 0;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    const FrameState<double>& f = ws.frames[i];
    const Vec3 first_moment = b.inertia.m1 * ws.basis[i].c;  // ∫ s dm, body frame
    V -= m.gravity.dot(b.inertia.mass * f.r + f.R * first_moment);
    if (b.inertia.ne > 0) {
      const VecX qe = q.segment(b.elastic_dof, b.inertia.ne);
      V += 0.5 * qe.dot(b.elastic.K * qe);
    }
  }
  for (const auto& s : m.springs) V += 0.5 * s.k * (q(s.dof) - s.q0) * (q(s.dof) - s.q0);
  for (const auto& bm : m.body_matrices) {
    const Eigen::Matrix<double, 6, 1> x = q.segment<6>(m.bodies[bm.body].joint_dof) - bm.x0;
    V += 0.5 * x.dot(bm.K * x);
  }
  return V;
}

class Lagrange : public ::testing::TestWithParam<bool> {};

TEST_P(Lagrange, VelocityTermsFollowFromTheMassMatrix) {
  const Model m = conservativeModel(GetParam());
  const int n = m.ndof();
  Workspace<double> ws(m);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-1, 1);
  VecX q(n), qd(n);
  for (int i = 0; i < n; ++i) {
    q(i) = 0.3 * d(gen);
    qd(i) = 0.5 * d(gen);
  }
  const VecX z = VecX::Zero(n), u = VecX::Zero(m.ninput());
  VecX e1(n), e0(n);
  residual(m, ws, q, qd, z, u, e1);
  residual(m, ws, q, z, z, u, e0);
  const VecX quad = e1 - e0;
  // −Ṁ q̇ + ½ ∇(q̇ᵀ M q̇) by central differences of M(q).
  const double h = 1e-6;
  MatX Mp, Mm;
  massMatrix(m, ws, q + h * qd, Mp);
  massMatrix(m, ws, q - h * qd, Mm);
  VecX expected = -(Mp - Mm) / (2 * h) * qd;
  for (int k = 0; k < n; ++k) {
    VecX dq = VecX::Zero(n);
    dq(k) = h;
    massMatrix(m, ws, q + dq, Mp);
    massMatrix(m, ws, q - dq, Mm);
    expected(k) += 0.5 * qd.dot((Mp - Mm) / (2 * h) * qd);
  }
  const double scale = expected.cwiseAbs().maxCoeff();
  for (int k = 0; k < n; ++k) EXPECT_NEAR(quad(k), expected(k), 1e-6 * scale) << m.dofs[k].name;
}

TEST_P(Lagrange, StaticTermsAreMinusThePotentialGradient) {
  const Model m = conservativeModel(GetParam());
  const int n = m.ndof();
  Workspace<double> ws(m);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> d(-1, 1);
  VecX q(n);
  for (int i = 0; i < n; ++i) q(i) = 0.3 * d(gen);
  const VecX z = VecX::Zero(n), u = VecX::Zero(m.ninput());
  VecX e0(n);
  residual(m, ws, q, z, z, u, e0);
  const double h = 1e-6;
  VecX grad(n);
  for (int k = 0; k < n; ++k) {
    VecX dq = VecX::Zero(n);
    dq(k) = h;
    grad(k) = (potential(m, ws, q + dq) - potential(m, ws, q - dq)) / (2 * h);
  }
  const double scale = grad.cwiseAbs().maxCoeff();
  for (int k = 0; k < n; ++k) EXPECT_NEAR(e0(k), -grad(k), 1e-6 * scale) << m.dofs[k].name;
}

INSTANTIATE_TEST_SUITE_P(AxialShortening, Lagrange, ::testing::Values(true, false));

}  // namespace
}  // namespace whirl

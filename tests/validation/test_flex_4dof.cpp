// [Branlard2019, §6]: four-DOF turbine (tower fore-aft, shaft rotation, two blade flaps).
// Mq and Kq at q = [1 1 1 1] (eq. 36, the shaft angle is 1 rad), the tower and blade body mass
// matrices at unit deflection, and the tower's geometric stiffness from the overhead mass and its
// own weight.
#include "linearize/jacobian.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr const char* kCase = "flex_4dof";

// The body mass matrix of `body` (rows/columns a', α', q̈_e, body frame) at coordinates q.
MatX bodyMatrixAt(const Model& m, const std::string& body, const VecX& q) {
  Workspace<double> ws(m);
  const VecX z = VecX::Zero(m.ndof());
  forwardKinematics(m, ws, q, z, z);
  const int b = *m.findBody(body);
  return bodyMassMatrix(m.bodies[b].inertia, ws.basis[b]);
}

TEST(Flex4Dof, MassAndStiffnessAtUnitCoordinates) {
  // Gravity off: eq. 36's Kq is the elastic stiffness alone.
  const Model m = test::loadCase(kCase, {"gravity=0"});
  ASSERT_EQ(m.ndof(), 4);
  const VecX q = VecX::Ones(4);
  Workspace<double> ws(m);
  MatX M;
  massMatrix(m, ws, q, M);
  JacobianWorkspace jw(m);
  const VecX z = VecX::Zero(4);
  const MatX K = -residualJacobian(m, jw, q, z, z, VecX(), Wrt::Q, {0, 1, 2, 3});
  std::map<std::string, double> c = {{"Mq_11", M(0, 0)}, {"Mq_13", M(0, 2)}, {"Mq_14", M(0, 3)},
                                     {"Mq_22", M(1, 1)}, {"Mq_33", M(2, 2)}, {"Mq_44", M(3, 3)},
                                     {"Kq_11", K(0, 0)}, {"Kq_33", K(2, 2)}, {"Kq_44", K(3, 3)}};
  // Body matrices, 1-based (i, j) as printed in the paper: rows/columns x, y, z, θx, θy, θz, shape.
  const MatX Mt = bodyMatrixAt(m, "tower", q), Mb = bodyMatrixAt(m, "blade 1", q);
  for (auto [i, j] : std::vector<std::pair<int, int>>{
           {1, 1}, {1, 5}, {2, 4}, {2, 6}, {3, 5}, {3, 7}, {4, 4}, {4, 6}, {5, 5}, {5, 7}, {6, 6}})
    c["Mt_" + std::to_string(i) + std::to_string(j)] = Mt(i - 1, j - 1);
  for (auto [i, j] :
       std::vector<std::pair<int, int>>{{1, 1}, {1, 5}, {2, 4}, {2, 6}, {3, 5}, {3, 7}, {4, 4}, {5, 5}, {5, 7}})
    c["Mb_" + std::to_string(i) + std::to_string(j)] = Mb(i - 1, j - 1);
  test::expectMatchesReference(kCase, c);
  EXPECT_NEAR(M(0, 1), 0.0, 1e-9 * M(0, 0));  // eq. 36: the printed zeros
  EXPECT_NEAR(M(2, 3), 0.0, 1e-9 * M(0, 0));
}

TEST(Flex4Dof, TowerGeometricStiffness) {
  // At q = 0 the other bodies' centres of gravity lie where tilting the tower top does not raise
  // or lower them to second order, so K(g) − K(0) is the tower's own geometric stiffness.
  auto k11 = [](const std::vector<std::string>& sets) {
    const Model m = test::loadCase(kCase, sets);
    return test::linearizeAt(m, VecX::Zero(m.ndof())).K(0, 0);
  };
  test::expectMatchesReference(kCase, {{"Kg_tower", k11({}) - k11({"gravity=0"})}});
}

}  // namespace
}  // namespace whirl

// An equilibrium on a jump of the loads (linearize/load_jump.hpp): which pairs of Newton iterates
// straddle one, what the message says, and what the validity check accepts there.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "linearize/load_jump.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/point_validity.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/io/case/case_file.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

using testing::HasSubstr;

Model landbased() { return readCase((test::sourceDir() / "cases/landbased_2dof/landbased_2dof.yaml").string()); }

VecX vec(std::initializer_list<double> v) {
  VecX x(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double d : v) x(i++) = d;
  return x;
}

// Residuals of opposite sign on both coordinates, nearly antiparallel: zero lies between them.
TEST(LoadJump, OppositeResidualsStraddleAJump) {
  const std::vector<int> solved{3, 7};
  const VecX qa = vec({0.1, -0.0167534}), qb = vec({0.1, -0.0167427});
  const VecX ea = vec({0.02, -3.50903}), eb = vec({-0.02, 3.50965});
  const LoadJump j = loadJump(solved, qa, qb, ea, eb, nullptr, nullptr);
  EXPECT_EQ(j.dof, 7);  // the larger jump
  EXPECT_DOUBLE_EQ(j.below, -3.50903);
  EXPECT_DOUBLE_EQ(j.above, 3.50965);
  EXPECT_NEAR(j.size, (ea - eb).norm(), 1e-15);
  EXPECT_NEAR(j.span, 1.07e-5, 1e-12);
  EXPECT_EQ(j.element, -1);
}

// Zero not between them: both residuals push the same way (a Newton cycle of a smooth problem, or a
// jump that does not cross zero), or across but far from antiparallel.
TEST(LoadJump, ResidualsThatDoNotEncloseZeroAreNoJump) {
  const std::vector<int> solved{0, 1};
  const VecX q = vec({0, 0});
  EXPECT_EQ(loadJump(solved, q, q, vec({1.0, 2.0}), vec({3.0, 1.0}), nullptr, nullptr).dof, -1);
  EXPECT_EQ(loadJump(solved, q, q, vec({1.0, 1.0}), vec({-1.0, 0.5}), nullptr, nullptr).dof, -1);
  EXPECT_EQ(loadJump(solved, q, q, vec({1.0, 1.0}), vec({1.0, 1.0}), nullptr, nullptr).dof, -1);
  // 1 % of the jump off zero at the nearest combination is the limit.
  // (‖e_a − e_b‖ = 2, the nearest combination (0, 0.019) or (0, 0.021)).
  EXPECT_GE(loadJump(solved, q, q, vec({1.0, 0.019}), vec({-1.0, 0.019}), nullptr, nullptr).dof, 0);
  EXPECT_EQ(loadJump(solved, q, q, vec({1.0, 0.021}), vec({-1.0, 0.021}), nullptr, nullptr).dof, -1);
}

// The element whose loads changed most, and why: the zero-velocity limit of AeroDyn's BEMT.
TEST(LoadJump, NamesTheElementAndTheSwitch) {
  const Model m = landbased();
  AeroRecord a, b;
  a.elements.resize(3);
  b.elements.resize(3);
  a.elements[1].vx = -0.000999758;
  b.elements[1].vx = -0.00100019;
  b.elements[1].fx = 0.28;
  LoadJump j = loadJump({0, 1}, vec({0, 0}), vec({0, 1e-5}), vec({0.1, -3.5}), vec({-0.1, 3.5}), &a, &b);
  ASSERT_EQ(j.dof, 1);
  EXPECT_EQ(j.element, 1);
  const std::string text = describe(m, j);
  EXPECT_THAT(text, HasSubstr("the load on DOF '" + m.dofs[1].name + "' jumps from -3.5 to 3.5"));
  EXPECT_THAT(text, HasSubstr("across 1e-05"));
  // The model has no blades: the element is numbered over all of them.
  EXPECT_THAT(text, HasSubstr("rad: element 2 crosses AeroDyn's zero-velocity limit of its normal velocity"));
  EXPECT_THAT(text, HasSubstr("here -0.000999758 and -0.00100019 m/s"));
  b.elements[1].vx = a.elements[1].vx;
  b.elements[1].bem_valid = false;
  j = loadJump({0, 1}, vec({0, 0}), vec({0, 1e-5}), vec({0.1, -3.5}), vec({-0.1, 3.5}), &a, &b);
  EXPECT_THAT(describe(m, j), HasSubstr("loses its valid BEM inflow angle on one side"));
  b.elements[1].bem_valid = true;
  j = loadJump({0, 1}, vec({0, 0}), vec({0, 1e-5}), vec({0.1, -3.5}), vec({-0.1, 3.5}), &a, &b);
  EXPECT_THAT(describe(m, j), HasSubstr("switches between two BEM roots"));
}

// On a jump the residual left is one side's: the validity check accepts it up to the jump's size, not
// beyond.
TEST(LoadJump, ValidityAcceptsTheResidualOfOneSideOnly) {
  const Model m = landbased();
  OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  ASSERT_FALSE(op.solved.empty());
  op.residual_norm = 1e-3 * op.load_scale;
  EXPECT_THAT(checkPointValidity(m, op), testing::Contains(HasSubstr("equilibrium residual")));
  op.load_jump.dof = op.solved.front();
  op.load_jump.size = 2e-3 * op.load_scale;
  EXPECT_TRUE(checkPointValidity(m, op).empty());
  op.residual_norm = 3e-3 * op.load_scale;
  EXPECT_THAT(checkPointValidity(m, op), testing::Contains(HasSubstr("equilibrium residual")));
}

}  // namespace
}  // namespace whirl

// Frozen-wake AD passes chain each blade's preaccumulated derivatives (src/dynamics/aero_blade_jet.hxx)
// instead of evaluating its elements in the AD scalar. Cross-check of the two paths: the same seeded
// evaluation of the aerodynamic loads once through the blade jets and once element by element (an
// evaluation that accumulates rotor totals takes that path), with every coordinate, rate and input
// carrying a derivative — so every variable of the jet (frame rotation and height, elastic
// coordinates and rates, pitch, frame velocity and angular velocity, wind speed) is exercised.
#include <gtest/gtest.h>

#include <random>

#include "linearize/operating_point.hpp"
#include "src/dynamics/aero_loads.hxx"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/aero_rotor_model.hpp"

namespace whirl {
namespace {

// Values and derivatives of the generalized aerodynamic forces through both paths at op, with eight
// random directions seeded in q, q̇ and u (pitch inputs through the coordinates they drive).
void expectPathsAgree(const Model& m, const OperatingPoint& op, const AeroInflow& frozen) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  const int n = m.ndof();
  VecXT<ADChunk> q(n), qd(n), qdd(n), u(m.ninput());
  for (int i = 0; i < n; ++i) {
    q(i) = ADChunk(op.q(i), ADChunk::DerType::NullaryExpr([&](Eigen::Index) { return d(rng); }));
    qd(i) = ADChunk(op.qd(i), ADChunk::DerType::NullaryExpr([&](Eigen::Index) { return d(rng); }));
    qdd(i) = ADChunk(op.qdd(i), ADChunk::DerType::Zero());
  }
  for (int k = 0; k < m.ninput(); ++k)
    u(k) = ADChunk(op.u(k), ADChunk::DerType::NullaryExpr([&](Eigen::Index) { return d(rng); }));
  Workspace<ADChunk> ws(m);
  forwardKinematics(m, ws, q, qd, qdd);
  VecXT<ADChunk> jet = VecXT<ADChunk>::Constant(n, ADChunk(0.0, ADChunk::DerType::Zero()));
  VecXT<ADChunk> direct = jet;
  addAeroLoads(m, ws, q, u, &frozen, nullptr, jet);
  RotorTotals<ADChunk> totals;
  addAeroLoads(m, ws, q, u, &frozen, nullptr, direct, 0, &totals);
  double scale = 0, value_scale = 0;
  for (int i = 0; i < n; ++i) {
    scale = std::max(scale, direct(i).derivatives().cwiseAbs().maxCoeff());
    value_scale = std::max(value_scale, std::abs(direct(i).value()));
  }
  ASSERT_GT(scale, 0.0);
  for (int i = 0; i < n; ++i) {
    // Both are exact first derivatives: they differ by round-off (orders of 1e-16 of the largest).
    EXPECT_NEAR(jet(i).value(), direct(i).value(), 1e-12 * value_scale) << m.dofs[i].name;
    for (int k = 0; k < kChunk; ++k)
      EXPECT_NEAR(jet(i).derivatives()(k), direct(i).derivatives()(k), 1e-11 * scale)
          << m.dofs[i].name << ", direction " << k;
  }
  // The second call at the same point reuses the jets: still the same.
  VecXT<ADChunk> again = VecXT<ADChunk>::Constant(n, ADChunk(0.0, ADChunk::DerType::Zero()));
  addAeroLoads(m, ws, q, u, &frozen, nullptr, again);
  for (int i = 0; i < n; ++i) EXPECT_EQ((again(i).derivatives() - jet(i).derivatives()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(AeroBladeJet, EqualsTheElementPathOnAShearedRotorWithDeflectedBlades) {
  Model m = test::aeroRotorModel();
  m.aero.wind.shear_exponent = 0.2;  // the frame height enters through the shear
  m.aero.wind.upflow = 0.05;
  OperatingPoint op = initialPoint(m);
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].kind == DofKind::Elastic) {
      op.q(i) = 0.3 + 0.05 * i;
      op.qd(i) = 0.2 - 0.03 * i;
    }
  op.q(*m.findDof("azimuth")) = 0.4;
  Workspace<double> ws(m);
  VecX e(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
  expectPathsAgree(m, op, rec.inflow());
}

TEST(AeroBladeJet, EqualsTheElementPathOnTheNrel5mwDeckAtItsOperatingPoint) {
  // Tower, yaw and drivetrain coordinates turn and move the blade frames (the δθ, v, ω variables).
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst");
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  ASSERT_FALSE(op.inflow.empty());
  expectPathsAgree(m, op, op.inflow);
}

}  // namespace
}  // namespace whirl

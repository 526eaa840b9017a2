// The general engine on the uniform tower with a top mass [Branlard2019, §5.1], built in code:
// analytic Mq, Kq and geometric-stiffness ratios for u0 = 1 − cos(πx/2L).
#include <gtest/gtest.h>

#include <numbers>

#include "linearize/linearize.hpp"
#include "src/base/error.hpp"
#include "src/shapes/beam.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double L = 100, EI = 2e12, mpl = 9e3, g = 9.81;

Model tower(double Mt, double gravity) {
  BeamProperties p;
  p.length = L;
  p.x = VecX::LinSpaced(2, 0, L);
  p.m = VecX::Constant(2, mpl);
  p.EIy = VecX::Constant(2, EI);
  p.EIz = VecX::Constant(2, EI);
  std::vector<ShapePtr> shapes{oneMinusCosShape("tower FA 1", L, 0, 1)};
  BeamOptions opt;
  opt.integration = {BeamIntegration::Gauss, 60};
  BeamBody bb = buildBeamBody(p, shapes, opt, "tower");
  Model m;
  m.gravity = Vec3(-gravity, 0, 0);  // tower along +x, gravity down the tower
  Body t;
  t.name = "tower";
  t.inertia = bb.inertia;
  t.elastic = bb.elastic;
  t.points.push_back(beamPoint(p, shapes, true, L, "top"));
  m.bodies.push_back(t);
  Body top;
  top.name = "top mass";
  top.parent = 0;
  top.parent_point = 0;
  top.inertia = rigidBodyInertia(Mt, Vec3::Zero(), Mat3::Zero());
  m.bodies.push_back(top);
  Dof d;
  d.name = "tower FA 1";
  d.kind = DofKind::Elastic;
  d.body = 0;
  m.dofs.push_back(d);
  finalize(m);
  return m;
}

LinearModel lin(const Model& m) { return linearize(m, solveOperatingPoint(m, initialPoint(m))); }

TEST(TowerTopMass, MassAndStiffnessMatchSeed000Sec51) {
  const double Mt = 0;  // beam alone
  const LinearModel l = lin(tower(Mt, 0.0));
  // [Branlard2019, §5.1]: Mq = m L (3π − 8)/(2π), Kq = EI π⁴/(32 L³) (exact).
  EXPECT_NEAR(l.M(0, 0), mpl * L * (3 * pi - 8) / (2 * pi), 1e-9 * l.M(0, 0));
  EXPECT_NEAR(l.K(0, 0), EI * pow(pi, 4) / (32 * pow(L, 3)), 1e-9 * l.K(0, 0));
}

TEST(TowerTopMass, GeometricStiffnessRatiosMatchSeed000Sec51) {
  const double Kq = EI * pow(pi, 4) / (32 * pow(L, 3));
  const double Pcr = pi * pi * EI / (4 * L * L);
  const double M = mpl * L;
  for (double ratio : {0.1, 0.5, 1.0, 2.0}) {
    const double Mt = ratio * M;
    const double Kg = lin(tower(Mt, g)).K(0, 0) - lin(tower(Mt, 0.0)).K(0, 0);
    // K_T/Kq = −Mt g/Pcr (top mass) − (M g/Pcr)(1/2 − 2/π²) (self weight), [Branlard2019, §5.1] (exact).
    const double expected = -Mt * g / Pcr - (M * g / Pcr) * (0.5 - 2 / (pi * pi));
    EXPECT_NEAR(Kg / Kq, expected, 1e-9) << "Mt/M = " << ratio;
  }
}

}  // namespace
}  // namespace whirl

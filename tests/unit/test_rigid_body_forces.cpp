// A rigid body's inertia forces three ways: rigidFrameForces (the residual's path for ne = 0), the
// general two-stage path (basisProducts + frameForces at c = [1]) and Newton–Euler about the body
// origin, F = −m (â + α × ρ + ω × (ω × ρ)), T = −(J_O α + ω × J_O ω + m ρ × â), with ρ the centre of
// mass and J_O = tr(Θ) 1 − Θ from the second moment Θ_jl = S_jl [BranlardGeisler2022, App. A].
#include <gtest/gtest.h>

#include "src/dynamics/body_forces.hxx"
#include "src/dynamics/workspace.hpp"

using namespace whirl;

namespace {

// A rigid body of mass m with its centre of mass at rho and a second moment about the origin that is
// that of the point mass plus a positive-definite central part.
BodyInertia rigidBody(double m, const Vec3& rho) {
  BodyInertia in;
  in.mass = m;
  in.m1 = Mat3X(3, 1);
  in.m1.col(0) = m * rho;
  Mat3 central;
  central << 40, 3, -2, 3, 25, 1.5, -2, 1.5, 60;
  const Mat3 theta = m * rho * rho.transpose() + central;
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l) in.S[3 * j + l] = MatX::Constant(1, 1, theta(j, l));
  in.len = {1, 1, 1};  // as finalize sets them: every direction uses the constant
  return in;
}

}  // namespace

TEST(RigidBodyForces, EqualTheGeneralPathAndNewtonEuler) {
  const double m = 1234.5;
  const Vec3 rho(0.7, -1.3, 2.1);
  const BodyInertia in = rigidBody(m, rho);
  const Vec3 ahat(0.4, -9.3, 1.7), alpha(0.21, -0.05, 0.33), omega(1.1, 0.4, -0.8);

  Vec3 F, T;
  rigidFrameForces(in, ahat, alpha, omega, F, T);

  // The general path at c = [1], ċ = c̈ = 0.
  BasisProducts<double, double> p(1);
  const VecX c = VecX::Ones(1), zero = VecX::Zero(1);
  basisProducts(in, c, zero, zero, p);
  VecX G(1);
  Vec3 Fg, Tg;
  frameForces(in, p, MatX(1, 0), ahat, alpha, omega, G, Fg, Tg, static_cast<decltype(&G(0))>(nullptr));
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(F(k), Fg(k), 1e-12 * Fg.norm()) << k;
    EXPECT_NEAR(T(k), Tg(k), 1e-12 * Tg.norm()) << k;
  }

  // Newton–Euler about the origin.
  Mat3 theta;
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l) theta(j, l) = in.S[3 * j + l](0, 0);
  const Mat3 J = theta.trace() * Mat3::Identity() - theta;
  const Vec3 Fne = -m * (ahat + alpha.cross(rho) + omega.cross(omega.cross(rho)));
  const Vec3 Tne = -(J * alpha + omega.cross(J * omega) + m * rho.cross(ahat));
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(F(k), Fne(k), 1e-11 * Fne.norm()) << k;
    EXPECT_NEAR(T(k), Tne(k), 1e-11 * Tne.norm()) << k;
  }
}

TEST(RigidBodyForces, DerivativesEqualTheGeneralPaths) {
  const BodyInertia in = rigidBody(56780, Vec3(0.1, 0.2, -0.4));
  // â, α, ω seeded in the chunk's first directions, as an AD pass of the residual would.
  auto seeded = [](const Vec3& v, int d0) {
    Vec3T<ADChunk> s;
    for (int k = 0; k < 3; ++k) {
      s(k) = ADChunk(v(k), ADChunk::DerType::Zero());
      if (d0 + k < kChunk) s(k).derivatives()(d0 + k) = 1;
    }
    return s;
  };
  const Vec3T<ADChunk> ahat = seeded(Vec3(0.3, 9.81, -0.2), 0), alpha = seeded(Vec3(0.02, 0.5, -0.1), 3),
                       omega = seeded(Vec3(1.27, -0.03, 0.08), 6);
  Vec3T<ADChunk> F, T, Fg, Tg;
  rigidFrameForces(in, ahat, alpha, omega, F, T);
  BasisProducts<double, double> p(1);
  const VecX c = VecX::Ones(1), zero = VecX::Zero(1);
  basisProducts(in, c, zero, zero, p);
  VecXT<ADChunk> G(1);
  frameForces(in, p, MatX(1, 0), ahat, alpha, omega, G, Fg, Tg, static_cast<decltype(&G(0))>(nullptr));
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(F(k).value(), Fg(k).value(), 1e-12 * std::abs(Fg(k).value()) + 1e-9) << k;
    EXPECT_NEAR(T(k).value(), Tg(k).value(), 1e-12 * std::abs(Tg(k).value()) + 1e-9) << k;
    for (int d = 0; d < kChunk; ++d) {
      EXPECT_NEAR(F(k).derivatives()(d), Fg(k).derivatives()(d), 1e-9 * (1 + std::abs(Fg(k).derivatives()(d))))
          << k << d;
      EXPECT_NEAR(T(k).derivatives()(d), Tg(k).derivatives()(d), 1e-9 * (1 + std::abs(Tg(k).derivatives()(d))))
          << k << d;
    }
  }
}

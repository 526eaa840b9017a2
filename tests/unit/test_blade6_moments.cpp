// Bending moments of an FE blade per modal coordinate (src/fem/blade6_moments.hpp), from the elements'
// stress resultants: a uniform cantilever's first flap and edge modes against the closed form (Euler–
// Bernoulli, the shear stiffness made large), at the root and at mid-span, converging with the mesh —
// where the second difference of the tabulated displacements (beamMomentGains of the modes as shapes)
// gives about half the root moment.
#include <gtest/gtest.h>

#include <cmath>

#include "src/fem/blade6_body.hpp"
#include "src/fem/blade6_moments.hpp"
#include "src/shapes/beam_moment.hpp"

namespace whirl {
namespace {

constexpr double kLength = 40, kEIflap = 4e9, kEIedge = 1e10;

// m 300 kg/m; K44 = EI about x_r (edgewise bending, body z), K55 = EI about y_r (flapwise, body y).
fem::Blade6Body uniformBlade(int elements) {
  fem::Blade6Input in;
  for (double z : {0.0, kLength / 2, kLength}) {
    fem::Blade6KeyPoint k;
    k.r = Vec3(0, 0, z);
    in.key_points.push_back(k);
  }
  for (double eta : {0.0, 1.0}) {
    fem::Blade6Station s;
    s.eta = eta;
    s.K.diagonal() << 1e12, 1e12, 1e12, kEIedge, kEIflap, 1e12;
    s.M.diagonal() << 300, 300, 300, 0, 0, 10;
    in.stations.push_back(s);
  }
  fem::Blade6Options o;
  o.elements = elements;
  o.modes = 2;
  return fem::blade6Body(in, o);
}

// EI φ''(ξL) / φ(L) of a clamped-free beam's first mode (Blevins 1979, Table 8-1: β₁L = 1.87510407,
// φ = cosh βx − cos βx − σ (sinh βx − sin βx), σ = 0.734095514): the moment per metre of tip deflection.
double exactMoment(double EI, double xi) {
  const double b = 1.87510407, s = 0.734095514;
  const auto phi = [&](double x) {
    return std::cosh(b * x) - std::cos(b * x) - s * (std::sinh(b * x) - std::sin(b * x));
  };
  const double d2 = std::cosh(b * xi) + std::cos(b * xi) - s * (std::sinh(b * xi) + std::sin(b * xi));
  return EI * b * b / (kLength * kLength) * d2 / phi(1.0);
}

// The columns of the flap 1 and edge 1 modes (by name) and their tip values.
struct Columns {
  int flap = -1, edge = -1;
};
Columns columns(const fem::Blade6Body& b) {
  Columns c;
  for (int j = 0; j < static_cast<int>(b.shapes.size()); ++j) {
    if (b.shapes[static_cast<std::size_t>(j)]->name == "flap 1") c.flap = j;
    if (b.shapes[static_cast<std::size_t>(j)]->name == "edge 1") c.edge = j;
  }
  return c;
}

TEST(Blade6Moments, UniformCantileverFirstModesMatchTheClosedForm) {
  double previous_root_error = 1;
  for (int elements : {20, 40}) {
    const fem::Blade6Body b = uniformBlade(elements);
    const Columns c = columns(b);
    ASSERT_GE(c.flap, 0);
    ASSERT_GE(c.edge, 0);
    // The modes are scaled to a tip deflection of 1 m.
    ASSERT_NEAR(b.shapes[static_cast<std::size_t>(c.flap)]->eval(kLength).uy, 1.0, 1e-12);
    ASSERT_NEAR(b.shapes[static_cast<std::size_t>(c.edge)]->eval(kLength).uz, 1.0, 1e-12);
    const MatX root = fem::blade6MomentGains(b, 0.0), mid = fem::blade6MomentGains(b, kLength / 2);
    const double flap0 = exactMoment(kEIflap, 0), edge0 = exactMoment(kEIedge, 0);
    const double flap_mid = exactMoment(kEIflap, 0.5), edge_mid = exactMoment(kEIedge, 0.5);
    // Linear elements: errors as h² (measured: 4.9e-4 at the root and 4.3e-4 at mid-span with 20
    // elements, 1.2e-4 and 1.0e-4 with 40).
    const double tol = 2e-3 * std::pow(20.0 / elements, 2);
    EXPECT_NEAR(root(0, c.flap), flap0, tol * flap0) << elements;
    EXPECT_NEAR(root(1, c.edge), edge0, tol * edge0) << elements;
    EXPECT_NEAR(mid(0, c.flap), flap_mid, tol * flap_mid) << elements;
    EXPECT_NEAR(mid(1, c.edge), edge_mid, tol * edge_mid) << elements;
    // Each mode bends in its own plane only.
    EXPECT_NEAR(root(1, c.flap), 0, 1e-9 * flap0);
    EXPECT_NEAR(root(0, c.edge), 0, 1e-9 * edge0);
    const double root_error = std::abs(root(0, c.flap) / flap0 - 1);
    EXPECT_LT(root_error, previous_root_error);
    previous_root_error = root_error;
  }
  // What the tabulated shapes' second difference gives at the root: 0.47 of it (why the resultants are used).
  const fem::Blade6Body b = uniformBlade(20);
  const MatX from_shapes = beamMomentGains(b.props, b.shapes, 0.0);
  EXPECT_LT(from_shapes(0, columns(b).flap), 0.6 * exactMoment(kEIflap, 0));
}

}  // namespace
}  // namespace whirl

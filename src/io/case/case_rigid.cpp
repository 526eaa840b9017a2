// Rigid bodies of a case: mass, centre of gravity, inertia at the COG and points.
#include "src/io/case/case_reader.hpp"

namespace whirl {
namespace {

// Inertia tensor at the COG: [Jxx, Jyy, Jzz], a 3×3 matrix, or {xx, yy, zz, xy, xz, yz}
// (the off-diagonal entries of the tensor, I_xy = −∫ x y dm).
Mat3 readInertia(const CaseNode& n) {
  Mat3 J = Mat3::Zero();
  if (n.isMap()) {
    n.allowKeys({"xx", "yy", "zz", "xy", "xz", "yz"});
    J(0, 0) = n.number("xx", 0);
    J(1, 1) = n.number("yy", 0);
    J(2, 2) = n.number("zz", 0);
    J(0, 1) = J(1, 0) = n.number("xy", 0);
    J(0, 2) = J(2, 0) = n.number("xz", 0);
    J(1, 2) = J(2, 1) = n.number("yz", 0);
  } else if (n.isList() && n.yaml().size() == 3 && n.yaml()[0].IsScalar()) {
    const Vec3 d = n.vec3();
    J = d.asDiagonal();
  } else {
    J = n.matrix(3, 3);
    if ((J - J.transpose()).norm() > 1e-9 * std::max(1.0, J.norm())) n.fail("the inertia matrix is not symmetric");
  }
  // The rigid-body mass matrix needs J positive semi-definite. Lumped models (ElastoDyn's nacelle
  // with only a yaw inertia, the nacelle of [Branlard2019, §6]) may break the triangle inequality of a
  // real mass distribution; that is accepted.
  const Vec3 pm = Eigen::SelfAdjointEigenSolver<Mat3>(J).eigenvalues();
  if (pm.minCoeff() < -1e-9 * std::max(1.0, J.trace()))
    n.fail("the inertia tensor is not positive semi-definite: principal moments " + num(pm(0)) + ", " + num(pm(1)) +
           ", " + num(pm(2)) + " kg m² (each must be ≥ 0)");
  return J;
}

}  // namespace

void readRigidBody(const CaseNode& n, Body& b) {
  double mass = 0;
  if (const auto m = n.find("mass")) {
    mass = m->number();
    if (mass < 0) m->fail("negative mass " + num(mass) + " kg");
  }
  const Vec3 cog = n.vec3("cog", Vec3::Zero());
  const auto in = n.find("inertia");
  b.inertia = rigidBodyInertia(mass, cog, in ? readInertia(*in) : Mat3::Zero());
  if (const auto pts = n.find("points"))
    for (const CaseNode& p : pts->items()) {
      p.allowKeys({"name", "position"});
      BodyPoint bp;
      bp.name = p.at("name").text();
      for (const auto& q : b.points)
        if (q.name == bp.name) p.at("name").fail("point name '" + bp.name + "' used twice in body '" + b.name + "'");
      const Vec3 pos = p.at("position").vec3();
      bp.P = Mat3X::Zero(3, 1);
      for (int k = 0; k < 3; ++k) bp.P(k, 0) = pos(k);
      bp.theta = Mat3X::Zero(3, 0);
      b.points.push_back(bp);
    }
}

}  // namespace whirl

#pragma once
// A three-bladed rotor on a hub turning at a prescribed speed (rigid support), each blade a
// uniform beam with one flap and one edge shape: in multiblade coordinates its cyclic modes sit
// exactly at the rotating-frame frequency ∓ Ω (undamped, isotropic rotor).
#include <numbers>

#include "src/model/model.hpp"
#include "src/shapes/beam.hpp"

namespace whirl::test {

inline Model rotorModel(double rpm, int nblades = 3) {
  using std::numbers::pi;
  Model m;
  m.gravity.setZero();
  Body hub;
  hub.name = "hub";
  hub.joint = JointType::Revolute;
  hub.axis = Vec3::UnitX();
  hub.inertia = rigidBodyInertia(1e4, Vec3::Zero(), Mat3(Vec3(1e4, 5e3, 5e3).asDiagonal()));
  BodyPoint root;
  root.name = "root";
  root.P = Vec3(0, 0, 1.5);
  root.theta = Mat3X::Zero(3, 0);
  hub.points.push_back(root);
  m.bodies.push_back(hub);
  BeamProperties p;
  p.length = 40;
  p.x = VecX::LinSpaced(2, 0, 40);
  p.m = VecX::Constant(2, 300);
  p.EIy = VecX::Constant(2, 4e9);
  p.EIz = VecX::Constant(2, 1e9);
  std::vector<ShapePtr> shapes{clampedTopMassShape("flap 1", 40, 1, 0, 0, 1),
                               clampedTopMassShape("edge 1", 40, 1, 0, 1, 0)};
  BeamOptions opt;
  opt.integration = {BeamIntegration::Gauss, 40};
  const BeamBody bb = buildBeamBody(p, shapes, opt, "blade");
  Dof az;
  az.name = "azimuth";
  az.body = 0;
  az.frozen = true;
  az.rotating = true;
  az.rate = rpm * 2 * pi / 60;
  m.dofs.push_back(az);
  for (int b = 0; b < nblades; ++b) {
    Body bl;
    bl.name = "blade " + std::to_string(b + 1);
    bl.parent = 0;
    // Blade b at +2πb/N about the shaft: radial body x, flap body z along the shaft.
    const Mat3 place = Eigen::AngleAxisd(2 * pi * b / nblades, Vec3::UnitX()).toRotationMatrix();
    Mat3 axes;
    axes << 0, 0, 1, 0, -1, 0, 1, 0, 0;  // columns: blade x = hub z, blade y = −hub y, blade z = hub x
    bl.offset = place * Vec3(0, 0, 1.5);
    bl.rotation = place * axes;
    bl.inertia = bb.inertia;
    bl.elastic = bb.elastic;
    m.bodies.push_back(bl);
    for (int k = 0; k < 2; ++k) {
      Dof d;
      d.name = bl.name + " " + shapes[k]->name;
      d.kind = DofKind::Elastic;
      d.body = b + 1;
      d.local = k;
      d.blade = b;
      m.dofs.push_back(d);
    }
  }
  finalize(m);
  return m;
}

}  // namespace whirl::test

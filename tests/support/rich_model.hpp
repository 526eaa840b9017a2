#pragma once
// A deliberately rich model for cross-checks: floating platform (free joint), tower with FA, SS and
// torsion shapes, nacelle with a full inertia tensor, tilted rotating shaft, three twisted, pre-bent
// blades with COG offsets, polar inertia and coupled shapes, point loads on inputs, springs,
// 6×6 platform matrices. Every term of the residual is exercised.
#include <numbers>

#include "src/model/model.hpp"
#include "src/shapes/beam.hpp"

namespace whirl::test {

inline Model richModel(bool axial_shortening = true) {
  using std::numbers::pi;
  Model m;
  m.gravity = Vec3(0.3, -0.2, -9.81);
  const auto input = [](const char* name, double value) {
    Input u;
    u.name = name;
    u.value = value;
    return u;
  };
  m.inputs = {input("thrust", 1.2e5), input("torque", 3e5)};

  Body plat;
  plat.name = "platform";
  plat.joint = JointType::Free;
  plat.inertia = rigidBodyInertia(5e6, Vec3(0.1, -0.2, -10),
                                  (Mat3() << 4e9, 1e7, 2e7, 1e7, 5e9, 3e7, 2e7, 3e7, 6e9).finished());
  BodyPoint base;
  base.name = "tower base";
  base.P = Vec3(0.5, 0.2, 10);
  base.theta = Mat3X::Zero(3, 0);
  plat.points.push_back(base);
  m.bodies.push_back(plat);

  BeamProperties tp;
  tp.length = 80;
  tp.x = VecX::LinSpaced(5, 0, 80);
  tp.m = (VecX(5) << 5000, 4500, 4000, 3500, 3000).finished();
  tp.EIy = VecX::LinSpaced(5, 5e11, 1e11);
  tp.EIz = VecX::LinSpaced(5, 6e11, 1.2e11);
  tp.GKt = VecX::LinSpaced(5, 4e11, 1e11);
  tp.jG = VecX::LinSpaced(5, 2e4, 5e3);
  std::vector<ShapePtr> ts{polynomialShape("tower FA 1", 80, {0, 0, 0.7, 2.2, -5.6, 6.2, -2.5}, 0, 1),
                           polynomialShape("tower SS 1", 80, {0, 0, 0.9, 1.2, -2.6, 2.2, -0.7}, 1, 0),
                           torsionSineShape("tower torsion", 80, 1)};
  BeamOptions to;
  to.axial_shortening = axial_shortening;
  to.integration = {BeamIntegration::Gauss, 20};
  to.damping.kind = BeamDamping::ModalRatio;
  to.damping.ratio = {0.01, 0.01, 0.02};
  BeamBody tb = buildBeamBody(tp, ts, to, "tower");
  Body tower;
  tower.name = "tower";
  tower.parent = 0;
  tower.parent_point = 0;
  tower.rotation = Eigen::AngleAxisd(-pi / 2, Vec3::UnitY()).toRotationMatrix();  // body x up
  tower.inertia = tb.inertia;
  tower.elastic = tb.elastic;
  tower.points.push_back(beamPoint(tp, ts, axial_shortening, 80, "top"));
  tower.points.push_back(beamPoint(tp, ts, axial_shortening, 40, "mid"));
  m.bodies.push_back(tower);

  Body nac;
  nac.name = "nacelle";
  nac.parent = 1;
  nac.parent_point = 0;
  nac.rotation = Eigen::AngleAxisd(pi / 2, Vec3::UnitY()).toRotationMatrix();  // back to ground axes
  nac.joint = JointType::Revolute;
  nac.axis = Vec3::UnitZ();  // yaw
  nac.inertia = rigidBodyInertia(2.4e5, Vec3(1.9, 0.1, 1.75),
                                 (Mat3() << 1e6, 2e4, 3e4, 2e4, 2.6e6, 1e4, 3e4, 1e4, 2.6e6).finished());
  BodyPoint shaft;
  shaft.name = "shaft";
  shaft.P = Vec3(-5.0, 0.0, 2.4);
  shaft.theta = Mat3X::Zero(3, 0);
  nac.points.push_back(shaft);
  m.bodies.push_back(nac);

  Body hub;
  hub.name = "hub";
  hub.parent = 2;
  hub.parent_point = 0;
  hub.rotation = Eigen::AngleAxisd(-5 * pi / 180, Vec3::UnitY()).toRotationMatrix();  // tilt
  hub.joint = JointType::Revolute;
  hub.axis = Vec3::UnitX();
  hub.inertia = rigidBodyInertia(5.6e4, Vec3(0.1, 0, 0), Mat3(Vec3(1.2e5, 6e4, 6e4).asDiagonal()));
  for (int b = 0; b < 3; ++b) {
    BodyPoint root;
    root.name = "root " + std::to_string(b + 1);
    const double psi = 2 * pi * b / 3;
    root.P = Vec3(0, -1.5 * std::sin(psi), 1.5 * std::cos(psi));
    root.theta = Mat3X::Zero(3, 0);
    hub.points.push_back(root);
  }
  m.bodies.push_back(hub);

  BeamProperties bp;
  bp.length = 61.5;
  bp.x = VecX::LinSpaced(6, 0, 61.5);
  bp.m = (VecX(6) << 700, 450, 350, 250, 150, 30).finished();
  bp.EIy = VecX::LinSpaced(6, 1e10, 1e8);
  bp.EIz = VecX::LinSpaced(6, 2e10, 5e7);
  bp.GKt = VecX::LinSpaced(6, 5e9, 1e7);
  bp.jG = VecX::LinSpaced(6, 200, 5);
  bp.twist = VecX::LinSpaced(6, 0.23, 0.0);
  bp.z0 = (VecX(6) << 0, 0.1, 0.3, 0.6, 1.0, 1.5).finished();
  bp.cgy = VecX::LinSpaced(6, 0.2, 0.05);
  bp.cgz = VecX::LinSpaced(6, -0.1, 0.0);
  std::vector<ShapePtr> bs{polynomialShape("flap 1", 61.5, {0, 0, 0.06, 1.7, -2.0, 1.7, -0.5}, 0.1, 1),
                           polynomialShape("edge 1", 61.5, {0, 0, 0.36, 0.73, -0.5, 0.5, -0.1}, 1, -0.1),
                           polynomialShape("flap 2", 61.5, {0, 0, -0.6, 1.4, 3.4, -5.3, 2.1}, 0, 1),
                           torsionSineShape("torsion", 61.5, 1)};
  BeamOptions bo;
  bo.axial_shortening = axial_shortening;
  bo.integration = {BeamIntegration::Gauss, 16};
  bo.damping.kind = BeamDamping::StiffnessProportional;
  bo.damping.beta = 0.003;
  BeamBody bb = buildBeamBody(bp, bs, bo, "blade");
  for (int b = 0; b < 3; ++b) {
    Body bl;
    bl.name = "blade " + std::to_string(b + 1);
    bl.parent = 3;
    bl.parent_point = b;
    const double psi = 2 * pi * b / 3;
    // Blade x radial, precone 2.5°.
    bl.rotation = (Eigen::AngleAxisd(psi, Vec3::UnitX()) * Eigen::AngleAxisd(-pi / 2, Vec3::UnitY()) *
                   Eigen::AngleAxisd(0.0436, Vec3::UnitY()))
                      .toRotationMatrix();
    bl.joint = JointType::Revolute;  // pitch
    bl.axis = Vec3::UnitX();
    bl.inertia = bb.inertia;
    bl.elastic = bb.elastic;
    bl.points.push_back(beamPoint(bp, bs, axial_shortening, 61.5, "tip"));
    m.bodies.push_back(bl);
  }
  // High-speed-shaft generator geared to the azimuth (a coordinate shared by two bodies).
  Body gen;
  gen.name = "generator";
  gen.parent = 2;
  gen.parent_point = 0;
  gen.rotation = hub.rotation;
  gen.joint = JointType::Revolute;
  gen.axis = Vec3::UnitX();
  gen.joint_follows = 3;
  gen.joint_ratio = 97.0;
  gen.inertia = rigidBodyInertia(100.0, Vec3(0.2, 0.01, 0), Mat3(Vec3(534.1, 300, 300).asDiagonal()));
  m.bodies.push_back(gen);
  auto dof = [&](const std::string& name, int body, DofKind kind, int local) {
    Dof d;
    d.name = name;
    d.body = body;
    d.kind = kind;
    d.local = local;
    m.dofs.push_back(d);
  };
  const char* plat_names[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw angle"};
  for (int k = 0; k < 6; ++k) dof(plat_names[k], 0, DofKind::Joint, k);
  for (int k = 0; k < 3; ++k) dof(ts[k]->name, 1, DofKind::Elastic, k);
  dof("yaw", 2, DofKind::Joint, 0);
  dof("azimuth", 3, DofKind::Joint, 0);
  for (int b = 0; b < 3; ++b) {
    dof("pitch " + std::to_string(b + 1), 4 + b, DofKind::Joint, 0);
    for (int k = 0; k < 4; ++k) dof("blade " + std::to_string(b + 1) + " " + bs[k]->name, 4 + b, DofKind::Elastic, k);
  }
  PointLoad thrust;
  thrust.body = 3;
  thrust.force = Vec3(1, 0.1, 0);
  thrust.moment = Vec3(0.2, 0, 0);
  thrust.input = 0;
  m.point_loads.push_back(thrust);
  PointLoad tip;
  tip.body = 4;
  tip.point = 0;
  tip.force = Vec3(10, 300, 2000);
  tip.moment = Vec3(500, 20, 10);
  m.point_loads.push_back(tip);
  PointLoad wind;
  wind.body = 1;
  wind.point = 1;
  wind.force = Vec3(0, 0, 1e4);
  wind.body_frame = false;
  m.point_loads.push_back(wind);
  m.dof_loads.push_back({0, 0, -1});
  m.springs.push_back({0, 9e9, 2e7, 0.0});
  BodyMatrices bm;
  bm.body = 0;
  bm.K.diagonal() << 4e4, 4e4, 3e5, 1e9, 1e9, 1e8;
  bm.C.diagonal() << 1e5, 1e5, 1e5, 1e7, 1e7, 1e7;
  bm.A.diagonal() << 1e6, 1e6, 2e6, 1e8, 1e8, 1e7;
  m.body_matrices.push_back(bm);
  finalize(m);
  m.dof_loads[0].dof = *m.findDof("azimuth");
  m.dof_loads[0].input = 1;
  m.dof_loads[0].value = 1.0;
  m.springs[0].dof = *m.findDof("yaw");
  return m;
}

}  // namespace whirl::test

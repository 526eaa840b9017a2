// Yaw bearing, nacelle, generator and hub of the ElastoDyn turbine (ElastoDyn `SetCoordSy`,
// `CalculatePositions`: points O, U, V, P = Q, C; frames d, c, e/g).
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/turbine/elastodyn_parts.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

}  // namespace

DrivetrainParts addNacelleAndDrivetrain(Builder& b, const TowerParts& tower) {
  const io::ElastoDynInput& ed = b.ed;
  const io::ElastoDynConfiguration& c = ed.config;
  const io::ElastoDynMassInertia& m = ed.mass;
  DrivetrainParts out;

  // Back from the tower body axes (x up, y = −Y, z = X) to ground axes; the rotation is its own inverse.
  Mat3 to_ground;
  to_ground.col(0) = Vec3::UnitZ();
  to_ground.col(1) = -Vec3::UnitY();
  to_ground.col(2) = Vec3::UnitX();

  Body bearing;
  bearing.name = "yaw bearing";
  bearing.parent = tower.body;
  bearing.parent_point = tower.top;
  bearing.rotation = to_ground;
  bearing.inertia = rigidBodyInertia(m.YawBrMass, Vec3::Zero(), Mat3::Zero());
  out.bearing = b.addBody(std::move(bearing));

  // Nacelle: ElastoDyn keeps only its inertia about the yaw axis d2, taken at the nacelle CM.
  const Vec3 cm(c.NacCMxn, c.NacCMyn, c.NacCMzn);
  const double offaxis = m.NacMass * (c.NacCMxn * c.NacCMxn + c.NacCMyn * c.NacCMyn);
  const double Jd2 = m.NacYIner - offaxis;
  if (Jd2 < 0)
    throw InputError(b.where("NacYIner", "must not be less than NacMass·(NacCMxn² + NacCMyn²) = " +
                                             std::to_string(offaxis) + " kg m²"));
  // The nacelle turns on the yaw bearing: its frame starts from the bearing's (the tower top's
  // deflection and small rotations evaluated once per kinematics pass, not once per body).
  Body nac;
  nac.name = "nacelle";
  nac.parent = out.bearing;
  nac.joint = JointType::Revolute;
  nac.axis = Vec3::UnitZ();
  nac.inertia = rigidBodyInertia(m.NacMass, cm, Mat3(Vec3(0, 0, Jd2).asDiagonal()));
  out.nacelle = b.addBody(std::move(nac));
  out.yaw = b.addDof("yaw", out.nacelle, DofKind::Joint, 0, ed.dof.YawDOF, ed.init.NacYaw * deg);

  // Low-speed shaft: on the shaft axis c1 = (cos ShftTilt, 0, sin ShftTilt) where it meets the yaw
  // axis, Twr2Shft above the tower top; turns with the generator azimuth (LSS side), massless.
  Body lss;
  lss.name = "low-speed shaft";
  lss.parent = out.nacelle;
  lss.offset = Vec3(0, 0, c.Twr2Shft);
  lss.rotation = axisRotation(1, -c.ShftTilt * deg);
  lss.joint = JointType::Revolute;
  lss.axis = Vec3::UnitX();
  lss.inertia = rigidBodyInertia(0.0, Vec3::Zero(), Mat3::Zero());
  out.shaft = b.addBody(std::move(lss));
  // Azimuth 0 = blade 1 up (ElastoDyn's internal azimuth is this minus 90°); AzimB1Up is I/O only.
  out.generator_azimuth = b.addDof("generator azimuth", out.shaft, DofKind::Joint, 0, ed.dof.GenDOF,
                                   (ed.init.Azimuth - c.AzimB1Up) * deg, ed.init.RotSpeed * std::numbers::pi / 30.0);
  b.model().dofs[out.generator_azimuth].rotating = true;
  // Generator on the high-speed shaft, geared to the generator azimuth at GBRatio: its kinetic energy
  // ½ GenIner (ω_c + GBRatio θ̇)² is ElastoDyn's, nacelle roll and gyroscopic terms included.
  Body gen;
  gen.name = "generator";
  gen.parent = out.nacelle;
  gen.offset = Vec3(0, 0, c.Twr2Shft);
  gen.rotation = axisRotation(1, -c.ShftTilt * deg);
  gen.joint = JointType::Revolute;
  gen.axis = Vec3::UnitX();
  gen.joint_follows = out.shaft;
  gen.joint_ratio = ed.drivetrain.GBRatio;
  gen.inertia = rigidBodyInertia(0.0, Vec3::Zero(), Mat3(Vec3(m.GenIner, 0, 0).asDiagonal()));
  out.generator = b.addBody(std::move(gen));

  // Hub at the rotor apex (OverHang along the shaft), turning by the drivetrain twist. With 2 blades
  // OverHang reaches the teeter pin instead, and the hub's mass teeters (elastodyn_teeter.cpp).
  Body hub;
  hub.name = "hub";
  hub.parent = out.shaft;
  hub.offset = Vec3(c.OverHang, 0, 0);
  hub.joint = JointType::Revolute;
  hub.axis = Vec3::UnitX();
  hub.inertia = c.NumBl == 2
                    ? rigidBodyInertia(0.0, Vec3::Zero(), Mat3::Zero())
                    : rigidBodyInertia(m.HubMass, Vec3(c.HubCM, 0, 0), Mat3(Vec3(m.HubIner, 0, 0).asDiagonal()));
  out.hub = b.addBody(std::move(hub));
  out.drivetrain = b.addDof("drivetrain", out.hub, DofKind::Joint, 0, ed.dof.DrTrDOF);
  return out;
}

}  // namespace whirl::elastodyn

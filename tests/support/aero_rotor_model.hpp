#pragma once
// A three-bladed rotor with blade elements: hub on a rigid support turning about the wind direction
// (ground X) at a prescribed speed, blades laid out as ElastoDyn's (span-first body axes, precone,
// pitch about −x) with one flap and one edge shape, a "wind speed" input and a "collective pitch"
// input. The polar is thin-airfoil Cl = 2π α with a constant drag, exact under linear interpolation.
#include <cmath>
#include <numbers>

#include "src/aero/polar.hpp"
#include "src/model/model.hpp"
#include "src/shapes/beam.hpp"

namespace whirl::test {

struct AeroRotorOptions {
  double rpm = 12;
  double wind = 8;  ///< [m/s]
  double pitch_deg = 2;
  double precone_deg = 2.5;
  double cd = 0.01;
  bool induction = true;
  double hub_height = 90;
  int elements = 12;
  double curve_deg = 0;  ///< AeroDyn's BlCrvAng of every element (AeroStation::curve) [deg]
};

inline Model aeroRotorModel(const AeroRotorOptions& o = {}) {
  using std::numbers::pi;
  const double hub_radius = 1.5, length = 40;
  Model m;
  m.name = "aero rotor";
  m.gravity.setZero();
  Body hub;
  hub.name = "hub";
  hub.offset = Vec3(0, 0, o.hub_height);
  hub.joint = JointType::Revolute;
  hub.axis = Vec3::UnitX();
  hub.inertia = rigidBodyInertia(1e4, Vec3::Zero(), Mat3(Vec3(1e6, 5e3, 5e3).asDiagonal()));
  m.bodies.push_back(hub);
  Dof az;
  az.name = "azimuth";
  az.body = 0;
  az.rotating = true;
  az.frozen = true;
  az.rate = o.rpm * 2 * pi / 60;
  m.dofs.push_back(az);

  BeamProperties p;
  p.length = length;
  p.x = VecX::LinSpaced(2, 0, length);
  p.m = VecX::Constant(2, 300);
  p.EIy = VecX::Constant(2, 4e9);
  p.EIz = VecX::Constant(2, 1e10);
  // Body y = out of plane (flap), z = in plane (edge), as ElastoDyn's blades.
  std::vector<ShapePtr> shapes{clampedTopMassShape("flap 1", length, 1, 0, 1, 0),
                               clampedTopMassShape("edge 1", length, 1, 0, 0, 1)};
  BeamOptions opt;
  opt.integration = {BeamIntegration::Gauss, 40};
  const BeamBody bb = buildBeamBody(p, shapes, opt, "blade");

  // Three rows: AeroDyn takes a table of fewer than 3 rows as constant.
  std::vector<double> alpha{-pi, 0.0, pi}, cl{-2 * pi * pi, 0.0, 2 * pi * pi}, cd{o.cd, o.cd, o.cd}, cm{0.0, 0.0, 0.0};
  m.aero.polars.push_back(aero::makePolar("thin", alpha, cl, cd, cm, aero::PolarInterp::Linear, "test"));
  m.aero.hub_body = 0;
  m.aero.hub_radius = hub_radius;
  m.aero.tip_radius = hub_radius + length;
  m.aero.rotor_radius = (hub_radius + length) * std::cos(o.precone_deg * pi / 180);
  m.aero.induction = o.induction;

  Mat3 span_first;
  span_first.col(0) = Vec3::UnitZ();
  span_first.col(1) = Vec3::UnitX();
  span_first.col(2) = Vec3::UnitY();
  Input wind;
  wind.name = "wind speed";
  wind.value = o.wind;
  Input pitch;
  pitch.name = "collective pitch";
  pitch.value = o.pitch_deg * pi / 180;
  for (int k = 0; k < 3; ++k) {
    const Mat3 coned = Eigen::AngleAxisd(2 * pi * k / 3, Vec3::UnitX()).toRotationMatrix() *
                       Eigen::AngleAxisd(o.precone_deg * pi / 180, Vec3::UnitY()).toRotationMatrix();
    Body bl;
    bl.name = "blade " + std::to_string(k + 1);
    bl.parent = 0;
    bl.offset = hub_radius * coned.col(2);
    bl.rotation = coned * span_first;
    bl.joint = JointType::Revolute;
    bl.axis = -Vec3::UnitX();
    bl.inertia = bb.inertia;
    bl.elastic = bb.elastic;
    bl.elastic.D.setZero();  // no structural damping: what damps is aerodynamic
    AeroBlade ab;
    for (int s = 0; s < o.elements; ++s) {
      const double x = length * s / (o.elements - 1);
      AeroStation st;
      st.point = static_cast<int>(bl.points.size());
      bl.points.push_back(beamPoint(p, shapes, opt.axial_shortening, x, "aero " + std::to_string(s + 1)));
      st.span = x;
      st.z = hub_radius + x;
      st.chord = 3.5 - 2.0 * x / length;
      st.twist = (10.0 - 10.0 * x / length) * pi / 180;
      st.polar = 0;
      st.curve = o.curve_deg * pi / 180;
      st.weight = length / (o.elements - 1) * (s == 0 || s == o.elements - 1 ? 0.5 : 1.0);
      ab.stations.push_back(st);
    }
    m.bodies.push_back(bl);
    const int body = k + 1;
    Dof pd;
    pd.name = bl.name + " pitch";
    pd.body = body;
    pd.frozen = true;
    m.dofs.push_back(pd);
    pitch.dofs.push_back({static_cast<int>(m.dofs.size()) - 1, 1.0});
    ab.pitch_dof = static_cast<int>(m.dofs.size()) - 1;
    m.roles.blade_pitch.push_back(ab.pitch_dof);
    for (int s = 0; s < 2; ++s) {
      Dof d;
      d.name = bl.name + " " + shapes[s]->name;
      d.kind = DofKind::Elastic;
      d.body = body;
      d.local = s;
      d.blade = k;
      m.dofs.push_back(d);
    }
    ab.body = body;
    m.aero.blades.push_back(ab);
  }
  m.inputs.push_back(wind);
  m.inputs.push_back(pitch);
  m.roles.wind_speed_input = 0;
  m.roles.collective_pitch_input = 1;
  m.aero.wind.reference_height = o.hub_height;
  finalize(m);
  return m;
}

}  // namespace whirl::test

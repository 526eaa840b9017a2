// Inputs and default outputs of the ElastoDyn turbine (definitions in elastodyn_model.hpp).
#include <cmath>
#include <numbers>

#include "src/turbine/elastodyn_parts.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

void addInputs(Builder& b, const TowerParts& tower, const DrivetrainParts& dt, const RotorParts& rotor) {
  Model& m = b.model();
  auto input = [&](const char* name, const char* unit) {
    Input in;
    in.name = name;
    in.unit = unit;
    m.inputs.push_back(in);
    return m.ninput() - 1;
  };
  auto load = [&](int body, int point, const Vec3& force, const Vec3& moment, bool body_frame, int in) {
    PointLoad l;
    l.body = body;
    l.point = point;
    l.force = force;
    l.moment = moment;
    l.body_frame = body_frame;
    l.input = in;
    m.point_loads.push_back(l);
  };
  // Generator torque u on the high-speed shaft, opposing the rotation: −u about c1 on the geared
  // generator rotor (−GBRatio·u on the generator azimuth), +u on the stator, the nacelle (c1 in
  // nacelle axes). The gearbox's own reaction comes through the geared joint.
  const double tilt = b.ed.config.ShftTilt * deg;
  const int gen = input("generator torque", "N m");
  load(dt.generator, -1, Vec3::Zero(), Vec3(-1, 0, 0), true, gen);
  load(dt.nacelle, -1, Vec3::Zero(), Vec3(std::cos(tilt), 0, std::sin(tilt)), true, gen);
  const int thrust = input("rotor thrust", "N");
  load(dt.hub, -1, Vec3::UnitX(), Vec3::Zero(), true, thrust);
  const int torque = input("rotor torque", "N m");
  load(dt.hub, -1, Vec3::Zero(), Vec3::UnitX(), true, torque);
  const int fa = input("tower-top force", "N");
  load(tower.body, tower.top, Vec3::UnitX(), Vec3::Zero(), false, fa);
  const int ss = input("tower-top side force", "N");
  load(tower.body, tower.top, Vec3::UnitY(), Vec3::Zero(), false, ss);
  // Pitch: prescribed rotations of the frozen pitch joints (positive to feather, as BlPitch).
  const int coll = input("collective pitch", "rad");
  for (int d : rotor.pitch) m.inputs[coll].dofs.push_back({d, 1.0});
  m.roles.collective_pitch_input = coll;
  for (size_t k = 0; k < rotor.pitch.size(); ++k) {
    const std::string name = "blade " + std::to_string(k + 1) + " pitch";
    Input in;
    in.name = name;
    in.unit = "rad";
    in.dofs.push_back({rotor.pitch[k], 1.0});
    in.blade = static_cast<int>(k);
    m.inputs.push_back(in);
    m.roles.blade_pitch_inputs.push_back(m.ninput() - 1);
  }
  // What an operating condition sets (src/model/operating_condition.hpp); no wind input (no aerodynamics).
  m.roles.blade_pitch = rotor.pitch;
  m.roles.generator_torque_input = gen;
  m.roles.yaw_dof = dt.yaw;
  m.roles.teeter_dof = rotor.teeter;
}

Output pointOutput(std::string name, std::string unit, int order, int body, int point, int frame, const Vec3& dir) {
  Output o;
  o.name = std::move(name);
  o.unit = std::move(unit);
  o.kind = OutputKind::Point;
  o.order = order;
  o.body = body;
  o.point = point;
  o.frame_body = frame;
  o.direction = dir;
  return o;
}

// The moment about `body`'s origin of the loads on it and the bodies it carries, along `axis` (body axes).
Output subtreeMoment(std::string name, int body, const Vec3& axis) {
  Output o;
  o.name = std::move(name);
  o.unit = "N m";
  o.kind = OutputKind::SubtreeLoadMoment;
  o.body = body;
  o.frame_body = body;
  o.direction = axis;
  return o;
}

void addOutputs(Builder& b, const TowerParts& tower, const DrivetrainParts& dt, const RotorParts& rotor) {
  std::vector<Output>& y = b.model().outputs;
  const double ratio = b.ed.drivetrain.GBRatio;
  y.push_back(dofOutput("GenSpeed", "rad/s", 1, {{dt.generator_azimuth, ratio}}));
  y.push_back(dofOutput("RotSpeed", "rad/s", 1, {{dt.generator_azimuth, 1.0}, {dt.drivetrain, 1.0}}));
  y.push_back(dofOutput("NacYaw", "rad", 0, {{dt.yaw, 1.0}}));
  // Tower top = the yaw bearing's origin; its axes follow the tower-top rotation (OpenFAST's xp, yp).
  y.push_back(pointOutput("TTDspFA", "m", 0, dt.bearing, -1, -1, Vec3::UnitX()));
  y.push_back(pointOutput("TTDspSS", "m", 0, dt.bearing, -1, -1, Vec3::UnitY()));
  y.push_back(pointOutput("YawBrTAxp", "m/s^2", 2, dt.bearing, -1, dt.bearing, Vec3::UnitX()));
  y.push_back(pointOutput("YawBrTAyp", "m/s^2", 2, dt.bearing, -1, dt.bearing, Vec3::UnitY()));
  // Tower body: x up, y = −Y (side-to-side), z = X (fore-aft). The base moments are summed from the loads on
  // the tower and everything it carries, as ElastoDyn's (the curvature of the tower's polynomial shapes at
  // the base gave 68 % of the NREL 5MW's fore-aft moment at 11 m/s): TwrBsMFA bends the top towards +X
  // (about +Y, the body's −y), TwrBsMSS towards +Y (about −X, the body's −z).
  y.push_back(subtreeMoment("TwrBsMFA", tower.body, -Vec3::UnitY()));
  y.push_back(subtreeMoment("TwrBsMSS", tower.body, -Vec3::UnitZ()));
  // ElastoDyn's RootMFlp = RootMyb and RootMEdg = RootMxb: the moment at the blade root of the loads on the
  // blade (aerodynamic, gravity, inertia: MomH0B, ElastoDyn.f90 CalcOutput) about the pitched axes j2 and
  // j1, which are the blade body's z and y. Summed from the loads, as ElastoDyn does: the curvature of the
  // polynomial shapes at the root, EI φ''(0), gave 37 % (flap) and 63 % (edge) of it (docs/theory/fe-blades.md).
  for (std::size_t k = 0; k < rotor.blades.size(); ++k) {
    const int body = rotor.blades[k].body;
    y.push_back(subtreeMoment("RootMFlp" + std::to_string(k + 1), body, Vec3::UnitZ()));
    y.back().blade = static_cast<int>(k);  // rotating frame
    y.push_back(subtreeMoment("RootMEdg" + std::to_string(k + 1), body, Vec3::UnitY()));
    y.back().blade = static_cast<int>(k);
  }
  if (rotor.teeter >= 0) y.push_back(dofOutput("TeetDefl", "rad", 0, {{rotor.teeter, 1.0}}));
  // The channels ROSCO's robust scheduling and users read from OpenFAST's .lin files (issue 41):
  // ElastoDyn's BldPitch1..3 (the pitch coordinates, driven by the pitch inputs), TwrBsMyt (the tower
  // base fore-aft moment about the base frame's yt, which is TwrBsMFA) and
  // NcIMURAys (the nacelle's angular acceleration about its lateral axis ys, which the tilt leaves
  // horizontal: the nacelle body's y).
  for (size_t k = 0; k < rotor.pitch.size(); ++k) {
    y.push_back(dofOutput("BldPitch" + std::to_string(k + 1), "rad", 0, {{rotor.pitch[k], 1.0}}));
    y.back().blade = static_cast<int>(k);  // rotating frame, as OpenFAST flags it
  }
  y.push_back(subtreeMoment("TwrBsMyt", tower.body, -Vec3::UnitY()));  // about yt: as TwrBsMFA
  Output imu;
  imu.name = "NcIMURAys";
  imu.unit = "rad/s^2";
  imu.kind = OutputKind::Angular;
  imu.order = 2;
  imu.body = dt.nacelle;
  imu.frame_body = dt.nacelle;
  imu.direction = Vec3::UnitY();
  y.push_back(imu);
  // The velocities ROSCO's floating feedback integrates from these accelerations (Fl_Mode 1: the
  // tower top's fore-aft, YawBrTVxp; Fl_Mode 2: the nacelle's pitch rate, NcIMURVys), as ElastoDyn
  // names them: a closed loop feeds them back directly (linearize/closed_loop.hpp).
  y.push_back(pointOutput("YawBrTVxp", "m/s", 1, dt.bearing, -1, dt.bearing, Vec3::UnitX()));
  imu.name = "NcIMURVys";
  imu.unit = "rad/s";
  imu.order = 1;
  y.push_back(std::move(imu));
}

}  // namespace

Output dofOutput(std::string name, std::string unit, int order, std::vector<std::pair<int, double>> terms) {
  Output o;
  o.name = std::move(name);
  o.unit = std::move(unit);
  o.order = order;
  o.terms = std::move(terms);
  return o;
}

void addInputsAndOutputs(Builder& b, const TowerParts& tower, const DrivetrainParts& dt, const RotorParts& rotor) {
  addInputs(b, tower, dt, rotor);
  addOutputs(b, tower, dt, rotor);
}

}  // namespace whirl::elastodyn

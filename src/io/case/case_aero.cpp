// `wind:` and `aero:` of a case: AeroDyn-style blade elements on beam bodies, the airfoil files, the
// rotor-level BEM settings and InflowWind's steady wind, built into Model::aero as the OpenFAST deck
// path does (src/turbine/elastodyn_aero.cpp), with the geometry the deck states (HubRad, precone) taken
// from the bodies' rest pose instead.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/case/case_columns.hpp"
#include "src/io/case/case_reader.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/shapes/beam.hpp"
#include "src/shapes/rigid_arm.hpp"

namespace whirl {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

const std::vector<std::string> kStationColumns = {"x",         "fraction", "chord", "twist",
                                                  "twist_deg", "airfoil",  "ac_y",  "ac_z"};

// An angle from `key` [rad] or `key_deg`, at most one of them.
double angle(const CaseNode& n, const std::string& key, double fallback) {
  const auto r = n.find(key), d = n.find(key + "_deg");
  if (r && d) d->fail("give " + key + " or " + key + "_deg, not both");
  return r ? r->number() : d ? d->number() * kDeg : fallback;
}

// Ground pose of a body's frame with every joint coordinate and elastic coordinate at zero (the
// undeflected reference the AeroDyn geometry is stated in). Parents are resolved (readBodies).
std::pair<Vec3, Mat3> restPose(const Model& m, int body, const Where& w) {
  std::vector<int> chain;
  for (int b = body; b >= 0; b = m.bodies[b].parent) {
    if (chain.size() > m.bodies.size()) w.fail("body '" + m.bodies[body].name + "': the parent chain forms a loop");
    chain.push_back(b);
  }
  Vec3 r = Vec3::Zero();
  Mat3 R = Mat3::Identity();
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const Body& b = m.bodies[*it];
    Vec3 at = Vec3::Zero();
    if (b.parent >= 0 && b.parent_point >= 0) at = m.bodies[b.parent].points[b.parent_point].P.col(0);
    r += R * (at + b.offset);
    R = R * b.rotation;
  }
  return {r, R};
}

struct PendingBlade {
  AeroBlade blade;
  CaseNode node;            // the body's `aero:`
  std::vector<Vec3> nodes;  // element positions in the body frame (rest)
};

// The pitch coordinate named by `aero.pitch`: the blade body's own revolute joint about −x (positive
// pitch towards feather, as ElastoDyn's pitch axis and the θ = twist + pitch of aero_loads.hxx).
int pitchDof(const CaseNode& p, int body, CaseBuild& build) {
  const int k = build.builder.dofIndex(p.text(), p.where());
  const Dof& d = build.model().dofs[k];
  const Body& b = build.model().bodies[body];
  if (d.body != body || d.kind != DofKind::Joint || b.joint != JointType::Revolute)
    p.fail("DOF '" + d.name + "' is not the revolute joint of body '" + b.name + "' (the blade's pitch bearing)");
  if ((b.axis.normalized() + Vec3::UnitX()).norm() > 1e-9)
    p.fail(
        "the pitch joint must turn the blade about its −x axis (joint axis [-1, 0, 0]: positive pitch towards "
        "feather, as ElastoDyn)");
  return k;
}

// One body's `aero:` — its elements at the stations of the table, on the beam's mean line plus the
// aerodynamic-centre offsets (AeroDyn's BlCrvAC, BlSwpAC are body y, z: aero_model.hpp).
PendingBlade readBlade(const CaseNode& n, int body, const CaseBuild::Beam& beam, int npolars, CaseBuild& build) {
  n.allowKeys({"pitch", "stations"});
  PendingBlade out{AeroBlade{}, n, {}};
  out.blade.body = body;
  if (const auto p = n.find("pitch")) {
    out.blade.pitch_dof = pitchDof(*p, body, build);
  } else if (const Body& b = build.model().bodies[body];
             b.joint == JointType::Revolute && (b.axis.normalized() + Vec3::UnitX()).norm() <= 1e-9) {
    // The body's own revolute joint about −x is its pitch bearing: the element angles need it apart.
    for (int k = 0; k < build.model().ndof(); ++k)
      if (build.model().dofs[k].body == body && build.model().dofs[k].kind == DofKind::Joint) out.blade.pitch_dof = k;
  }
  const CaseNode table = n.at("stations");
  const Columns c = readColumns(table, kStationColumns, {});
  const double L = beam.props.length;
  const VecX x = stations(table, c, L, false);
  const Column& xc = c.at(c.count("x") ? "x" : "fraction");
  const double tol = 1e-9 * std::max(1.0, L);
  for (Eigen::Index j = 0; j < x.size(); ++j)
    if (x(j) < -tol || x(j) > L + tol)
      xc.failAt(j, "station " + std::to_string(j + 1) + " at " + num(x(j)) + " m lies outside the blade (0 to " +
                       num(L) + " m)");
  auto required = [&](const char* key, const char* alt) -> const Column& {
    if (!c.count(key) && !(alt && c.count(alt)))
      table.fail(std::string("missing column '") + key + "'" + (alt ? std::string(" (or '") + alt + "')" : ""));
    return c.count(key) ? c.at(key) : c.at(alt);
  };
  const Column& chord = required("chord", nullptr);
  requireNonNegative(chord, true);
  if (c.count("twist") && c.count("twist_deg")) c.at("twist_deg").where.fail("give twist or twist_deg, not both");
  const Column& twist = required("twist_deg", "twist");
  const double twist_factor = c.count("twist_deg") ? kDeg : 1.0;
  const Column& airfoil = required("airfoil", nullptr);
  const VecX zero = VecX::Zero(x.size());
  const VecX ac_y = c.count("ac_y") ? c.at("ac_y").values : zero, ac_z = c.count("ac_z") ? c.at("ac_z").values : zero;

  Body& b = build.model().bodies[body];
  const int n_el = static_cast<int>(x.size());
  for (int j = 0; j < n_el; ++j) {
    const double id = airfoil.values(j);
    if (id != std::round(id) || id < 1 || id > npolars)
      airfoil.failAt(j, "value " + std::to_string(j + 1) + " is " + num(id) +
                            ", not an airfoil of aero.airfoils (1 to " + std::to_string(npolars) + ")");
    const std::string name = "aero " + std::to_string(j + 1);
    for (const BodyPoint& q : b.points)
      if (q.name == name)
        table.fail("body '" + b.name + "' already has a point named '" + name +
                   "' (the blade elements' points are 'aero 1', 'aero 2', …)");
    BodyPoint pt = beamPoint(beam.props, beam.shapes, beam.axial_shortening, std::clamp(x(j), 0.0, L), name);
    if (beam.finite_element) offsetOnRigidArm(pt, Vec3(0.0, ac_y(j), ac_z(j)));
    else {
      pt.P(1, 0) += ac_y(j);
      pt.P(2, 0) += ac_z(j);
    }
    out.nodes.push_back(pt.P.col(0));
    AeroStation st;
    st.point = static_cast<int>(b.points.size());
    b.points.push_back(std::move(pt));
    st.span = x(j);
    st.chord = chord.values(j);
    st.twist = twist.values(j) * twist_factor;
    st.polar = static_cast<int>(id) - 1;
    st.weight = 0.5 * (x(std::min(j + 1, n_el - 1)) - x(std::max(j - 1, 0)));
    out.blade.stations.push_back(st);
  }
  return out;
}

// The airfoil files of `aero.airfoils`, relative to the case folder, read as AeroDyn does.
std::vector<aero::Polar> readAirfoils(const CaseNode& list, bool use_cm) {
  std::vector<aero::Polar> polars;
  const std::vector<CaseNode> items = list.items();
  if (items.empty()) list.fail("at least one airfoil file");
  for (const CaseNode& f : items) {
    const std::string path = f.source().resolve(f.text());
    if (const std::string outside = f.source().outsideReason(path); !outside.empty()) f.fail(outside);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      f.fail("cannot open the airfoil file '" + path + "' (relative paths start at the case folder)");
    // The airfoil reader's own errors name the airfoil file and line.
    polars.push_back(io::airfoilPolar(io::readAirfoil(path), use_cm));
  }
  return polars;
}

void readWind(const CaseNode& w, CaseBuild& build) {
  w.allowKeys({"speed", "reference_height", "shear_exponent", "direction", "direction_deg", "upflow", "upflow_deg"});
  Model& m = build.model();
  if (m.findInput("wind speed")) w.fail("the case already has an input named 'wind speed' (the wind adds it)");
  const CaseNode speed = w.at("speed");
  Input in;
  in.name = "wind speed";
  in.unit = "m/s";
  in.value = speed.number();
  if (in.value < 0) speed.fail("must not be negative");
  if (in.value > limits::kMaxWindSpeed)
    speed.fail(fmt::format("{:g} m/s is above the limit of {:g} m/s (the aerodynamics are incompressible)", in.value,
                           limits::kMaxWindSpeed));
  m.inputs.push_back(in);
  m.roles.wind_speed_input = m.ninput() - 1;
  SteadyWind& sw = m.aero.wind;
  sw.reference_height = w.number("reference_height", 0);
  if (sw.reference_height < 0) w.at("reference_height").fail("must not be negative");
  sw.shear_exponent = w.number("shear_exponent", 0);
  if (sw.shear_exponent != 0 && !(sw.reference_height > 0))
    w.at("shear_exponent").fail("a shear exponent needs a positive reference_height [m]");
  sw.direction = angle(w, "direction", 0);
  sw.upflow = angle(w, "upflow", 0);
}

}  // namespace

void readAerodynamics(const CaseNode& top, CaseBuild& build) {
  Model& m = build.model();
  AeroModel& am = m.aero;
  const auto wind = top.find("wind"), rotor = top.find("aero");
  std::vector<std::pair<CaseNode, int>> blade_nodes;  // each body's `aero:` and the body
  for (const CaseNode& b : top.at("bodies").items())
    if (const auto a = b.find("aero")) blade_nodes.push_back({*a, *m.findBody(b.at("name").text())});
  if (!rotor) {
    if (!blade_nodes.empty())
      blade_nodes.front().first.fail("blade elements need the top-level aero: block (hub, airfoils)");
    if (wind) wind->fail("the wind acts on blade elements: the case has no aero: block");
    return;
  }
  const CaseNode& r = *rotor;
  r.allowKeys({"hub", "air_density", "induction", "airfoils", "TipLoss", "HubLoss", "TanInd", "AIDrag", "TIDrag",
               "MaxIter", "UseBlCm"});
  if (blade_nodes.empty()) r.fail("no beam or fe_blade body has an aero: block (its blade elements)");
  if (!wind) r.fail("aerodynamics need a top-level wind: block (at least its speed)");
  const CaseNode hub = r.at("hub");
  am.hub_body = build.builder.bodyIndex(hub.text(), hub.where());
  am.air_density = r.number("air_density", 1.225);
  if (!(am.air_density > 0)) r.at("air_density").fail("must be positive");
  am.induction = r.boolean("induction", true);
  am.bem.tip_loss = r.boolean("TipLoss", true);
  am.bem.hub_loss = r.boolean("HubLoss", true);
  am.bem.tan_ind = r.boolean("TanInd", true);
  am.bem.ai_drag = r.boolean("AIDrag", true);
  am.bem.ti_drag = r.boolean("TIDrag", true);
  if (const auto it = r.find("MaxIter")) {
    am.bem.max_iter = it->integer();
    if (am.bem.max_iter < 1 || am.bem.max_iter > 100000) it->fail("must be from 1 to 100000");
  }
  am.polars = readAirfoils(r.at("airfoils"), r.boolean("UseBlCm", true));

  std::vector<PendingBlade> blades;
  for (const auto& [node, body] : blade_nodes) {
    const auto beam = std::find_if(build.beams.begin(), build.beams.end(),
                                   [body = body](const CaseBuild::Beam& b) { return b.body == body; });
    blades.push_back(readBlade(node, body, *beam, static_cast<int>(am.polars.size()), build));
  }
  readWind(*wind, build);

  // Geometry from the rest pose: AeroDyn's zHub (apex to blade root), the elements' curvilinear
  // distance from the apex (loss constants), and the swept radius of the coned tip (rTipFix).
  const auto [rh, Rh] = restPose(m, am.hub_body, hub.where());
  const Vec3 axis = Rh.col(0);
  for (std::size_t k = 0; k < blades.size(); ++k) {
    PendingBlade& pb = blades[k];
    const Body& b = m.bodies[pb.blade.body];
    const auto [rb, Rb] = restPose(m, pb.blade.body, pb.node.where());
    // AeroDyn's blade frame (aero_model.hpp): body y out of the rotor plane downwind, z in the plane
    // against the rotation, the rotor turning positively about the hub's x.
    if (!(Rb.col(1).dot(axis) > 0) || !(Rb.col(2).dot(axis.cross(Rb.col(0))) < 0))
      pb.node.fail("body '" + b.name +
                   "' is not in AeroDyn's blade frame: x along the span, y downwind (along the "
                   "hub's x, the rotor axis), z in the rotor plane against the rotation (positive about the hub's x)");
    const double hub_radius = (rb - rh).norm();
    if (k == 0) am.hub_radius = hub_radius;
    else if (std::abs(hub_radius - am.hub_radius) > 1e-6 * std::max(1.0, am.hub_radius))
      pb.node.fail("the root of body '" + b.name + "' is " + num(hub_radius) + " m from the hub origin, the first " +
                   "blade's " + num(am.hub_radius) + " m (one hub radius per rotor)");
    double z = hub_radius;
    Vec3 previous = Vec3::Zero();
    for (std::size_t j = 0; j < pb.nodes.size(); ++j) {
      z += (pb.nodes[j] - previous).norm();
      previous = pb.nodes[j];
      pb.blade.stations[j].z = z;
    }
    am.tip_radius = std::max(am.tip_radius, z);
    const Vec3 d = rb + Rb * pb.nodes.back() - rh;
    am.rotor_radius = std::max(am.rotor_radius, (d - d.dot(axis) * axis).norm());
    am.blades.push_back(std::move(pb.blade));
  }

  // AeroDyn's rotor outputs (names as OpenFAST's channels, SI units), as the deck path adds them.
  for (Output& o : aeroRotorOutputs()) {
    if (m.findOutput(o.name)) r.fail("output name '" + o.name + "' is taken: the aerodynamics add it");
    m.outputs.push_back(std::move(o));
  }
}

}  // namespace whirl

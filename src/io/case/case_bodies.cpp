// `bodies:` of a case: common keys (name, type, parent, at, offset, rotation, joint, points),
// joint DOFs, and the parent/point references resolved once every body is known.
#include <cmath>
#include <numbers>
#include <optional>

#include "src/io/case/case_reader.hpp"

namespace whirl {
namespace {

const std::vector<std::string> kCommonKeys = {"name", "type", "parent", "at", "offset", "rotation", "joint", "points"};
const std::vector<std::string> kRigidKeys = {"mass", "cog", "inertia"};
const std::vector<std::string> kBeamKeys = {"length",      "uniform",          "properties", "shapes",
                                            "integration", "axial_shortening", "damping",    "aero"};
const std::vector<std::string> kFemKeys = {
    "length", "elements", "uniform",   "properties", "timoshenko",         "dofs", "clamped", "supports",
    "soil",   "masses",   "reduction", "damping",    "geometric_stiffness"};
const std::vector<std::string> kBlade6Keys = {"reference_axis", "sections",         "mu",  "elements",
                                              "modes",          "axial_shortening", "aero"};

Mat3 elementary(char axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Mat3 r;
  switch (axis) {
    case 'x': r << 1, 0, 0, 0, c, -s, 0, s, c; break;
    case 'y': r << c, 0, s, 0, 1, 0, -s, 0, c; break;
    default: r << c, -s, 0, s, c, 0, 0, 0, 1; break;
  }
  return r;
}

// The joint of `node` (default fixed) and its DOFs.
void readJoint(const CaseNode& body_node, int index, CaseBuild& build) {
  Body& b = build.model().bodies[index];
  const auto j = body_node.find("joint");
  if (!j) return;
  const std::string type = j->at("type").text();
  const Where jw = j->where();
  if (type == "fixed") {
    j->allowKeys({"type"});
    b.joint = JointType::Fixed;
  } else if (type == "revolute" || type == "prismatic") {
    j->allowKeys({"type", "axis", "dof"});
    b.joint = type == "revolute" ? JointType::Revolute : JointType::Prismatic;
    if (const auto a = j->find("axis")) {
      b.axis = a->vec3();
      if (b.axis.norm() < 1e-12) a->fail("the joint axis must not be zero");
    }
    const auto d = j->find("dof");
    build.addDof(d ? d->text() : b.name + " joint", DofKind::Joint, index, 0, d ? d->where() : jw,
                 b.joint == JointType::Revolute);
  } else if (type == "free") {
    j->allowKeys({"type", "dofs"});
    b.joint = JointType::Free;
    static const char* kDefault[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
    std::vector<CaseNode> names;
    if (const auto d = j->find("dofs")) {
      names = d->items();
      if (names.size() != 6)
        d->fail("a free joint has 6 DOFs (surge, sway, heave, roll, pitch, yaw), got " + std::to_string(names.size()) +
                " names");
    }
    for (int k = 0; k < 6; ++k)
      build.addDof(names.empty() ? b.name + " " + kDefault[k] : names[k].text(), DofKind::Joint, index, k,
                   names.empty() ? jw : names[k].where(), k >= 3);
  } else {
    j->at("type").fail("unknown joint type '" + type + "' (allowed: fixed, revolute, prismatic, free)");
  }
}

}  // namespace

Mat3 readRotation(const CaseNode& node) {
  if (node.isMap()) {
    Mat3 r = Mat3::Identity();
    node.allowKeys({"x", "y", "z", "x_deg", "y_deg", "z_deg"});
    for (const MapEntry& e : node.entries()) {
      const double a = e.value.number();
      r = r * elementary(e.key[0], e.key.size() > 1 ? a * std::numbers::pi / 180 : a);
    }
    return r;
  }
  const Mat3 r = node.matrix(3, 3);
  if ((r.transpose() * r - Mat3::Identity()).norm() > 1e-6)
    node.fail("the rotation matrix is not orthonormal (to 1e-6); write the angles instead, e.g. {z_deg: 30}");
  if (r.determinant() < 0) node.fail("the rotation matrix is a reflection (determinant −1)");
  // Round the typed digits to the nearest rotation: R (RᵀR)^(-1/2).
  Eigen::SelfAdjointEigenSolver<Mat3> es(r.transpose() * r);
  return r * es.operatorInverseSqrt();
}

void readBodies(const CaseNode& list, CaseBuild& build) {
  Model& m = build.model();
  const std::vector<CaseNode> items = list.items();
  if (items.empty()) list.fail("a case needs at least one body");
  struct Link {
    std::optional<CaseNode> parent, at;
  };
  std::vector<Link> links;
  for (const CaseNode& n : items) {
    const std::string type = n.at("type").text();
    std::vector<std::string> keys = kCommonKeys;
    if (type == "rigid") keys.insert(keys.end(), kRigidKeys.begin(), kRigidKeys.end());
    else if (type == "beam") keys.insert(keys.end(), kBeamKeys.begin(), kBeamKeys.end());
    else if (type == "fem_beam") keys.insert(keys.end(), kFemKeys.begin(), kFemKeys.end());
    else if (type == "fe_blade") keys.insert(keys.end(), kBlade6Keys.begin(), kBlade6Keys.end());
    else n.at("type").fail("unknown body type '" + type + "' (allowed: rigid, beam, fem_beam, fe_blade)");
    n.allowKeys(keys);
    Body b;
    const CaseNode name = n.at("name");
    b.name = name.text();
    if (b.name.empty() || b.name == "ground") name.fail("'" + b.name + "' cannot name a body");
    if (const auto k = m.findBody(b.name))
      name.fail("body name '" + b.name + "' is already used at line " +
                std::to_string(build.builder.bodyWhere(*k).line));
    b.offset = n.vec3("offset", Vec3::Zero());
    if (const auto r = n.find("rotation")) b.rotation = readRotation(*r);
    const int index = build.builder.addBody(b, n.where());
    links.push_back({n.find("parent"), n.find("at")});
    readJoint(n, index, build);
    if (type == "rigid") readRigidBody(n, m.bodies[index]);
    else if (type == "beam") readBeamBody(n, index, build);
    else if (type == "fe_blade") readBlade6Body(n, index, build);
    else readFemBody(n, index, build);
  }
  for (size_t i = 0; i < items.size(); ++i) {
    Body& b = m.bodies[i];
    const Link& l = links[i];
    const std::string parent = l.parent ? l.parent->text() : "ground";
    if (parent == b.name) l.parent->fail("a body cannot be its own parent");
    b.parent = parent == "ground" ? -1 : build.builder.bodyIndex(parent, l.parent->where());
    if (!l.at) continue;
    if (b.parent < 0) l.at->fail("a point needs a parent body; on the ground, give the position as offset");
    b.parent_point = build.builder.pointIndex(b.parent, l.at->text(), l.at->where());
  }
}

}  // namespace whirl

// `inputs:`, `dofs:` settings and `loads:` of a case.
#include <numbers>

#include "src/dynamics/catenary.hpp"
#include "src/io/case/case_reader.hpp"

namespace whirl {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kRpm = 2 * std::numbers::pi / 60;

// Value in SI from `key` or `key_suffix` (converted by `factor`), at most one of them.
double oneOf(const CaseNode& n, const std::string& key, const std::string& alt, double factor, double fallback,
             bool alt_allowed, const std::string& why_not) {
  const auto a = n.find(key), b = n.find(alt);
  if (a && b) b->fail("give " + key + " or " + alt + ", not both");
  if (b && !alt_allowed) b->fail(why_not);
  return a ? a->number() : b ? b->number() * factor : fallback;
}

void pointLoad(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"type", "body", "point", "force", "moment", "frame", "input"});
  PointLoad l;
  const CaseNode body = n.at("body");
  l.body = build.builder.bodyIndex(body.text(), body.where());
  if (const auto p = n.find("point")) l.point = build.builder.pointIndex(l.body, p->text(), p->where());
  l.force = n.vec3("force", Vec3::Zero());
  l.moment = n.vec3("moment", Vec3::Zero());
  if (const auto f = n.find("frame")) {
    const std::string s = f->text();
    if (s != "body" && s != "ground") f->fail("expected body or ground, got '" + s + "'");
    l.body_frame = s == "body";
  }
  if (const auto u = n.find("input")) l.input = build.builder.inputIndex(u->text(), u->where());
  build.model().point_loads.push_back(l);
}

void dofLoad(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"type", "dof", "value", "input"});
  DofLoad l;
  const CaseNode dof = n.at("dof");
  l.dof = build.builder.dofIndex(dof.text(), dof.where());
  l.value = n.at("value").number();
  if (const auto u = n.find("input")) l.input = build.builder.inputIndex(u->text(), u->where());
  build.model().dof_loads.push_back(l);
}

void spring(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"type", "dof", "k", "c", "q0"});
  DofSpring s;
  const CaseNode dof = n.at("dof");
  s.dof = build.builder.dofIndex(dof.text(), dof.where());
  if (!n.has("k") && !n.has("c")) n.fail("a spring needs k and/or c");
  s.k = n.number("k", 0);
  s.c = n.number("c", 0);
  s.q0 = n.number("q0", 0);
  build.model().springs.push_back(s);
}

void bodyMatrices(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"type", "body", "K", "C", "A", "x0"});
  BodyMatrices bm;
  const CaseNode body = n.at("body");
  bm.body = build.builder.bodyIndex(body.text(), body.where());
  if (build.model().bodies[bm.body].joint != JointType::Free)
    body.fail("body '" + body.text() + "' has no free joint: 6×6 matrices act on the 6 coordinates of a free joint");
  if (const auto k = n.find("K")) bm.K = k->matrix(6, 6);
  if (const auto c = n.find("C")) bm.C = c->matrix(6, 6);
  if (const auto a = n.find("A")) bm.A = a->matrix(6, 6);
  if (const auto x = n.find("x0")) {
    const std::vector<double> v = x->numbers();
    if (v.size() != 6)
      x->fail("expected 6 numbers (surge, sway, heave, roll, pitch, yaw), got " + std::to_string(v.size()));
    for (int i = 0; i < 6; ++i) bm.x0(i) = v[i];
  }
  build.model().body_matrices.push_back(bm);
}

// A quasi-static catenary from a fairlead on a rigid body to an anchor on the ground, as a MAP++ line
// (src/model/mooring.hpp); checked at the undisplaced body so that a line that cannot reach its anchor
// names its place.
void mooringLine(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"type", "name", "body", "fairlead", "anchor", "length", "weight", "EA", "CB", "seabed"});
  MooringLine ml;
  const CaseNode body = n.at("body");
  ml.body = build.builder.bodyIndex(body.text(), body.where());
  ml.name = n.text("name", "mooring line " + std::to_string(build.model().mooring.size() + 1));
  ml.fairlead = n.at("fairlead").vec3();
  ml.anchor = n.at("anchor").vec3();
  ml.length = n.number("length", 0);
  ml.weight = n.number("weight", 0);
  ml.EA = n.number("EA", 0);
  ml.CB = n.number("CB", 0);
  ml.seabed = n.boolean("seabed", false);
  if (!(ml.length > 0)) n.at("length").fail("must be positive");
  if (!(ml.weight > 0)) n.fail("weight: the weight in water per length [N/m] must be positive (a catenary)");
  if (!(ml.EA > 0)) n.fail("EA: must be positive");
  if (!(ml.CB >= 0)) n.at("CB").fail("must not be negative");
  const Body& b = build.model().bodies[ml.body];
  if (b.joint != JointType::Free || b.parent >= 0)
    body.fail("body '" + body.text() + "' is not on a free joint to the ground: a fairlead's body needs one");
  const Vec3 d = b.offset + b.rotation * ml.fairlead - ml.anchor;  // the undisplaced fairlead, ground
  try {
    mooringFairleadForce<double>(ml, d);
  } catch (const ComputeError& e) {
    n.fail(e.what());
  }
  build.model().mooring.push_back(ml);
}

}  // namespace

void readInputs(const CaseNode& list, CaseBuild& build) {
  for (const CaseNode& n : list.items()) {
    n.allowKeys({"name", "value", "unit", "dofs", "blade"});
    Input in;
    const CaseNode name = n.at("name");
    in.name = name.text();
    if (in.name.empty()) name.fail("an input name must not be empty");
    if (build.model().findInput(in.name)) name.fail("input name '" + in.name + "' is used twice");
    in.value = n.number("value", 0);
    in.unit = n.text("unit", "");
    if (const auto b = n.find("blade")) {
      in.blade = b->integer() - 1;
      if (in.blade < 0) b->fail("blades are numbered from 1");
    }
    build.model().inputs.push_back(in);
  }
}

void readDofSettings(const CaseNode& map, CaseBuild& build) {
  for (const MapEntry& e : map.entries()) {
    const int k = build.builder.dofIndex(e.key, e.key_where);
    const CaseNode& n = e.value;
    n.allowKeys({"value", "value_deg", "frozen", "rotating", "rate", "rate_rpm"});
    Dof& d = build.model().dofs[k];
    const bool ang = build.dof_angular[k];
    const std::string why = "DOF '" + d.name + "' is a displacement [m], not an angle";
    d.value = oneOf(n, "value", "value_deg", kDeg, d.value, ang, why);
    d.rate = oneOf(n, "rate", "rate_rpm", kRpm, d.rate, ang, why);
    d.frozen = n.boolean("frozen", d.frozen);
    d.rotating = n.boolean("rotating", d.rotating);
  }
}

void readLoads(const CaseNode& list, CaseBuild& build) {
  for (const CaseNode& n : list.items()) {
    const std::string type = n.at("type").text();
    if (type == "point") pointLoad(n, build);
    else if (type == "dof") dofLoad(n, build);
    else if (type == "spring") spring(n, build);
    else if (type == "body_matrices") bodyMatrices(n, build);
    else if (type == "mooring_line") mooringLine(n, build);
    else
      n.at("type").fail("unknown load type '" + type + "' (allowed: point, dof, spring, body_matrices, mooring_line)");
  }
}

}  // namespace whirl

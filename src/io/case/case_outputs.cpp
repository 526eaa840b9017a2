// `outputs:` of a case, and the frozen coordinates an input drives (`inputs: - dofs:`).
#include <algorithm>

#include "src/io/case/case_reader.hpp"
#include "src/shapes/beam_moment.hpp"

namespace whirl {
namespace {

int orderOf(const CaseNode& n) {
  if (const auto o = n.find("order")) {
    const std::string s = o->text();
    if (s == "0" || s == "value" || s == "position") return 0;
    if (s == "1" || s == "rate" || s == "velocity") return 1;
    if (s == "2" || s == "acceleration") return 2;
    o->fail("expected value/position (0), rate/velocity (1) or acceleration (2), got '" + s + "'");
  }
  return 0;
}

// `dofs:` as a list of names (gain 1) or a map name → gain.
std::vector<std::pair<int, double>> dofTerms(const CaseNode& n, CaseBuild& build) {
  std::vector<std::pair<int, double>> terms;
  if (n.isMap()) {
    for (const MapEntry& e : n.entries())
      terms.push_back({build.builder.dofIndex(e.key, e.key_where), e.value.number()});
  } else if (n.isList()) {
    for (const CaseNode& d : n.items()) terms.push_back({build.builder.dofIndex(d.text(), d.where()), 1.0});
  } else {
    terms.push_back({build.builder.dofIndex(n.text(), n.where()), 1.0});
  }
  if (terms.empty()) n.fail("at least one DOF");
  return terms;
}

Output dofOutput(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"name", "type", "unit", "order", "dof", "dofs", "blade"});
  const auto one = n.find("dof"), many = n.find("dofs");
  if (one && many) many->fail("give dof or dofs, not both");
  if (!one && !many) n.fail("a dof output needs dof (a name) or dofs (names, or a map name: gain)");
  Output o;
  o.kind = OutputKind::DofCombination;
  o.order = orderOf(n);
  o.terms = dofTerms(one ? *one : *many, build);
  return o;
}

// `type: point` (a body point's motion) or `type: angular` (a body frame's angular velocity or
// acceleration: no point, order rate or acceleration).
Output pointOutput(const CaseNode& n, CaseBuild& build, OutputKind kind) {
  const bool angular = kind == OutputKind::Angular;
  if (angular) n.allowKeys({"name", "type", "unit", "order", "body", "frame", "direction", "blade"});
  else n.allowKeys({"name", "type", "unit", "order", "body", "point", "frame", "direction", "blade"});
  Output o;
  o.kind = kind;
  o.order = angular && !n.has("order") ? 1 : orderOf(n);
  if (angular && o.order == 0) n.at("order").fail("an angular output is a rate (1) or an acceleration (2)");
  const CaseNode body = n.at("body");
  o.body = build.builder.bodyIndex(body.text(), body.where());
  if (const auto p = n.find("point")) o.point = build.builder.pointIndex(o.body, p->text(), p->where());
  if (const auto f = n.find("frame")) {
    const std::string s = f->text();
    o.frame_body = s == "ground" ? -1 : build.builder.bodyIndex(s, f->where());
  }
  o.direction = n.vec3("direction", Vec3::UnitX());
  if (o.direction.norm() < 1e-12) n.at("direction").fail("the direction must not be zero");
  return o;
}

Output momentOutput(const CaseNode& n, CaseBuild& build) {
  n.allowKeys({"name", "type", "unit", "body", "fraction", "x", "component", "blade"});
  const CaseNode body = n.at("body");
  const int b = build.builder.bodyIndex(body.text(), body.where());
  const CaseBuild::Beam* beam = nullptr;
  for (const auto& bm : build.beams)
    if (bm.body == b) beam = &bm;
  if (!beam) body.fail("body '" + body.text() + "' is not a beam: bending moments come from a beam's curvature");
  const double L = beam->props.length;
  if (n.has("fraction") && n.has("x")) n.at("x").fail("give fraction or x, not both");
  const double x = n.has("x") ? n.at("x").number() : n.number("fraction", 0.0) * L;
  if (x < 0 || x > L) n.fail("the station must lie on the beam (0 … " + std::to_string(L) + " m)");
  const CaseNode comp = n.at("component");
  const std::string c = comp.text();
  if (c != "y" && c != "z") comp.fail("expected y (bends towards body +y) or z (towards body +z), got '" + c + "'");
  const MatX G = beam->moment_gains ? beam->moment_gains(x) : beamMomentGains(beam->props, beam->shapes, x);
  Output o;
  o.kind = OutputKind::DofCombination;
  for (int j = 0; j < G.cols(); ++j) {
    int dof = -1;
    for (int k = 0; k < build.model().ndof(); ++k) {
      const Dof& d = build.model().dofs[k];
      if (d.body == b && d.kind == DofKind::Elastic && d.local == j) dof = k;
    }
    o.terms.push_back({dof, G(c == "y" ? 0 : 1, j)});
  }
  if (o.terms.empty()) body.fail("beam '" + body.text() + "' has no shapes");
  if (!n.has("unit")) o.unit = "N m";
  return o;
}

}  // namespace

void readInputTargets(const CaseNode& list, CaseBuild& build) {
  for (const CaseNode& n : list.items()) {
    const auto d = n.find("dofs");
    if (!d) continue;
    Input& in = build.model().inputs[*build.model().findInput(n.at("name").text())];
    for (const auto& [dof, gain] : dofTerms(*d, build)) {
      if (!build.model().dofs[dof].frozen)
        d->fail("DOF '" + build.model().dofs[dof].name + "' is not frozen: an input sets frozen coordinates only " +
                "(add `frozen: true` under dofs:)");
      in.dofs.push_back({dof, gain});
    }
  }
}

void assignRoles(CaseBuild& build) {
  Model& m = build.model();
  std::vector<int> pitch, inputs;  // per blade
  for (int i = 0; i < m.ninput(); ++i) {
    const Input& in = m.inputs[i];
    if (in.blade < 0 || in.dofs.size() != 1 || !build.dof_angular[in.dofs.front().dof]) continue;
    const size_t b = static_cast<size_t>(in.blade);
    if (pitch.size() <= b) {
      pitch.resize(b + 1, -1);
      inputs.resize(b + 1, -1);
    }
    if (pitch[b] >= 0) return;  // two candidates for one blade: no pitch roles
    pitch[b] = in.dofs.front().dof;
    inputs[b] = i;
  }
  if (pitch.empty() || std::find(pitch.begin(), pitch.end(), -1) != pitch.end()) return;
  m.roles.blade_pitch = pitch;
  m.roles.blade_pitch_inputs = inputs;
  std::vector<int> all = pitch;
  std::sort(all.begin(), all.end());
  for (int i = 0; i < m.ninput(); ++i) {
    const Input& in = m.inputs[i];
    if (in.blade >= 0 || in.dofs.size() != all.size()) continue;
    std::vector<int> targets;
    for (const InputDofTarget& t : in.dofs) targets.push_back(t.dof);
    std::sort(targets.begin(), targets.end());
    if (targets == all) {
      m.roles.collective_pitch_input = i;
      break;
    }
  }
}

void readOutputs(const CaseNode& list, CaseBuild& build) {
  for (const CaseNode& n : list.items()) {
    const std::string type = n.at("type").text();
    Output o;
    if (type == "dof") o = dofOutput(n, build);
    else if (type == "point") o = pointOutput(n, build, OutputKind::Point);
    else if (type == "angular") o = pointOutput(n, build, OutputKind::Angular);
    else if (type == "moment") o = momentOutput(n, build);
    else n.at("type").fail("unknown output type '" + type + "' (allowed: dof, point, angular, moment)");
    const CaseNode name = n.at("name");
    o.name = name.text();
    if (o.name.empty()) name.fail("an output name must not be empty");
    if (build.model().findOutput(o.name)) name.fail("output name '" + o.name + "' is used twice");
    if (n.has("unit")) o.unit = n.at("unit").text();
    if (o.unit.empty()) {  // SI from the kind: m or rad, per s, per s²
      bool angular = o.kind == OutputKind::DofCombination || o.kind == OutputKind::Angular;
      for (const auto& t : o.terms) angular = angular && build.dof_angular[t.first];
      o.unit = std::string(angular ? "rad" : "m") + (o.order == 1 ? "/s" : o.order == 2 ? "/s^2" : "");
    }
    if (const auto b = n.find("blade")) {
      o.blade = b->integer() - 1;
      if (o.blade < 0) b->fail("blades are numbered from 1");
    }
    build.model().outputs.push_back(o);
  }
}

}  // namespace whirl

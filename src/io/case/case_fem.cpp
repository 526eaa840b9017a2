// Finite-element beam bodies of a case (`type: fem_beam`): the keys (properties, points, soil, DOF
// kinds, boundary conditions, springs, lumped masses, reduction, damping) read into a
// fem::StraightBeamSpec, which src/fem/straight_beam_body assembles and reduces to a Ritz body. After
// finalize(), the geometric stiffness of the gravity loads each FE body carries is added (the loads from
// src/dynamics/gravity_loads, the stiffness from src/fem/fem_body).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/dynamics/gravity_loads.hpp"
#include "src/fem/straight_beam_body.hpp"
#include "src/io/case/case_columns.hpp"
#include "src/io/case/case_reader.hpp"

namespace whirl {

/// What the geometric stiffness needs once the model is finalized.
struct FemPending {
  std::string body;
  fem::BeamModel model;
  fem::FemBody fb;
  std::vector<int> point_node;  ///< node of each body point
  Where where;
};

namespace {

const std::vector<std::string> kSectionKeys = {"m", "EA", "EIy", "EIz", "GJ", "jG", "kGAy", "kGAz"};

fem::BeamStations femProperties(const CaseNode& n, double L, bool uniform) {
  fem::BeamStations p;
  std::map<std::string, VecX> col;
  if (uniform) {
    n.allowKeys(kSectionKeys);
    p.x = VecX::LinSpaced(2, 0, L);
    for (const MapEntry& e : n.entries()) {
      const double v = e.value.number();
      if (v < 0) e.value.fail("must not be negative");
      col[e.key] = VecX::Constant(2, v);
    }
  } else {
    std::vector<std::string> allowed = kSectionKeys;
    allowed.insert(allowed.end(), {"x", "fraction"});
    const Columns c = readColumns(n, allowed, {});
    p.x = stations(n, c, L, true);
    for (const auto& [k, v] : c) {
      if (k == "x" || k == "fraction") continue;
      requireNonNegative(v);
      col[k] = v.values;
    }
  }
  for (const char* k : {"m", "EIy", "EIz"})
    if (!col.count(k)) n.fail(std::string("missing '") + k + "'");
  auto get = [&](const char* k) { return col.count(k) ? col[k] : VecX(); };
  p.m = get("m");
  p.EIy = get("EIy");
  p.EIz = get("EIz");
  p.EA = get("EA");
  p.GJ = get("GJ");
  p.kGAy = get("kGAy");
  p.kGAz = get("kGAz");
  // Sections are taken as circular or tubular: the polar mass moment splits equally, ∫y² = ∫z² = jG/2.
  if (col.count("jG")) p.iy2 = p.iz2 = 0.5 * col["jG"];
  return p;
}

double station(const CaseNode& p, double L, const char* what) {
  const auto x = p.find("x"), f = p.find("fraction");
  if (x && f) f->fail("give x or fraction, not both");
  if (!x && !f) p.fail(std::string("missing key 'x' (or 'fraction') of the ") + what);
  const double v = x ? x->number() : f->number() * L;
  if (v < -1e-9 * L || v > L * (1 + 1e-9)) (x ? *x : *f).fail("must lie on the beam, 0 ≤ x ≤ " + num(L));
  return std::clamp(v, 0.0, L);
}

std::array<bool, 6> readActiveDofs(const CaseNode& n) {
  std::array<bool, 6> a{};
  for (const CaseNode& d : n.items()) {
    const std::string s = d.text();
    const auto it = std::find(fem::kNodeDofNames.begin(), fem::kNodeDofNames.end(), s);
    if (it == fem::kNodeDofNames.end()) d.fail("unknown DOF '" + s + "' (allowed: ux, uy, uz, rx, ry, rz)");
    a[it - fem::kNodeDofNames.begin()] = true;
  }
  return a;
}

/// A named station of an FE body (`points:`), placed on the mesh.
struct FemPoint {
  std::string name;
  double x;
};

std::vector<FemPoint> readFemPoints(const CaseNode& n, double L, const std::string& body) {
  std::vector<FemPoint> pts;
  if (const auto p = n.find("points"))
    for (const CaseNode& pt : p->items()) {
      pt.allowKeys({"name", "x", "fraction"});
      const std::string name = pt.at("name").text();
      for (const auto& q : pts)
        if (q.name == name) pt.at("name").fail("point name '" + name + "' used twice in body '" + body + "'");
      pts.push_back({name, station(pt, L, "point")});
    }
  return pts;
}

/// Distributed soil springs (`soil:` kx, ky, kz per length along x).
std::optional<fem::BeamSoil> readFemSoil(const CaseNode& n, double L) {
  const auto s = n.find("soil");
  if (!s) return std::nullopt;
  const Columns columns = readColumns(*s, {"x", "fraction", "kx", "ky", "kz"}, {});
  fem::BeamSoil soil;
  soil.x = stations(*s, columns, L, false);
  if (soil.x(0) < -1e-9 * L || soil.x(soil.x.size() - 1) > L * (1 + 1e-9))
    s->fail("soil stations must lie on the beam");
  for (const char* k : {"kx", "ky", "kz"})
    if (columns.count(k)) requireNonNegative(columns.at(k));
  auto column = [&](const char* k) { return columns.count(k) ? columns.at(k).values : VecX(); };
  soil.kx = column("kx");
  soil.ky = column("ky");
  soil.kz = column("kz");
  return soil;
}

/// Index of the point named in `v` (StraightBeamSpec::points); an FE body's points are its nodes.
using PointIndex = std::function<int(const CaseNode&)>;

void readFemSupports(const CaseNode& n, const PointIndex& pointIndex, fem::StraightBeamSpec& spec) {
  if (const auto c = n.find("clamped"))
    for (const CaseNode& p : c->items()) spec.clamped.push_back(pointIndex(p));
  if (const auto s = n.find("supports"))
    for (const CaseNode& sp : s->items()) {
      sp.allowKeys({"at", "K"});
      fem::BeamPointSpring ns;
      ns.point = pointIndex(sp.at("at"));
      const CaseNode k = sp.at("K");
      ns.K = k.matrix(6, 6);
      if ((ns.K - ns.K.transpose()).norm() > 1e-9 * ns.K.norm()) k.fail("the 6×6 stiffness matrix must be symmetric");
      spec.supports.push_back(ns);
    }
}

void readFemMasses(const CaseNode& n, const PointIndex& pointIndex, fem::StraightBeamSpec& spec) {
  if (const auto ms = n.find("masses"))
    for (const CaseNode& mm : ms->items()) {
      mm.allowKeys({"at", "mass", "inertia"});
      fem::BeamPointMass nm;
      nm.point = pointIndex(mm.at("at"));
      nm.mass = mm.number("mass", 0);
      if (nm.mass < 0) mm.at("mass").fail("negative mass");
      if (const auto j = mm.find("inertia")) {
        const Vec3 d = j->vec3();
        if ((d.array() < 0).any()) j->fail("inertia [Jxx, Jyy, Jzz] about the node must not be negative");
        nm.inertia = d.asDiagonal();
      }
      spec.masses.push_back(nm);
    }
}

/// Each active DOF kind needs stiffness and inertia, else K or M is singular; `props_node`: the
/// `uniform` or `properties` node the message points at.
void requireFemStiffnessAndInertia(const fem::BeamStations& props, const std::array<bool, 6>& active,
                                   const CaseNode& props_node) {
  auto need = [&](int k, const VecX& v, const char* what) {
    if (active[k] && (v.size() == 0 || (v.array() <= 0).any()))
      props_node.fail(std::string("DOF ") + fem::kNodeDofNames[k] + " needs " + what + " > 0 (or leave " +
                      fem::kNodeDofNames[k] + " out of `dofs`)");
  };
  need(0, props.EA, "EA");
  need(3, props.GJ, "GJ");
  need(3, props.iy2, "jG");
}

void readFemReduction(const CaseNode& n, const PointIndex& pointIndex, fem::StraightBeamSpec& spec) {
  const auto r = n.find("reduction");
  if (!r) return;
  r->allowKeys({"type", "interface", "modes"});
  const std::string t = r->at("type").text();
  if (t == "none") spec.reduction = fem::ReductionKind::None;
  else if (t == "guyan") spec.reduction = fem::ReductionKind::Guyan;
  else if (t == "craig_bampton") spec.reduction = fem::ReductionKind::CraigBampton;
  else r->at("type").fail("unknown reduction '" + t + "' (allowed: none, guyan, craig_bampton)");
  if (spec.reduction != fem::ReductionKind::None) {
    for (const CaseNode& p : r->at("interface").items()) spec.interface_points.push_back(pointIndex(p));
    if (spec.interface_points.empty()) r->at("interface").fail("the interface needs at least one point");
  }
  if (spec.reduction == fem::ReductionKind::CraigBampton) {
    spec.modes = r->at("modes").integer();
    if (spec.modes < 0 || spec.modes > limits::kMaxReducedModes)
      r->at("modes").fail("must be between 0 and " + std::to_string(limits::kMaxReducedModes) +
                          " (src/base/limits.hpp)");
  } else if (r->has("modes")) {
    r->at("modes").fail("modes only with craig_bampton");
  }
}

/// Structural damping of the reduced body: D = α M_e + β K_e (`stiffness_proportional: β` or `rayleigh`).
void readFemDamping(const CaseNode& n, Body& b) {
  const auto d = n.find("damping");
  if (!d) return;
  d->allowKeys({"stiffness_proportional", "rayleigh"});
  if (d->entries().size() != 1) d->fail("give one of stiffness_proportional, rayleigh");
  double alpha = 0, beta = 0;
  if (const auto s = d->find("stiffness_proportional")) beta = s->number();
  if (const auto r = d->find("rayleigh")) {
    r->allowKeys({"alpha", "beta"});
    alpha = r->number("alpha", 0);
    beta = r->number("beta", 0);
  }
  b.elastic.D = alpha * fem::elasticMass(b.inertia) + beta * b.elastic.K;
}

/// DOF names "<body> <point or n<k>> <ux…rz>" and "<body> CB j".
void addFemDofs(const fem::FemBody& fb, const std::map<int, std::string>& point_name, int index, const CaseNode& n,
                CaseBuild& build) {
  const std::string& body = build.model().bodies[index].name;
  for (size_t k = 0; k < fb.dof_names.size(); ++k) {
    std::string s = fb.dof_names[k];
    if (s[0] == 'n') {
      const auto it = point_name.find(std::stoi(s.substr(1)));
      if (it != point_name.end()) s = it->second + s.substr(s.find(' '));
    }
    build.addDof(body + " " + s, DofKind::Elastic, index, static_cast<int>(k), n.where(), false);
  }
}

}  // namespace

void readFemBody(const CaseNode& n, int index, CaseBuild& build) {
  Body& b = build.model().bodies[index];
  fem::StraightBeamSpec spec;
  const CaseNode len = n.at("length");
  const double L = spec.length = len.number();
  if (!(L > 0)) len.fail("the length must be positive");
  if (const auto e = n.find("elements")) {
    spec.elements = e->integer();
    if (spec.elements < 1 || spec.elements > limits::kMaxFemElements)
      e->fail("must be between 1 and " + std::to_string(limits::kMaxFemElements) + " (src/base/limits.hpp)");
  }
  const auto uni = n.find("uniform"), tab = n.find("properties");
  if (uni && tab) tab->fail("give uniform or properties, not both");
  if (!uni && !tab) n.fail("an FE beam needs uniform or properties");
  const CaseNode& props_node = uni ? *uni : *tab;
  spec.props = femProperties(props_node, L, uni.has_value());
  spec.timoshenko = n.boolean("timoshenko", false);

  const std::vector<FemPoint> pts = readFemPoints(n, L, b.name);
  for (const FemPoint& p : pts) spec.points.emplace_back(p.name, p.x);
  spec.soil = readFemSoil(n, L);
  const PointIndex pointIndex = [&](const CaseNode& v) {
    const std::string s = v.text();
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (pts[i].name == s) return static_cast<int>(i);
    v.fail("no point named '" + s + "' in body '" + b.name + "' (points of an FE body are its nodes)");
  };
  if (const auto d = n.find("dofs")) spec.active = readActiveDofs(*d);
  readFemSupports(n, pointIndex, spec);
  readFemMasses(n, pointIndex, spec);
  requireFemStiffnessAndInertia(spec.props, spec.active, props_node);
  readFemReduction(n, pointIndex, spec);

  fem::StraightBeamBody beam;
  try {
    beam = fem::buildStraightBeamBody(spec, b.name);
  } catch (const std::exception& e) {
    rethrowAt(n.where(), e);
  }
  fem::FemBody& fb = beam.body;
  b.inertia = fb.body.inertia;
  b.elastic = fb.body.elastic;
  b.points = fb.body.points;
  readFemDamping(n, b);
  std::map<int, std::string> point_name;
  for (std::size_t i = 0; i < pts.size(); ++i) point_name.emplace(beam.point_node[i], pts[i].name);
  addFemDofs(fb, point_name, index, n, build);
  if (n.boolean("geometric_stiffness", true)) {
    auto pend = std::make_shared<FemPending>();
    pend->body = b.name;
    pend->model = std::move(beam.model);
    pend->fb = std::move(beam.body);
    pend->point_node = std::move(beam.point_node);
    pend->where = n.where();
    build.fem.push_back(pend);
  }
}

void addFemGeometricStiffness(Model& m, const std::vector<std::shared_ptr<FemPending>>& pending) {
  if (pending.empty() || m.gravity.isZero(0)) return;
  const GravityAtRest g = gravityAtRest(m);
  for (const auto& p : pending) {
    const int bi = *m.findBody(p->body);
    std::vector<fem::CarriedMass> loads;
    for (size_t c = 0; c < m.bodies.size(); ++c) {
      const Body& child = m.bodies[c];
      if (child.parent != bi) continue;
      if (child.parent_point < 0)
        throw InputError(where(p->where.file, p->where.line, "",
                               "body '" + child.name + "' sits on FE body '" + p->body +
                                   "' without a point: attach it at a node (`at:`)"));
      loads.push_back({p->point_node[child.parent_point], g.carried[c]});
    }
    try {
      m.bodies[bi].elastic.K += fem::gravityGeometricStiffness(p->fb, p->model, g.gravity_body[bi], loads);
    } catch (const std::exception& e) {
      rethrowAt(p->where, e);
    }
  }
}

}  // namespace whirl

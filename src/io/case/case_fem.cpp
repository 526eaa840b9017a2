// Finite-element beam bodies of a case (`type: fem_beam`): properties, mesh, boundary conditions,
// springs, lumped masses, reduction (none, Guyan, Craig–Bampton) → a Ritz body (src/fem/). After
// finalize(), the geometric stiffness of the gravity loads each FE body carries is added.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/fem/fem_body.hpp"
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

int nodeAt(const fem::BeamModel& m, double x) {
  int best = 0;
  for (int i = 1; i < m.nnodes(); ++i)
    if (std::abs(m.nodes[i].x() - x) < std::abs(m.nodes[best].x() - x)) best = i;
  return best;
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

/// Distributed soil springs (`soil:` kx, ky, kz per length along x), interpolated linearly.
struct FemSoil {
  Columns columns;
  VecX x;
  /// Stiffness per length of column `c` at x; 0 outside the table or where the column is absent.
  double at(const char* c, double xs, double L) const {
    if (!columns.count(c) || xs < x(0) - 1e-9 * L || xs > x(x.size() - 1) + 1e-9 * L) return 0.0;
    const VecX& v = columns.at(c).values;
    Eigen::Index i = 0;
    while (i < x.size() - 2 && xs > x(i + 1)) ++i;
    const double w = std::clamp((xs - x(i)) / (x(i + 1) - x(i)), 0.0, 1.0);
    return (1 - w) * v(i) + w * v(i + 1);
  }
};

std::optional<FemSoil> readFemSoil(const CaseNode& n, double L) {
  const auto s = n.find("soil");
  if (!s) return std::nullopt;
  FemSoil soil;
  soil.columns = readColumns(*s, {"x", "fraction", "kx", "ky", "kz"}, {});
  soil.x = stations(*s, soil.columns, L, false);
  if (soil.x(0) < -1e-9 * L || soil.x(soil.x.size() - 1) > L * (1 + 1e-9))
    s->fail("soil stations must lie on the beam");
  for (const char* k : {"kx", "ky", "kz"})
    if (soil.columns.count(k)) requireNonNegative(soil.columns.at(k));
  return soil;
}

/// Soil springs on the elements whose middle lies in the soil table (nodal values at both ends).
void applyFemSoil(const FemSoil& soil, double L, fem::BeamModel& fm) {
  for (fem::Element& e : fm.elements) {
    const double x1 = fm.nodes[e.n1].x(), x2 = fm.nodes[e.n2].x(), xm = 0.5 * (x1 + x2);
    if (xm < soil.x(0) || xm > soil.x(soil.x.size() - 1)) continue;
    e.k1 = Vec3(soil.at("kx", x1, L), soil.at("ky", x1, L), soil.at("kz", x1, L));
    e.k2 = Vec3(soil.at("kx", x2, L), soil.at("ky", x2, L), soil.at("kz", x2, L));
  }
}

/// Node of a point named in `v`; an FE body's points are its nodes.
using PointNode = std::function<int(const CaseNode&)>;

void readFemSupports(const CaseNode& n, const PointNode& pointNode, fem::BeamModel& fm) {
  if (const auto c = n.find("clamped"))
    for (const CaseNode& p : c->items()) fem::clamp(fm, pointNode(p));
  if (const auto s = n.find("supports"))
    for (const CaseNode& sp : s->items()) {
      sp.allowKeys({"at", "K"});
      fem::NodeSpring ns;
      ns.node = pointNode(sp.at("at"));
      const CaseNode k = sp.at("K");
      ns.K = k.matrix(6, 6);
      if ((ns.K - ns.K.transpose()).norm() > 1e-9 * ns.K.norm()) k.fail("the 6×6 stiffness matrix must be symmetric");
      fm.springs.push_back(ns);
    }
}

void readFemMasses(const CaseNode& n, const PointNode& pointNode, fem::BeamModel& fm) {
  if (const auto ms = n.find("masses"))
    for (const CaseNode& mm : ms->items()) {
      mm.allowKeys({"at", "mass", "inertia"});
      fem::NodeMass nm;
      nm.node = pointNode(mm.at("at"));
      nm.mass = mm.number("mass", 0);
      if (nm.mass < 0) mm.at("mass").fail("negative mass");
      if (const auto j = mm.find("inertia")) {
        const Vec3 d = j->vec3();
        if ((d.array() < 0).any()) j->fail("inertia [Jxx, Jyy, Jzz] about the node must not be negative");
        nm.inertia = d.asDiagonal();
      }
      fm.masses.push_back(nm);
    }
}

/// Each active DOF kind needs stiffness and inertia, else K or M is singular; `props_node`: the
/// `uniform` or `properties` node the message points at.
void requireFemStiffnessAndInertia(const fem::BeamStations& props, const std::array<bool, 6>& active,
                                   const CaseNode& props_node, fem::BeamModel& fm) {
  auto need = [&](int k, const VecX& v, const char* what) {
    if (active[k] && (v.size() == 0 || (v.array() <= 0).any()))
      props_node.fail(std::string("DOF ") + fem::kNodeDofNames[k] + " needs " + what + " > 0 (or leave " +
                      fem::kNodeDofNames[k] + " out of `dofs`)");
  };
  need(0, props.EA, "EA");
  need(3, props.GJ, "GJ");
  need(3, props.iy2, "jG");
  for (fem::Element& e : fm.elements)  // unused kinds: any positive value keeps the element valid
    if (!active[0]) e.s1.EA = e.s2.EA = 1.0;
}

void readFemReduction(const CaseNode& n, const PointNode& pointNode, fem::FemBodySpec& spec) {
  const auto r = n.find("reduction");
  if (!r) return;
  r->allowKeys({"type", "interface", "modes"});
  const std::string t = r->at("type").text();
  if (t == "none") spec.reduction = fem::ReductionKind::None;
  else if (t == "guyan") spec.reduction = fem::ReductionKind::Guyan;
  else if (t == "craig_bampton") spec.reduction = fem::ReductionKind::CraigBampton;
  else r->at("type").fail("unknown reduction '" + t + "' (allowed: none, guyan, craig_bampton)");
  if (spec.reduction != fem::ReductionKind::None) {
    for (const CaseNode& p : r->at("interface").items()) spec.interface_nodes.push_back(pointNode(p));
    if (spec.interface_nodes.empty()) r->at("interface").fail("the interface needs at least one point");
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
  const CaseNode len = n.at("length");
  const double L = len.number();
  if (!(L > 0)) len.fail("the length must be positive");
  int elements = 20;
  if (const auto e = n.find("elements")) {
    elements = e->integer();
    if (elements < 1 || elements > limits::kMaxFemElements)
      e->fail("must be between 1 and " + std::to_string(limits::kMaxFemElements) + " (src/base/limits.hpp)");
  }
  const auto uni = n.find("uniform"), tab = n.find("properties");
  if (uni && tab) tab->fail("give uniform or properties, not both");
  if (!uni && !tab) n.fail("an FE beam needs uniform or properties");
  const CaseNode& props_node = uni ? *uni : *tab;
  const fem::BeamStations props = femProperties(props_node, L, uni.has_value());

  // The mesh contains the points and the ends of the soil table.
  const std::vector<FemPoint> pts = readFemPoints(n, L, b.name);
  const std::optional<FemSoil> soil = readFemSoil(n, L);
  std::vector<double> extra;
  for (const FemPoint& p : pts) extra.push_back(p.x);
  if (soil) extra.insert(extra.end(), {soil->x(0), soil->x(soil->x.size() - 1)});
  fem::FemBodySpec spec;
  spec.model = fem::straightBeam(props, fem::meshStations(0, L, elements, extra), n.boolean("timoshenko", false));
  fem::BeamModel& fm = spec.model;
  if (soil) applyFemSoil(*soil, L, fm);

  std::map<std::string, int> node_of;
  for (const FemPoint& p : pts) {
    node_of[p.name] = nodeAt(fm, p.x);
    spec.points.emplace_back(p.name, node_of[p.name]);
  }
  const PointNode pointNode = [&](const CaseNode& v) {
    const std::string s = v.text();
    const auto it = node_of.find(s);
    if (it == node_of.end())
      v.fail("no point named '" + s + "' in body '" + b.name + "' (points of an FE body are its nodes)");
    return it->second;
  };
  std::array<bool, 6> active{true, true, true, true, true, true};
  if (const auto d = n.find("dofs")) active = readActiveDofs(*d);
  fem::keepOnly(fm, active);
  readFemSupports(n, pointNode, fm);
  readFemMasses(n, pointNode, fm);
  requireFemStiffnessAndInertia(props, active, props_node, fm);
  readFemReduction(n, pointNode, spec);

  fem::FemBody fb;
  try {
    fb = fem::buildFemBody(spec, b.name);
  } catch (const std::exception& e) {
    rethrowAt(n.where(), e);
  }
  b.inertia = fb.body.inertia;
  b.elastic = fb.body.elastic;
  b.points = fb.body.points;
  readFemDamping(n, b);
  std::map<int, std::string> point_name;
  for (const FemPoint& p : pts) point_name.emplace(node_of[p.name], p.name);
  addFemDofs(fb, point_name, index, n, build);
  if (n.boolean("geometric_stiffness", true)) {
    auto pend = std::make_shared<FemPending>();
    pend->body = b.name;
    pend->model = fm;
    pend->fb = std::move(fb);
    for (const FemPoint& p : pts) pend->point_node.push_back(node_of[p.name]);
    pend->where = n.where();
    build.fem.push_back(pend);
  }
}

void addFemGeometricStiffness(Model& m, const std::vector<std::shared_ptr<FemPending>>& pending) {
  if (pending.empty() || m.gravity.isZero(0)) return;
  Workspace<double> ws(m);
  VecX q(m.ndof());
  for (int k = 0; k < m.ndof(); ++k) q(k) = m.dofs[k].value;
  const VecX zero = VecX::Zero(m.ndof());
  forwardKinematics(m, ws, q, zero, zero);
  // Mass of each body with everything it carries (parents come before children).
  std::vector<double> carried(m.bodies.size());
  for (size_t i = 0; i < m.bodies.size(); ++i) carried[i] = m.bodies[i].inertia.mass;
  for (int i = static_cast<int>(m.bodies.size()) - 1; i >= 0; --i)
    if (m.bodies[i].parent >= 0) carried[m.bodies[i].parent] += carried[i];
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
      loads.push_back({p->point_node[child.parent_point], carried[c]});
    }
    const Vec3 g_body = ws.frames[bi].R.transpose() * m.gravity;
    try {
      m.bodies[bi].elastic.K += fem::gravityGeometricStiffness(p->fb, p->model, g_body, loads);
    } catch (const std::exception& e) {
      rethrowAt(p->where, e);
    }
  }
}

}  // namespace whirl

// Beam bodies of a case: spanwise properties, integration, damping and points; the shapes are in
// case_shapes.cpp. The body data come from buildBeamBody and beamPoint (src/shapes/beam.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/case/case_columns.hpp"
#include "src/io/case/case_reader.hpp"
#include "src/shapes/beam.hpp"

namespace whirl {
namespace {

const std::vector<std::string> kPropertyColumns = {"x",     "fraction",  "m",  "EIy", "EIz", "GKt", "jG",
                                                   "twist", "twist_deg", "y0", "z0",  "cgy", "cgz"};

BeamProperties uniformProperties(const CaseNode& u, double L) {
  u.allowKeys({"m", "EIy", "EIz", "GKt", "jG"});
  BeamProperties p;
  p.length = L;
  p.x = VecX::LinSpaced(2, 0, L);
  auto value = [&](const char* key, bool required, bool strict) {
    const auto n = u.find(key);
    if (!n && required) u.fail(std::string("missing key '") + key + "'");
    const double v = n ? n->number() : 0.0;
    if (n && (v < 0 || (strict && v == 0))) n->fail(strict ? "must be positive" : "must not be negative");
    return VecX(VecX::Constant(2, v));
  };
  p.m = value("m", true, false);
  p.EIy = value("EIy", true, true);
  p.EIz = value("EIz", true, true);
  if (u.has("GKt")) p.GKt = value("GKt", false, false);
  if (u.has("jG")) p.jG = value("jG", false, false);
  return p;
}

BeamProperties tabulatedProperties(const CaseNode& n, double L) {
  const Columns c = readColumns(n, kPropertyColumns, {});
  BeamProperties p;
  p.length = L;
  p.x = stations(n, c, L, true);
  auto column = [&](const char* key, bool required, int sign) {
    if (!c.count(key)) {
      if (required) n.fail(std::string("missing column '") + key + "'");
      return VecX();
    }
    if (sign >= 0) requireNonNegative(c.at(key), sign > 0);
    return c.at(key).values;
  };
  p.m = column("m", true, 0);
  p.EIy = column("EIy", true, 1);
  p.EIz = column("EIz", true, 1);
  p.GKt = column("GKt", false, 0);
  p.jG = column("jG", false, 0);
  if (c.count("twist") && c.count("twist_deg")) c.at("twist_deg").where.fail("give twist or twist_deg, not both");
  p.twist = c.count("twist_deg") ? VecX(column("twist_deg", false, -1) * (std::numbers::pi / 180))
                                 : column("twist", false, -1);
  p.y0 = column("y0", false, -1);
  p.z0 = column("z0", false, -1);
  p.cgy = column("cgy", false, -1);
  p.cgz = column("cgz", false, -1);
  return p;
}

BeamIntegration readIntegration(const CaseNode& n) {
  n.allowKeys({"method", "n"});
  BeamIntegration q;
  std::string s = "gauss";
  if (const auto m = n.find("method")) {
    s = m->text();
    if (s == "gauss") q.method = BeamIntegration::Gauss;
    else if (s == "trapezoid") q.method = BeamIntegration::Trapezoid;
    else if (s == "midpoint") q.method = BeamIntegration::Midpoint;
    else if (s == "stations") q.method = BeamIntegration::Stations;
    else m->fail("unknown method '" + s + "' (allowed: gauss, trapezoid, midpoint, stations)");
  }
  if (const auto k = n.find("n")) {
    if (q.method == BeamIntegration::Stations)
      k->fail("n has no meaning with method stations (the property stations are used)");
    q.n = k->integer();
    const int most = q.method == BeamIntegration::Gauss ? limits::kMaxGaussPoints : limits::kMaxIntegrationPoints;
    if (q.n < 1 || q.n > most)
      k->fail("must be between 1 and " + std::to_string(most) + " with method " + s + " (src/base/limits.hpp)");
  }
  return q;
}

BeamDamping readDamping(const CaseNode& n, int ne) {
  n.allowKeys({"ratio", "stiffness_proportional", "rayleigh"});
  const std::vector<MapEntry> e = n.entries();
  if (e.size() != 1) n.fail("give one of ratio, stiffness_proportional, rayleigh");
  BeamDamping d;
  const CaseNode& v = e[0].value;
  if (e[0].key == "ratio") {
    d.kind = BeamDamping::ModalRatio;
    d.ratio = v.numbers();
    if (static_cast<int>(d.ratio.size()) != ne)
      v.fail("one ratio per shape: " + std::to_string(ne) + " shapes, " + std::to_string(d.ratio.size()) + " ratios");
  } else if (e[0].key == "stiffness_proportional") {
    d.kind = BeamDamping::StiffnessProportional;
    d.beta = v.number();
  } else {
    v.allowKeys({"alpha", "beta"});
    d.kind = BeamDamping::Rayleigh;
    d.alpha = v.number("alpha", 0);
    d.beta = v.number("beta", 0);
  }
  return d;
}

double pointStation(const CaseNode& p, double L) {
  p.allowKeys({"name", "x", "fraction"});
  const auto x = p.find("x"), f = p.find("fraction");
  if (x && f) f->fail("give x or fraction, not both");
  if (!x && !f) p.fail("missing key 'x' (or 'fraction')");
  const double v = x ? x->number() : f->number() * L;
  if (v < -1e-9 * L || v > L * (1 + 1e-9)) (x ? *x : *f).fail("the point must lie on the beam, 0 ≤ x ≤ " + num(L));
  return std::clamp(v, 0.0, L);
}

}  // namespace

void readBeamBody(const CaseNode& n, int index, CaseBuild& build) {
  const CaseNode len = n.at("length");
  const double L = len.number();
  if (!(L > 0)) len.fail("the length must be positive");
  const auto uni = n.find("uniform"), tab = n.find("properties");
  if (uni && tab) tab->fail("give uniform or properties, not both");
  if (!uni && !tab) n.fail("a beam needs uniform or properties");
  const BeamProperties p = uni ? uniformProperties(*uni, L) : tabulatedProperties(*tab, L);
  const std::vector<ShapePtr> shapes = readShapes(n, p, index, build);
  BeamOptions opt;
  if (const auto q = n.find("integration")) opt.integration = readIntegration(*q);
  if (const auto d = n.find("damping")) opt.damping = readDamping(*d, static_cast<int>(shapes.size()));
  opt.axial_shortening = n.boolean("axial_shortening", true);
  const auto sh = n.find("shapes");
  fem::ModeShapeInput fe;
  fe.props = p;
  if (sh && sh->isMap()) fe = readFemShapeSettings(*sh, p);
  build.beams.push_back({index, p, shapes, fe, opt.axial_shortening, false, {}});
  Body& b = build.model().bodies[index];
  try {
    const BeamBody bb = buildBeamBody(p, shapes, opt, b.name);
    b.inertia = bb.inertia;
    b.elastic = bb.elastic;
  } catch (const InputError& e) {
    rethrowAt(n.where(), e);
  }
  b.nodes = beamNodes(p, shapes, opt.axial_shortening, L);
  if (const auto pts = n.find("points"))
    for (const CaseNode& pt : pts->items()) {
      const double x = pointStation(pt, L);
      const std::string name = pt.at("name").text();
      for (const auto& q : b.points)
        if (q.name == name) pt.at("name").fail("point name '" + name + "' used twice in body '" + b.name + "'");
      b.points.push_back(beamPoint(p, shapes, opt.axial_shortening, x, name));
    }
}

}  // namespace whirl

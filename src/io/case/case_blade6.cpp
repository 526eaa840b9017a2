// Blades of a case described by 6 × 6 sections (`type: fe_blade`): BeamDyn's description written in
// the case — the reference axis through key points (kp_xr, kp_yr, kp_zr, twist), stations η with their
// 6 × 6 stiffness K and mass M in BeamDyn's section frame, the stiffness-proportional damping mu — built
// by the code path of a BeamDyn deck's blade (src/fem/blade6_body.hpp: mesh, fixed-root modes, the
// modes as Rayleigh–Ritz shapes). The matrices are checked as the BeamDyn reader checks them
// (src/io/openfast/beamdyn/beamdyn_input.cpp).
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/fem/blade6_body.hpp"
#include "src/fem/blade6_moments.hpp"
#include "src/io/case/case_columns.hpp"
#include "src/io/case/case_reader.hpp"
#include "src/shapes/beam.hpp"

namespace whirl {
namespace {

// The key points: columns kp_xr, kp_yr, kp_zr [m] (blade-root frame) and the twist (twist [rad] or
// twist_deg), at least three, z_r increasing.
std::vector<fem::Blade6KeyPoint> readReferenceAxis(const CaseNode& n) {
  const Columns c = readColumns(n, {"kp_xr", "kp_yr", "kp_zr", "twist", "twist_deg"}, {});
  for (const char* k : {"kp_xr", "kp_yr", "kp_zr"})
    if (!c.count(k)) n.fail(std::string("missing column '") + k + "'");
  if (c.count("twist") && c.count("twist_deg")) c.at("twist_deg").where.fail("give twist or twist_deg, not both");
  const Column& z = c.at("kp_zr");
  if (z.values.size() < 3) z.where.fail("the reference axis needs at least 3 key points (a parabola through three)");
  std::vector<fem::Blade6KeyPoint> kp;
  for (Eigen::Index i = 0; i < z.values.size(); ++i) {
    if (i > 0 && !(z.values(i) > z.values(i - 1)))
      z.failAt(i, "key points must advance along z_r (towards the tip): " + num(z.values(i)) + " after " +
                      num(z.values(i - 1)));
    fem::Blade6KeyPoint p;
    p.r = Vec3(c.at("kp_xr").values(i), c.at("kp_yr").values(i), z.values(i));
    if (c.count("twist")) p.twist = c.at("twist").values(i);
    if (c.count("twist_deg")) p.twist = c.at("twist_deg").values(i) * std::numbers::pi / 180;
    kp.push_back(p);
  }
  return kp;
}

// A symmetric 6 × 6 matrix to the precision a table is typed with (the BeamDyn reader's test:
// |a_ij − a_ji| ≤ 1e-5 max(|a_ij|, |a_ji|), or ≤ 1e-9 of the largest diagonal entry), symmetrized.
fem::Mat6s symmetric6(const CaseNode& n) {
  const fem::Mat6s A = n.matrix(6, 6);
  const double scale = A.diagonal().cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const double a = A(i, j), b = A(j, i);
      if (std::abs(a - b) > std::max(1e-5 * std::max(std::abs(a), std::abs(b)), 1e-9 * scale))
        n.fail("not symmetric: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") = " + num(a) +
               " but (" + std::to_string(j + 1) + "," + std::to_string(i + 1) + ") = " + num(b));
    }
  return 0.5 * (A + A.transpose());
}

fem::Blade6Station readSection(const CaseNode& s) {
  s.allowKeys({"eta", "K", "M"});
  fem::Blade6Station st;
  st.eta = s.at("eta").number();
  const CaseNode k = s.at("K"), m = s.at("M");
  st.K = symmetric6(k);
  st.M = symmetric6(m);
  if (Eigen::LLT<fem::Mat6s>(st.K).info() != Eigen::Success || !(st.K.diagonal().array() > 0).all())
    k.fail("not positive definite (every strain must take energy)");
  if (!(st.M(0, 0) > 0) || st.M(1, 1) != st.M(0, 0) || st.M(2, 2) != st.M(0, 0))
    m.fail("the first three diagonal entries must be the same positive mass per length");
  const Eigen::SelfAdjointEigenSolver<fem::Mat6s> eig(st.M, Eigen::EigenvaluesOnly);
  if (eig.eigenvalues().minCoeff() < -1e-9 * st.M.diagonal().maxCoeff())
    m.fail("not positive semi-definite (negative kinetic energy)");
  return st;
}

// The stations: η from 0 to 1, increasing.
std::vector<fem::Blade6Station> readSections(const CaseNode& n) {
  const std::vector<CaseNode> items = n.items();
  if (items.size() < 2) n.fail("a blade needs at least 2 sections (η = 0 and η = 1)");
  if (items.size() > static_cast<std::size_t>(limits::kMaxFemElements))
    n.fail("more than " + std::to_string(limits::kMaxFemElements) + " sections (src/base/limits.hpp)");
  std::vector<fem::Blade6Station> out;
  for (const CaseNode& s : items) {
    out.push_back(readSection(s));
    const CaseNode eta = s.at("eta");
    if (out.size() == 1 && out.back().eta != 0.0) eta.fail("the first section must be at η = 0");
    if (out.size() > 1 && !(out.back().eta > out[out.size() - 2].eta))
      eta.fail("sections must increase in η: " + num(out.back().eta) + " after " + num(out[out.size() - 2].eta));
  }
  if (out.back().eta != 1.0) items.back().at("eta").fail("the last section must be at η = 1");
  return out;
}

int boundedInteger(const CaseNode& n, std::string_view key, int fallback, int lo, int hi) {
  const auto v = n.find(key);
  if (!v) return fallback;
  const int k = v->integer();
  if (k < lo || k > hi) v->fail("must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return k;
}

}  // namespace

void readBlade6Body(const CaseNode& n, int index, CaseBuild& build) {
  fem::Blade6Input in;
  in.key_points = readReferenceAxis(n.at("reference_axis"));
  in.stations = readSections(n.at("sections"));
  if (const auto mu = n.find("mu")) {
    const std::vector<double> v = mu->numbers();
    if (v.size() != 6) mu->fail("expected the 6 factors mu1 … mu6 [s], got " + std::to_string(v.size()));
    for (std::size_t k = 0; k < 6; ++k) {
      if (v[k] < 0) mu->fail("must not be negative");
      in.mu[k] = v[k];
    }
  }
  fem::Blade6Options opt;
  opt.elements = boundedInteger(n, "elements", opt.elements, 2, limits::kMaxFemElements);
  opt.modes = boundedInteger(n, "modes", opt.modes, 1, 6 * opt.elements);
  const bool axial_shortening = n.boolean("axial_shortening", true);
  Body& b = build.model().bodies[index];
  fem::Blade6Body fe;
  BeamOptions o;
  // The FE shapes are linear between the FE nodes: 4 trapezoid points per element (as a deck's blade).
  o.integration = {BeamIntegration::Trapezoid, 4 * opt.elements};
  o.axial_shortening = axial_shortening;
  try {
    fe = fem::blade6Body(in, opt);
    const BeamBody bb = buildBeamBody(fe.props, fe.shapes, o, b.name);
    b.inertia = bb.inertia;
  } catch (const std::exception& e) {
    rethrowAt(n.where(), e);
  }
  b.elastic.K = fe.K;
  b.elastic.D = fe.D;
  b.nodes = beamNodes(fe.props, fe.shapes, axial_shortening, fe.length);
  if (const auto pts = n.find("points"))
    for (const CaseNode& pt : pts->items()) {
      pt.allowKeys({"name", "x", "fraction"});
      const auto x = pt.find("x"), f = pt.find("fraction");
      if (x && f) f->fail("give x or fraction, not both");
      if (!x && !f) pt.fail("missing key 'x' (or 'fraction') along z_r");
      const double v = x ? x->number() : f->number() * fe.length;
      if (v < -1e-9 * fe.length || v > fe.length * (1 + 1e-9))
        (x ? *x : *f).fail("the point must lie on the blade, 0 ≤ x ≤ " + num(fe.length));
      const std::string name = pt.at("name").text();
      for (const auto& q : b.points)
        if (q.name == name) pt.at("name").fail("point name '" + name + "' used twice in body '" + b.name + "'");
      b.points.push_back(beamPoint(fe.props, fe.shapes, axial_shortening, std::clamp(v, 0.0, fe.length), name));
    }
  // The blade elements of an `aero:` block sit on the FE blade's modes as on a beam's shapes.
  CaseBuild::Beam record;
  record.body = index;
  record.props = fe.props;
  record.shapes = fe.shapes;
  record.axial_shortening = axial_shortening;
  record.finite_element = true;
  record.moment_gains = [fe = std::make_shared<const fem::Blade6Body>(fe)](double x) {
    return fem::blade6MomentGains(*fe, x);
  };
  build.beams.push_back(std::move(record));
  for (std::size_t s = 0; s < fe.shapes.size(); ++s)
    build.addDof(b.name + " " + fe.shapes[s]->name, DofKind::Elastic, index, static_cast<int>(s), n.where(), false);
}

}  // namespace whirl

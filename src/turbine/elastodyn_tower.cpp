// The ElastoDyn tower as a whirl beam body (ElastoDyn `Coeff`, tower part).
#include <cmath>

#include "src/base/error.hpp"
#include "src/shapes/beam.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"
#include "src/turbine/elastodyn_fem_shapes.hpp"
#include "src/turbine/elastodyn_parts.hpp"
#include "src/turbine/elastodyn_tower_beam.hpp"

namespace whirl {
namespace {

VecX column(const io::DistributedTable& t, const char* name, double scale) {
  const std::vector<double>& c = t.column(name);
  VecX v(static_cast<Eigen::Index>(c.size()));
  for (std::size_t i = 0; i < c.size(); ++i) v(static_cast<Eigen::Index>(i)) = scale * c[i];
  return v;
}

// Σ c_k (h/L)^k, k = 2..6, along the body direction (dy, dz).
ShapePtr towerShape(const char* name, double L, const io::ModeShapeCoeffs& c, double dy, double dz) {
  return polynomialShape(name, L, {0.0, 0.0, c[0], c[1], c[2], c[3], c[4]}, dy, dz);
}

}  // namespace

ElastoDynTowerBeam elastoDynTowerBeam(const io::ElastoDynInput& ed) {
  const io::ElastoDynTower& tw = ed.tower;
  const std::string file = tw.source.path().string();
  // Tower base: TowerBsHt (OpenFAST), or −TwrDraft in ElastoDyn v1.00 files (TwrRBHt ≠ 0 is refused).
  ElastoDynTowerBeam t;
  t.base = ed.config.TowerBsHt.value_or(-ed.config.TwrDraft.value_or(0.0));
  const double L = ed.config.TowerHt - t.base;
  if (!(L > 0))
    throw InputError(ed.source.where("TowerHt", "must be above the tower base (" + std::to_string(t.base) +
                                                    " m): no flexible tower"));
  BeamProperties& p = t.props;
  p.length = L;
  p.x = column(tw.distributed, "HtFract", L);
  p.x(p.x.size() - 1) = L;
  p.m = column(tw.distributed, "TMassDen", tw.AdjTwMa);
  p.EIy = column(tw.distributed, "TwSSStif", tw.AdjSSSt);  // body y = side-to-side
  p.EIz = column(tw.distributed, "TwFAStif", tw.AdjFASt);  // body z = fore-aft
  try {
    validateBeam(p, "tower");
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  // FA shapes along body z (ground X), SS along body y (ground −Y): ElastoDyn's a1 and a3.
  t.shapes = {towerShape("tower FA 1", L, tw.TwFAM1Sh, 0, 1), towerShape("tower SS 1", L, tw.TwSSM1Sh, 1, 0),
              towerShape("tower FA 2", L, tw.TwFAM2Sh, 0, 1), towerShape("tower SS 2", L, tw.TwSSM2Sh, 1, 0)};
  return t;
}

void placeTowerTopAtDofValues(BodyPoint& top) {
  for (int i = 0; i < 4; ++i) top.P.col(1 + i) << 0.0, i % 2 == 1 ? 1.0 : 0.0, i % 2 == 0 ? 1.0 : 0.0;
}

namespace elastodyn {

TowerParts addTower(Builder& b, const PlatformParts& platform) {
  const io::ElastoDynInput& ed = b.ed;
  const io::ElastoDynTower& tw = ed.tower;
  if (ed.TwrNodes < 1) throw InputError(b.where("TwrNodes", "must be at least 1"));
  ElastoDynTowerBeam beam = elastoDynTowerBeam(ed);
  const BeamProperties& p = beam.props;
  const double L = p.length, base = beam.base;
  // Or (shapes=fem) the FE modes of the same properties with the rotor-nacelle top mass and gravity.
  if (b.opt.fem_shapes) beam.shapes = elastoDynTowerFemShapes(elastoDynTowerModeInput(ed, p, -b.model().gravity(2)));
  const std::vector<ShapePtr>& shapes = beam.shapes;
  BeamOptions o;
  o.integration = {BeamIntegration::Midpoint, ed.TwrNodes};
  o.axial_shortening = b.opt.axial_shortening;
  const BeamBody bb = buildBeamBody(p, shapes, o, "tower");

  // ElastoDyn's tuners on the generalized stiffness, then its modal damping at the frequencies of the
  // tower alone (generalized masses Σ m φ² ΔH, no tower-top mass).
  VecX tuner(4), zeta(4), mass(4);
  tuner << tw.FAStTunr[0], tw.SSStTunr[0], tw.FAStTunr[1], tw.SSStTunr[1];
  zeta << tw.TwrFADmp[0], tw.TwrSSDmp[0], tw.TwrFADmp[1], tw.TwrSSDmp[1];
  zeta *= 0.01;
  for (int i = 0; i < 4; ++i) {
    mass(i) = 0;
    for (int k = 0; k < 3; ++k) mass(i) += bb.inertia.S[4 * k](1 + i, 1 + i);
  }
  Body t;
  t.name = "tower";
  t.parent = platform.body;  // −1: clamped to the ground
  t.offset = Vec3(0, 0, base) - platform.reference;
  t.rotation.col(0) = Vec3::UnitZ();   // x up the tower
  t.rotation.col(1) = -Vec3::UnitY();  // y side-to-side (ElastoDyn a3)
  t.rotation.col(2) = Vec3::UnitX();   // z fore-aft (downwind)
  t.inertia = bb.inertia;
  t.elastic.K = applyStiffnessTuners(bb.elastic.K, tuner);
  t.elastic.D = elastoDynModalDamping(t.elastic.K, mass, zeta);
  BodyPoint top = beamPoint(p, shapes, o.axial_shortening, L, "top");
  placeTowerTopAtDofValues(top);
  t.points.push_back(std::move(top));
  t.nodes = beamNodes(p, shapes, o.axial_shortening, L);
  TowerParts out;
  out.body = b.addBody(std::move(t));
  out.top = 0;
  const bool on[4] = {ed.dof.TwFADOF1, ed.dof.TwSSDOF1, ed.dof.TwFADOF2, ed.dof.TwSSDOF2};
  for (int i = 0; i < 4; ++i) out.dofs[i] = b.addDof(shapes[i]->name, out.body, DofKind::Elastic, i, on[i]);
  return out;
}

}  // namespace elastodyn
}  // namespace whirl

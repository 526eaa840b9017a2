#include "src/fem/straight_beam_body.hpp"

#include <algorithm>
#include <cmath>

#include "src/fem/boundary.hpp"

namespace whirl::fem {

namespace {

/// Stiffness per length of `column` at xs: linear between the stations, 0 outside them or for an
/// empty column (the table's ends are nodes of the mesh, so no element straddles them).
double soilAt(const BeamSoil& soil, const VecX& column, double xs, double L) {
  const VecX& x = soil.x;
  if (column.size() == 0 || xs < x(0) - 1e-9 * L || xs > x(x.size() - 1) + 1e-9 * L) return 0.0;
  Eigen::Index i = 0;
  while (i < x.size() - 2 && xs > x(i + 1)) ++i;
  const double w = std::clamp((xs - x(i)) / (x(i + 1) - x(i)), 0.0, 1.0);
  return (1 - w) * column(i) + w * column(i + 1);
}

/// Soil springs on the elements whose middle lies in the soil table (nodal values at both ends).
void applySoil(const BeamSoil& soil, double L, BeamModel& fm) {
  for (Element& e : fm.elements) {
    const double x1 = fm.nodes[e.n1].x(), x2 = fm.nodes[e.n2].x(), xm = 0.5 * (x1 + x2);
    if (xm < soil.x(0) || xm > soil.x(soil.x.size() - 1)) continue;
    e.k1 = Vec3(soilAt(soil, soil.kx, x1, L), soilAt(soil, soil.ky, x1, L), soilAt(soil, soil.kz, x1, L));
    e.k2 = Vec3(soilAt(soil, soil.kx, x2, L), soilAt(soil, soil.ky, x2, L), soilAt(soil, soil.kz, x2, L));
  }
}

int nodeAt(const BeamModel& m, double x) {
  int best = 0;
  for (int i = 1; i < m.nnodes(); ++i)
    if (std::abs(m.nodes[i].x() - x) < std::abs(m.nodes[best].x() - x)) best = i;
  return best;
}

}  // namespace

StraightBeamBody buildStraightBeamBody(const StraightBeamSpec& spec, const std::string& name) {
  const double L = spec.length;
  std::vector<double> extra;
  for (const auto& p : spec.points) extra.push_back(p.second);
  if (spec.soil) extra.insert(extra.end(), {spec.soil->x(0), spec.soil->x(spec.soil->x.size() - 1)});
  StraightBeamBody out;
  FemBodySpec body;
  body.model = straightBeam(spec.props, meshStations(0, L, spec.elements, extra), spec.timoshenko);
  BeamModel& fm = body.model;
  if (spec.soil) applySoil(*spec.soil, L, fm);
  for (const auto& p : spec.points) {
    out.point_node.push_back(nodeAt(fm, p.second));
    body.points.emplace_back(p.first, out.point_node.back());
  }
  keepOnly(fm, spec.active);
  for (int p : spec.clamped) clamp(fm, out.point_node[static_cast<std::size_t>(p)]);
  for (const BeamPointSpring& s : spec.supports) {
    NodeSpring ns;
    ns.node = out.point_node[static_cast<std::size_t>(s.point)];
    ns.K = s.K;
    fm.springs.push_back(ns);
  }
  for (const BeamPointMass& m : spec.masses) {
    NodeMass nm;
    nm.node = out.point_node[static_cast<std::size_t>(m.point)];
    nm.mass = m.mass;
    nm.inertia = m.inertia;
    fm.masses.push_back(nm);
  }
  for (Element& e : fm.elements)  // unused kinds: any positive value keeps the element valid
    if (!spec.active[0]) e.s1.EA = e.s2.EA = 1.0;
  body.reduction = spec.reduction;
  for (int p : spec.interface_points) body.interface_nodes.push_back(out.point_node[static_cast<std::size_t>(p)]);
  body.modes = spec.modes;
  out.body = buildFemBody(body, name);
  out.model = std::move(fm);
  return out;
}

}  // namespace whirl::fem

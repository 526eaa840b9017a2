#include "src/fem/beam_model.hpp"

#include "src/shapes/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/base/error.hpp"

namespace whirl::fem {

const std::array<const char*, 6> kNodeDofNames = {"ux", "uy", "uz", "rx", "ry", "rz"};

namespace {

Section sectionAt(const BeamStations& p, double x) {
  Section s;
  s.m = interpolateStations(p.x, p.m, x);
  s.EA = interpolateStations(p.x, p.EA, x);
  s.EIy = interpolateStations(p.x, p.EIy, x);
  s.EIz = interpolateStations(p.x, p.EIz, x);
  s.GJ = interpolateStations(p.x, p.GJ, x);
  s.iy2 = interpolateStations(p.x, p.iy2, x);
  s.iz2 = interpolateStations(p.x, p.iz2, x);
  s.kGAy = interpolateStations(p.x, p.kGAy, x);
  s.kGAz = interpolateStations(p.x, p.kGAz, x);
  return s;
}

}  // namespace

Mat3 elementFrame(const BeamModel& m, const Element& e) {
  const Vec3 ex = (m.nodes[e.n2] - m.nodes[e.n1]).normalized();
  Vec3 ref = e.y_axis.isZero(0) ? Vec3::UnitY() : e.y_axis;
  Vec3 ey = ref - ref.dot(ex) * ex;
  if (ey.norm() < 1e-6) {  // element along body y: take body z as reference
    ref = Vec3::UnitZ();
    ey = ref - ref.dot(ex) * ex;
  }
  ey.normalize();
  Mat3 R;
  R.col(0) = ex;
  R.col(1) = ey;
  R.col(2) = ex.cross(ey);
  return R;
}

void validate(const BeamModel& m, const std::string& name) {
  auto fail = [&](const std::string& what) { throw InputError("FE model '" + name + "': " + what); };
  if (m.nodes.size() < 2 || m.elements.empty()) fail("needs at least one element");
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (!m.nodes[i].allFinite()) fail("node " + std::to_string(i) + ": position is not finite");
  for (size_t k = 0; k < m.elements.size(); ++k) {
    const Element& e = m.elements[k];
    const std::string el = "element " + std::to_string(k) + ": ";
    if (e.n1 < 0 || e.n2 < 0 || e.n1 >= m.nnodes() || e.n2 >= m.nnodes() || e.n1 == e.n2) fail(el + "bad node indices");
    if ((m.nodes[e.n2] - m.nodes[e.n1]).norm() <= 0) fail(el + "zero length");
    for (const Section* s : {&e.s1, &e.s2}) {
      const double v[] = {s->m, s->EA, s->EIy, s->EIz, s->GJ, s->iy2, s->iz2, s->kGAy, s->kGAz};
      for (double x : v)
        if (!std::isfinite(x)) fail(el + "a section property is not finite");
      if (s->m < 0 || s->iy2 < 0 || s->iz2 < 0) fail(el + "negative mass or rotary inertia");
      if (!(s->EA > 0) || !(s->EIy > 0) || !(s->EIz > 0)) fail(el + "EA, EIy and EIz must be positive");
      if (s->GJ < 0 || s->kGAy < 0 || s->kGAz < 0) fail(el + "negative GJ or shear stiffness");
    }
    if (!e.k1.allFinite() || !e.k2.allFinite() || (e.k1.array() < 0).any() || (e.k2.array() < 0).any())
      fail(el + "distributed springs must be finite and non-negative");
  }
  for (const NodeMass& nm : m.masses) {
    if (nm.node < 0 || nm.node >= m.nnodes()) fail("lumped mass at a node that does not exist");
    if (!std::isfinite(nm.mass) || nm.mass < 0 || !nm.inertia.allFinite()) fail("lumped mass: bad mass or inertia");
  }
  for (const NodeSpring& s : m.springs) {
    if (s.node < 0 || s.node >= m.nnodes()) fail("spring at a node that does not exist");
    if (!s.K.allFinite()) fail("spring matrix is not finite");
    if ((s.K - s.K.transpose()).norm() > 1e-9 * s.K.norm()) fail("spring matrix is not symmetric");
  }
  if (!m.fixed.empty() && static_cast<int>(m.fixed.size()) != m.nnodes()) fail("fixed flags: one entry per node");
}

BeamModel straightBeam(const BeamStations& p, const std::vector<double>& node_x, bool timoshenko) {
  BeamModel m;
  m.timoshenko = timoshenko;
  for (double x : node_x) m.nodes.emplace_back(x, 0.0, 0.0);
  for (size_t i = 0; i + 1 < node_x.size(); ++i) {
    Element e;
    e.n1 = static_cast<int>(i);
    e.n2 = static_cast<int>(i + 1);
    e.s1 = sectionAt(p, node_x[i]);
    e.s2 = sectionAt(p, node_x[i + 1]);
    e.k1 = Vec3(interpolateStations(p.x, p.soil_x, node_x[i]), interpolateStations(p.x, p.soil_y, node_x[i]),
                interpolateStations(p.x, p.soil_z, node_x[i]));
    e.k2 = Vec3(interpolateStations(p.x, p.soil_x, node_x[i + 1]), interpolateStations(p.x, p.soil_y, node_x[i + 1]),
                interpolateStations(p.x, p.soil_z, node_x[i + 1]));
    m.elements.push_back(e);
  }
  m.fixed.assign(m.nodes.size(), {false, false, false, false, false, false});
  return m;
}

std::vector<double> meshStations(double x0, double x1, int elements, const std::vector<double>& extra) {
  std::vector<double> x;
  for (int i = 0; i <= elements; ++i) x.push_back(x0 + (x1 - x0) * i / elements);
  const double tol = 1e-6 * (x1 - x0) / elements;
  for (double e : extra) {
    auto it = std::lower_bound(x.begin(), x.end(), e);
    if ((it != x.end() && std::abs(*it - e) < tol) || (it != x.begin() && std::abs(*(it - 1) - e) < tol)) continue;
    x.insert(it, e);
  }
  return x;
}

}  // namespace whirl::fem

// SubDyn's discretization, element properties, boundary conditions, reduction and damping on whirl's
// FE bodies (subdyn_fem.hpp).
#include "src/turbine/subdyn_fem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/fem/boundary.hpp"

namespace whirl {
namespace {

// Diameter and thickness at a node.
struct Tube {
  double D = 0, t = 0;
};

// The element section between two nodes, as SubDyn's SetElementProperties.
fem::Section tubeSection(const io::SubDynSection& mat, const Tube& a, const Tube& b, bool timoshenko) {
  const double ro = 0.25 * (a.D + b.D), t = 0.5 * (a.t + b.t);
  const double ri = t > 0 ? ro - t : 0.0;
  const double pi = std::numbers::pi;
  const double A = pi * (ro * ro - ri * ri), I = 0.25 * pi * (std::pow(ro, 4) - std::pow(ri, 4));
  fem::Section s;
  s.m = mat.rho * A;
  s.EA = mat.E * A;
  s.EIy = s.EIz = mat.E * I;
  s.GJ = mat.G * 2 * I;
  s.iy2 = s.iz2 = mat.rho * I;
  if (timoshenko) {
    // Shear coefficient of a thick circular tube (Steinboeck et al. 2013; SubDyn theory manual, eq. 13).
    const double nu = mat.E / (2 * mat.G) - 1, m2 = (ri / ro) * (ri / ro), q = (1 + m2) * (1 + m2);
    const double kappa = 6 * (1 + nu) * (1 + nu) * q /
                         (q * (7 + 14 * nu + 8 * nu * nu) + 4 * m2 * (5 + 10 * nu + 4 * nu * nu));
    s.kGAy = s.kGAz = kappa * mat.G * A;
  }
  return s;
}

}  // namespace

SubDynFem subDynFem(const io::SubDynInput& sd, const Vec3& tp_reference) {
  SubDynFem out;
  fem::FemBodySpec& spec = out.spec;
  fem::BeamModel& m = spec.model;
  m.timoshenko = sd.FEMMod == 3;
  for (const io::SubDynJoint& j : sd.joints) {
    m.nodes.push_back(j.position);
    out.node_names.push_back("joint " + std::to_string(j.id));
  }
  for (const io::SubDynMember& mb : sd.members) {
    const io::SubDynSection& s1 = sd.sections[sd.sectionIndex(mb.prop1)];
    const io::SubDynSection& s2 = sd.sections[sd.sectionIndex(mb.prop2)];
    const int a = sd.jointIndex(mb.joint1), b = sd.jointIndex(mb.joint2);
    // Member nodes 1 … NDiv + 1: the joints at the ends, new nodes between.
    std::vector<int> nodes{a};
    std::vector<Tube> tube{{s1.D, s1.t}};
    for (int k = 1; k < sd.NDiv; ++k) {
      const double f = static_cast<double>(k) / sd.NDiv;
      nodes.push_back(m.nnodes());
      m.nodes.push_back((1 - f) * m.nodes[a] + f * m.nodes[b]);
      out.node_names.push_back("member " + std::to_string(mb.id) + " node " + std::to_string(k + 1));
      tube.push_back({(1 - f) * s1.D + f * s2.D, (1 - f) * s1.t + f * s2.t});
    }
    nodes.push_back(b);
    tube.push_back({s2.D, s2.t});
    for (int k = 0; k < sd.NDiv; ++k) {
      fem::Element e;
      e.n1 = nodes[k];
      e.n2 = nodes[k + 1];
      e.s1 = e.s2 = tubeSection(s1, tube[k], tube[k + 1], m.timoshenko);
      m.elements.push_back(e);
    }
  }
  m.fixed.assign(m.nodes.size(), {false, false, false, false, false, false});
  for (const io::SubDynReaction& r : sd.reactions)
    for (int d = 0; d < 6; ++d) m.fixed[sd.jointIndex(r.joint)][d] = r.fixed[d];
  for (const io::SubDynMass& c : sd.masses) m.masses.push_back({sd.jointIndex(c.joint), c.mass, c.inertia});

  for (const io::SubDynInterface& i : sd.interfaces) spec.interface_nodes.push_back(sd.jointIndex(i.joint));
  spec.rigid_interface = tp_reference;
  spec.rigid_interface_name = "TP";
  // Interior DOFs: the free DOFs not tied to the TP.
  int interior = 0;
  const fem::DofMap map = fem::freeDofs(m);
  std::vector<bool> tied(m.nodes.size(), false);
  for (int n : spec.interface_nodes) tied[n] = true;
  for (int f : map.free) interior += tied[f / fem::kNodeDofs] ? 0 : 1;
  if (sd.Nmodes > interior)
    throw InputError(sd.source.where("Nmodes", "is " + std::to_string(sd.Nmodes) + ", more than the " +
                                                   std::to_string(interior) + " DOFs of the substructure's interior"));
  if (sd.Nmodes == 0) {
    spec.reduction = fem::ReductionKind::Guyan;
  } else {
    spec.reduction = fem::ReductionKind::CraigBampton;
    spec.modes = sd.Nmodes < 0 ? interior : sd.Nmodes;
  }
  return out;
}

SubDynBody buildSubDynBody(const io::SubDynInput& sd, const Vec3& tp_reference, const MatX& added_mass) {
  const SubDynFem f = subDynFem(sd, tp_reference);
  SubDynBody out;
  try {
    out.fem = fem::buildFemBody(f.spec, "substructure");
  } catch (const ComputeError& e) {
    // K_ii singular: the reactions and the TP leave part of the structure free (a mechanism).
    throw InputError(
        sd.source.where("NReact", std::string(e.what()) +
                                      " (is every part of the substructure held by its reaction joints and the TP?)"));
  }
  const int ne = static_cast<int>(f.spec.modes) + 6;
  const MatX Me = fem::elasticMass(out.fem.body.inertia);
  const MatX& Ke = out.fem.body.elastic.K;
  out.damping = MatX::Zero(ne, ne);
  if (sd.GuyanDampMod == 1)
    out.damping.topLeftCorner(6, 6) = sd.RayleighDamp[0] * Me.topLeftCorner(6, 6) +
                                      sd.RayleighDamp[1] * Ke.topLeftCorner(6, 6);
  else if (sd.GuyanDampMod == 2) out.damping.topLeftCorner(6, 6) = sd.GuyanDampMat;
  // Each mode: 2 ζ ω μ, μ its modal mass (the modes are scaled to a largest entry of 1, not to μ = 1).
  for (int j = 0; j < f.spec.modes; ++j) {
    const double zeta = sd.JDampings[std::min<std::size_t>(j, sd.JDampings.size() - 1)];
    const double omega = 2 * std::numbers::pi * out.fem.fixed_interface_hz(j);
    out.damping(6 + j, 6 + j) = 2 * zeta * omega * Me(6 + j, 6 + j);
  }
  if (added_mass.size() > 0) {
    const std::vector<int>& free = out.fem.map.free;
    MatX Af(free.size(), free.size());
    for (std::size_t r = 0; r < free.size(); ++r)
      for (std::size_t c = 0; c < free.size(); ++c) Af(r, c) = added_mass(free[r], free[c]);
    out.added_mass = out.fem.basis.transpose() * Af * out.fem.basis;
  }
  return out;
}

}  // namespace whirl

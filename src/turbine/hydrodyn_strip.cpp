#include "src/turbine/hydrodyn_strip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/io/elastodyn_common.hpp"
#include "src/model/error.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double kPi = std::numbers::pi;

std::string where(const io::HydroDynInput& hd, int line, const std::string& key, const std::string& reason) {
  return whirl::where(hd.source.path().string(), line, key, reason);
}

// A strip-theory member as a line: ends a, b, outer radius and coefficients linear between them.
struct StripMember {
  const io::HydroDynMember* row = nullptr;
  Vec3 a, b, k;
  double length = 0, Ra = 0, Rb = 0;
  io::HydroDynMemberCoef coef;
};

// The parameter s ∈ [0, 1] of point p on the member's axis, or −1 when p is not on it (1e-6 of its length).
double onAxis(const StripMember& m, const Vec3& p) {
  const double s = (p - m.a).dot(m.k) / m.length;
  const double off = (p - m.a - s * m.length * m.k).norm();
  const double tol = 1e-6 * m.length;
  if (off > tol || s < -tol / m.length || s > 1 + tol / m.length) return -1;
  return std::clamp(s, 0.0, 1.0);
}

// Adds ∫ N_iᵀ A(s) N_j over the part of the element (nodes n1, n2) in the water, the element lying on
// the member from parameter s1 (node 1) to s2 (node 2); returns the member length covered in the water.
double addElement(MatX& M, const StripMember& m, int n1, int n2, const Vec3& p1, const Vec3& p2, double s1, double s2,
                  double rho, double depth) {
  // The part of the element between the seabed and the still-water level, ξ ∈ [x0, x1].
  double x0 = 0, x1 = 1;
  const double z1 = p1(2), z2 = p2(2);
  for (double level : {0.0, -depth}) {
    const bool below = level == 0.0;  // keep z ≤ 0, then z ≥ −depth
    if (z1 == z2) {
      if (below ? z1 > level : z1 < level) return 0;
      continue;
    }
    const double xi = (level - z1) / (z2 - z1);
    if ((z2 > z1) == below) x1 = std::min(x1, xi);
    else x0 = std::max(x0, xi);
  }
  if (x1 <= x0) return 0;
  static const double kX[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double kW[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double Le = (p2 - p1).norm(), half = 0.5 * (x1 - x0);
  const Mat3 kk = m.k * m.k.transpose(), side = Mat3::Identity() - kk;
  const double dRdl = std::abs(m.Rb - m.Ra) / m.length;
  for (int g = 0; g < 3; ++g) {
    const double xi = x0 + half * (1 + kX[g]), s = s1 + (s2 - s1) * xi;
    const double R = m.Ra + (m.Rb - m.Ra) * s;
    const double Ca = m.coef.Ca1 + (m.coef.Ca2 - m.coef.Ca1) * s;
    const double AxCa = m.coef.AxCa1 + (m.coef.AxCa2 - m.coef.AxCa1) * s;
    const Mat3 A = rho * kPi * R * R * (Ca * side + 2 * AxCa * dRdl * kk);
    const double w = kW[g] * half * Le, N[2] = {1 - xi, xi};
    const int n[2] = {n1, n2};
    for (int i = 0; i < 2; ++i)
      M.block<3, 3>(fem::kNodeDofs * n[i], fem::kNodeDofs * n[i]) += w * N[i] * A;  // lumped: each node its share
  }
  return (x1 - x0) * Le;
}

// The node at p, or −1.
int nodeAt(const fem::BeamModel& model, const Vec3& p) {
  for (int n = 0; n < model.nnodes(); ++n)
    if ((model.nodes[n] - p).norm() <= 1e-6 * std::max(1.0, p.norm())) return n;
  return -1;
}

}  // namespace

MatX stripTheoryAddedMass(const io::HydroDynInput& hd, const fem::BeamModel& model, double rho, double depth) {
  const io::HydroDynMembers& g = hd.geometry;
  MatX M = MatX::Zero(model.ndof(), model.ndof());
  std::vector<StripMember> strip;
  for (const io::HydroDynMember& mb : g.members) {
    if (mb.PropPot) continue;
    StripMember m;
    m.row = &mb;
    m.a = g.joint(mb.joint1)->position;
    m.b = g.joint(mb.joint2)->position;
    m.length = (m.b - m.a).norm();
    m.k = (m.b - m.a) / m.length;
    m.Ra = 0.5 * g.prop(mb.prop1)->D;
    m.Rb = 0.5 * g.prop(mb.prop2)->D;
    m.coef = g.memberCoefs(mb, hd.source);
    strip.push_back(m);
  }
  for (const StripMember& m : strip) {
    // The member's length in the water column, and what the elements on it cover.
    double wet = 0;
    {
      double lo = std::min(m.a(2), m.b(2)), hi = std::max(m.a(2), m.b(2));
      if (lo == hi) wet = (lo <= 0 && lo >= -depth) ? m.length : 0;
      else wet = std::max(0.0, std::min(hi, 0.0) - std::max(lo, -depth)) / (hi - lo) * m.length;
    }
    double covered = 0;
    for (const fem::Element& e : model.elements) {
      const Vec3 &p1 = model.nodes[e.n1], &p2 = model.nodes[e.n2];
      const double s1 = onAxis(m, p1), s2 = onAxis(m, p2);
      if (s1 < 0 || s2 < 0 || s1 == s2) continue;
      covered += addElement(M, m, e.n1, e.n2, p1, p2, s1, s2, rho, depth);
    }
    if (std::abs(covered - wet) > 1e-6 * m.length)
      throw InputError(where(hd, m.row->line, "MemberID",
                             "strip-theory member " + std::to_string(m.row->id) + ": " + io::numberText(wet - covered) +
                                 " m of its length in the water lie on no SubDyn member (HydroDyn's members must "
                                 "follow the substructure's)"));
  }
  // End effects at the joints in the water.
  for (const io::HydroDynJoint& j : g.joints) {
    if (j.position(2) > 0 || j.position(2) < -depth) continue;
    Vec3 Vn = Vec3::Zero();
    for (const StripMember& m : strip) {
      if (m.row->joint1 == j.id) Vn -= 2 * kPi / 3 * std::pow(m.Ra, 3) * m.k;
      if (m.row->joint2 == j.id) Vn += 2 * kPi / 3 * std::pow(m.Rb, 3) * m.k;
    }
    const double mag = Vn.norm();
    if (mag == 0) continue;
    const io::HydroDynAxialCoef* c = g.axialCoef(j.axial_coef);
    if (!c)
      throw InputError(where(hd, j.line, "JointAxID",
                             std::to_string(j.axial_coef) + " is not a row of the AXIAL COEFFICIENTS table"));
    if (c->AxCa == 0) continue;
    const int n = nodeAt(model, j.position);
    if (n < 0)
      throw InputError(where(hd, j.line, "JointID",
                             "joint " + std::to_string(j.id) + " (in the water) is at no SubDyn joint or node"));
    M.block<3, 3>(fem::kNodeDofs * n, fem::kNodeDofs * n) += c->AxCa * rho / mag * Vn * Vn.transpose();
  }
  return M;
}

}  // namespace whirl::elastodyn

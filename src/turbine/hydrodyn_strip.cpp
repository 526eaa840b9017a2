#include "src/turbine/hydrodyn_strip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double kPi = std::numbers::pi;

std::string where(const io::HydroDynInput& hd, int line, const std::string& key, const std::string& reason) {
  return whirl::where(hd.source.path().string(), line, key, reason);
}

// A member as a line: ends a, b; outer radius, wall and coefficients linear between them; its fill.
struct Member {
  const io::HydroDynMember* row = nullptr;
  Vec3 a, b, k;
  double length = 0, Ra = 0, Rb = 0, ta = 0, tb = 0;
  io::HydroDynMemberCoef coef;
  const io::HydroDynFillGroup* fill = nullptr;
};

// The parameter s ∈ [0, 1] of point p on the member's axis, or −1 when p is not on it (1e-6 of its length).
double onAxis(const Member& m, const Vec3& p) {
  const double s = (p - m.a).dot(m.k) / m.length;
  const double off = (p - m.a - s * m.length * m.k).norm();
  const double tol = 1e-6 * m.length;
  if (off > tol || s < -tol / m.length || s > 1 + tol / m.length) return -1;
  return std::clamp(s, 0.0, 1.0);
}

// Added mass per unit length at parameter s, height z: the water around a strip-theory member in the
// water column (with its marine growth: radius R + t_MG, Ca_MG), the growth's own mass, the fill.
Mat3 perLength(const io::HydroDynInput& hd, const Member& m, double s, double z, double rho, double depth) {
  const double R = m.Ra + (m.Rb - m.Ra) * s, t = m.ta + (m.tb - m.ta) * s;
  const auto [tMG, rhoMG] = hd.geometry.growthAt(z);
  const Mat3 kk = m.k * m.k.transpose();
  Mat3 A = Mat3::Zero();
  const bool wet = z <= 0 && z >= -depth;
  if (wet && !m.row->PropPot) {
    const double Ca = tMG > 0 ? m.coef.CaMG1 + (m.coef.CaMG2 - m.coef.CaMG1) * s
                              : m.coef.Ca1 + (m.coef.Ca2 - m.coef.Ca1) * s;
    const double AxCa = m.coef.AxCa1 + (m.coef.AxCa2 - m.coef.AxCa1) * s;
    const double Ro = R + tMG, dRdl = std::abs(m.Rb - m.Ra) / m.length;
    A += rho * kPi * Ro * Ro * (Ca * (Mat3::Identity() - kk) + 2 * AxCa * dRdl * kk);
  }
  if (tMG > 0) A += rhoMG * kPi * ((R + tMG) * (R + tMG) - R * R) * Mat3::Identity();
  if (m.fill && z <= m.fill->FillFSLoc && z >= -depth) {  // HydroDyn fills nothing below the seabed
    const double ri = R - t;
    A += m.fill->FillDens.value_or(rho) * kPi * ri * ri * Mat3::Identity();
  }
  return A;
}

// Adds ∫ N_i A(s) over the element (nodes n1, n2) lying on the member from parameter s1 (node 1) to s2
// (node 2), split where z crosses a level at which A jumps; returns the length of the element in
// [z_lo, z_hi] (the part of the member that needs elements under it).
double addElement(MatX& M, const io::HydroDynInput& hd, const Member& m, const fem::Element& e, const Vec3& p1,
                  const Vec3& p2, double s1, double s2, double rho, double depth, const std::vector<double>& levels,
                  double z_lo, double z_hi) {
  std::vector<double> cuts{0.0, 1.0};
  const double z1 = p1(2), z2 = p2(2);
  if (z1 != z2)
    for (double level : levels) {
      const double xi = (level - z1) / (z2 - z1);
      if (xi > 0 && xi < 1) cuts.push_back(xi);
    }
  std::sort(cuts.begin(), cuts.end());
  static const double kX[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double kW[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double Le = (p2 - p1).norm();
  double needed = 0;
  for (std::size_t c = 1; c < cuts.size(); ++c) {
    const double x0 = cuts[c - 1], x1 = cuts[c], half = 0.5 * (x1 - x0);
    if (half <= 0) continue;
    const double zmid = z1 + (z2 - z1) * 0.5 * (x0 + x1);
    if (zmid >= z_lo && zmid <= z_hi) needed += (x1 - x0) * Le;
    for (int g = 0; g < 3; ++g) {
      const double xi = x0 + half * (1 + kX[g]);
      const Mat3 A = perLength(hd, m, s1 + (s2 - s1) * xi, z1 + (z2 - z1) * xi, rho, depth);
      const double w = kW[g] * half * Le, N[2] = {1 - xi, xi};
      const int n[2] = {e.n1, e.n2};
      for (int i = 0; i < 2; ++i)
        M.block<3, 3>(fem::kNodeDofs * n[i], fem::kNodeDofs * n[i]) += w * N[i] * A;  // lumped: each node its share
    }
  }
  return needed;
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
  // The heights where the added mass per length jumps or bends: the still-water level, the seabed,
  // the marine growth's depths, the fill levels.
  std::vector<double> levels{0.0, -depth};
  for (const io::HydroDynMarineGrowth& r : g.growth) levels.push_back(r.z);
  for (const io::HydroDynFillGroup& f : g.fills) levels.push_back(f.FillFSLoc);
  std::vector<Member> members;
  for (const io::HydroDynMember& mb : g.members) {
    Member m;
    m.row = &mb;
    m.a = g.joint(mb.joint1)->position;
    m.b = g.joint(mb.joint2)->position;
    m.length = (m.b - m.a).norm();
    m.k = (m.b - m.a) / m.length;
    m.Ra = 0.5 * g.prop(mb.prop1)->D;
    m.Rb = 0.5 * g.prop(mb.prop2)->D;
    m.ta = g.prop(mb.prop1)->thickness;
    m.tb = g.prop(mb.prop2)->thickness;
    for (const io::HydroDynFillGroup& f : g.fills)
      if (std::find(f.members.begin(), f.members.end(), mb.id) != f.members.end()) m.fill = &f;
    const bool growth = !g.growth.empty();
    if (mb.PropPot && !m.fill && !growth) continue;  // nothing of it in the linear model
    if (!mb.PropPot || growth) m.coef = g.memberCoefs(mb, hd.source);
    members.push_back(m);
  }
  for (const Member& m : members) {
    // The part of the member that carries mass: the water column, up to its fill level if higher.
    const double z_lo = -depth, z_hi = m.fill ? std::max(0.0, m.fill->FillFSLoc) : 0.0;
    double needed = 0;
    {
      const double lo = std::min(m.a(2), m.b(2)), hi = std::max(m.a(2), m.b(2));
      if (lo == hi) needed = (lo <= z_hi && lo >= z_lo) ? m.length : 0;
      else needed = std::max(0.0, std::min(hi, z_hi) - std::max(lo, z_lo)) / (hi - lo) * m.length;
    }
    double covered = 0;
    for (const fem::Element& e : model.elements) {
      const Vec3 &p1 = model.nodes[e.n1], &p2 = model.nodes[e.n2];
      const double s1 = onAxis(m, p1), s2 = onAxis(m, p2);
      if (s1 < 0 || s2 < 0 || s1 == s2) continue;
      covered += addElement(M, hd, m, e, p1, p2, s1, s2, rho, depth, levels, z_lo, z_hi);
    }
    if (std::abs(covered - needed) > 1e-6 * m.length)
      throw InputError(where(hd, m.row->line, "MemberID",
                             "member " + std::to_string(m.row->id) + ": " + io::numberText(needed - covered) +
                                 " m of its length in the water lie on no SubDyn member (HydroDyn's members must "
                                 "follow the substructure's)"));
  }
  // End effects at the joints in the water (strip-theory members only).
  for (const io::HydroDynJoint& j : g.joints) {
    if (j.position(2) > 0 || j.position(2) < -depth) continue;
    Vec3 Vn = Vec3::Zero();
    for (const Member& m : members) {
      if (m.row->PropPot) continue;
      const double tMG = g.growthAt(j.position(2)).first;
      if (m.row->joint1 == j.id) Vn -= 2 * kPi / 3 * std::pow(m.Ra + tMG, 3) * m.k;
      if (m.row->joint2 == j.id) Vn += 2 * kPi / 3 * std::pow(m.Rb + tMG, 3) * m.k;
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

#include "modal/mode_shapes.hpp"

#include <cctype>
#include <cmath>
#include <numbers>

#include "src/base/skew.hpp"
#include "src/dynamics/kinematics.hpp"

namespace whirl {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Multiblade meaning of slot `slot` (0-based) of a set of N blade coordinates (linearize/mbc.hpp):
// its value on blade b (0-based) at azimuth psi_b.
double slotBasis(int slot, int b, int N, double psi_b) {
  if (slot == 0) return 1.0;
  if (N % 2 == 0 && slot == N - 1) return b % 2 == 0 ? 1.0 : -1.0;
  const int k = (slot + 1) / 2;
  return slot % 2 == 1 ? std::cos(k * psi_b) : std::sin(k * psi_b);
}

// The 6 × ndof map of one node (origin when pt is null), ground components, then turned to the body frame.
MatX nodeMap(const Body& body, const FrameState<double>& f, const BasisState<double>& bs, const BodyPoint* pt) {
  const Eigen::Index nd = f.Jv.cols();
  MatX J = MatX::Zero(6, nd);
  Vec3 s = Vec3::Zero();
  if (pt)
    for (Eigen::Index k = 0; k < pt->P.cols(); ++k) s += pt->P.col(k) * bs.c(k);
  J.topRows(3) = f.Jv - skew(Vec3(f.R * s)) * f.Jw;
  J.bottomRows(3) = f.Jw;
  if (pt && body.inertia.ne > 0 && body.elastic_dof >= 0) {
    const MatX PD = pt->P * bs.D;  // 3 × ne: ∂s/∂q_e
    J.block(0, body.elastic_dof, 3, body.inertia.ne) += f.R * PD;
    J.block(3, body.elastic_dof, 3, body.inertia.ne) += f.R * pt->theta;
  }
  MatX out(6, nd);
  out.topRows(3) = f.R.transpose() * J.topRows(3);
  out.bottomRows(3) = f.R.transpose() * J.bottomRows(3);
  return out;
}

// The body's part in the tables of other tools (BodyMotion::role), from its joint and its name.
std::string bodyRole(const Model& m, int b, int blade) {
  const Body& body = m.bodies[b];
  if (blade >= 0) return "blade";
  if (body.joint == JointType::Free) return "platform";
  std::string lower = body.name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* role : {"tower", "nacelle", "hub"})
    if (lower.find(role) != std::string::npos) return role;
  return "";
}

}  // namespace

std::vector<BodyNodeMap> bodyNodeMaps(const Model& m, const VecX& q, const VecX& qd, const std::vector<int>& active) {
  Workspace<double> ws(m);
  const VecX qdd = VecX::Zero(m.ndof());
  forwardKinematics(m, ws, q, qd, qdd);
  std::vector<BodyNodeMap> maps;
  for (int b = 0; b < static_cast<int>(m.bodies.size()); ++b) {
    const Body& body = m.bodies[b];
    if (body.inertia.massless && body.inertia.ne == 0) continue;
    const FrameState<double>& f = ws.frames[b];
    BodyNodeMap map;
    map.body = b;
    map.shape.body = body.name;
    map.shape.R = f.R;
    for (int i = body.elastic_dof; i >= 0 && i < body.elastic_dof + body.inertia.ne; ++i)
      if (m.dofs[i].blade >= 0) map.shape.blade = m.dofs[i].blade;
    map.shape.role = bodyRole(m, b, map.shape.blade);
    std::vector<const BodyPoint*> pts;
    if (!body.nodes.empty()) {
      for (const BodyPoint& p : body.nodes) pts.push_back(&p);
    } else {
      pts.push_back(nullptr);
      for (const BodyPoint& p : body.points) pts.push_back(&p);
    }
    map.shape.x.resize(static_cast<Eigen::Index>(pts.size()));
    map.shape.position.resize(3, static_cast<Eigen::Index>(pts.size()));
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const BodyPoint* p = pts[k];
      map.shape.nodes.push_back(p ? p->name : "origin");
      Vec3 s = Vec3::Zero();
      if (p)
        for (Eigen::Index c = 0; c < p->P.cols(); ++c) s += p->P.col(c) * ws.basis[b].c(c);
      map.shape.x(static_cast<Eigen::Index>(k)) = p ? p->P(0, 0) : 0.0;
      map.shape.position.col(static_cast<Eigen::Index>(k)) = f.r + f.R * s;
      const MatX full = nodeMap(body, f, ws.basis[b], p);
      MatX J(6, static_cast<Eigen::Index>(active.size()));
      for (std::size_t i = 0; i < active.size(); ++i) J.col(static_cast<Eigen::Index>(i)) = full.col(active[i]);
      map.J.push_back(std::move(J));
    }
    maps.push_back(std::move(map));
  }
  return maps;
}

ModeMotion modeMotion(const std::vector<BodyNodeMap>& maps, const Eigen::VectorXcd& phi) {
  ModeMotion out;
  double largest = 0;
  std::complex<double> ref = 1;
  for (const BodyNodeMap& map : maps) {
    BodyMotion bm = map.shape;
    bm.u.resize(static_cast<Eigen::Index>(map.J.size()), 6);
    for (std::size_t k = 0; k < map.J.size(); ++k) {
      const Eigen::VectorXcd v = map.J[k].cast<std::complex<double>>() * phi;
      bm.u.row(static_cast<Eigen::Index>(k)) = v.transpose();
      for (int c = 0; c < 3; ++c)
        if (std::abs(v(c)) > largest) largest = std::abs(v(c)), ref = v(c);
    }
    out.bodies.push_back(std::move(bm));
  }
  // Largest translation 1 at phase 0: the whole motion divided by that complex amplitude.
  if (largest > 0)
    for (BodyMotion& bm : out.bodies) bm.u /= ref;
  return out;
}

Eigen::VectorXcd bladeCoordinates(const Eigen::VectorXcd& phi, const std::vector<int>& dof_blade, int N, double psi) {
  Eigen::VectorXcd out = phi;
  std::vector<std::vector<int>> per_blade(static_cast<std::size_t>(N));
  for (std::size_t i = 0; i < dof_blade.size(); ++i)
    if (dof_blade[i] >= 0 && dof_blade[i] < N)
      per_blade[static_cast<std::size_t>(dof_blade[i])].push_back(static_cast<int>(i));
  const std::size_t sets = per_blade[0].size();
  for (std::size_t j = 0; j < sets; ++j) {
    for (int b = 0; b < N; ++b) {
      const double psi_b = psi + kTwoPi * b / N;
      std::complex<double> v = 0;
      for (int slot = 0; slot < N; ++slot)
        v += phi(per_blade[static_cast<std::size_t>(slot)].at(j)) * slotBasis(slot, b, N, psi_b);
      out(per_blade[static_cast<std::size_t>(b)].at(j)) = v;
    }
  }
  return out;
}

void multibladeContent(ModeMotion& motion, int N, double psi, double rotor_speed) {
  std::vector<const BodyMotion*> blades(static_cast<std::size_t>(std::max(N, 0)), nullptr);
  for (const BodyMotion& bm : motion.bodies)
    if (bm.blade >= 0 && bm.blade < N) blades[static_cast<std::size_t>(bm.blade)] = &bm;
  if (N < 3) return;
  for (const BodyMotion* b : blades)
    if (!b || b->u.rows() != blades[0]->u.rows()) return;
  const Eigen::Index rows = blades[0]->u.rows();
  Eigen::MatrixXcd u0 = Eigen::MatrixXcd::Zero(rows, 6), uc = u0, us = u0;
  for (int b = 0; b < N; ++b) {
    const double psi_b = psi + kTwoPi * b / N;
    u0 += blades[static_cast<std::size_t>(b)]->u / double(N);
    uc += blades[static_cast<std::size_t>(b)]->u * (2.0 * std::cos(psi_b) / N);
    us += blades[static_cast<std::size_t>(b)]->u * (2.0 * std::sin(psi_b) / N);
  }
  const std::complex<double> i(0, 1);
  const double sign = rotor_speed < 0 ? -1.0 : 1.0;  // turning in −ψ: forward and backward swap
  motion.collective = u0;
  motion.backward = (uc - sign * i * us) / 2.0;
  motion.forward = (uc + sign * i * us) / 2.0;
  motion.blade_nodes = blades[0]->nodes;
  motion.blade_x = blades[0]->x;
}

void addModeMotions(const Model& m, const PeriodicLinearization& p, int num_blades,
                    const std::vector<std::string>& coordinates, std::vector<Mode>& modes) {
  const LinearModel& lin = p.models.front();
  const std::size_t n = lin.dofs.size();
  // Not a pattern per mode in the model's coordinates (Floquet harmonics): no motion.
  if (coordinates.size() < n) return;
  if (num_blades < 3)
    for (std::size_t i = 0; i < n; ++i)
      if (coordinates[i] != lin.dof_names[i]) return;
  const OperatingPoint& op = p.points.front();
  const std::vector<BodyNodeMap> maps = bodyNodeMaps(m, op.q, op.qd, lin.dofs);
  std::vector<int> dof_blade;
  for (int d : lin.dofs) dof_blade.push_back(m.dofs[d].blade);
  const double psi = p.azimuths.empty() ? 0.0 : p.azimuths.front();
  for (Mode& mode : modes) {
    if (mode.shape.size() < static_cast<Eigen::Index>(n)) continue;
    Eigen::VectorXcd phi = mode.shape.head(static_cast<Eigen::Index>(n));
    if (num_blades >= 3) phi = bladeCoordinates(phi, dof_blade, num_blades, psi);
    mode.motion = modeMotion(maps, phi);
    if (num_blades >= 3) multibladeContent(mode.motion, num_blades, psi, p.rotor_speed);
  }
}

void addModeMotions(const Model& m, const OperatingPoint& op, const LinearModel& lin, std::vector<Mode>& modes) {
  const std::size_t n = lin.dofs.size();
  const std::vector<BodyNodeMap> maps = bodyNodeMaps(m, op.q, op.qd, lin.dofs);
  for (Mode& mode : modes)
    if (mode.shape.size() >= static_cast<Eigen::Index>(n))
      mode.motion = modeMotion(maps, mode.shape.head(static_cast<Eigen::Index>(n)));
}

}  // namespace whirl

#pragma once
#include <cassert>
#include "src/dynamics/aero_loads.hxx"
#include "src/dynamics/basis_jet.hxx"
#include "src/dynamics/body_forces.hxx"
#include "src/dynamics/generator_torque.hpp"
#include "src/dynamics/kinematics.hxx"
#include "src/dynamics/mooring_loads.hxx"
#include "src/dynamics/point_force.hxx"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace detail {

// Whether the inertia forces of body i depend on a seeded direction: through its frame (the
// coordinates of its support) or its own elastic coordinates.
template <class T>
bool bodyVaries(const Model& m, int i, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd) {
  auto any = [&](int s) { return seeded(q(s)) || seeded(qd(s)) || seeded(qdd(s)); };
  for (int s : m.support[i])
    if (any(s)) return true;
  const Body& b = m.bodies[i];
  for (int j = 0; j < b.inertia.ne; ++j)
    if (any(b.elastic_dof + j)) return true;
  return false;
}

template <class T>
T inputScale(const VecXT<T>& u, int input) {
  return input >= 0 ? u(input) : T(1);
}

template <class T>
bool anySeeded(const VecXT<T>& x) {
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (seeded(x(k))) return true;
  return false;
}

// The body's double basis and products at the values of its elastic coordinates in q, q̇, q̈
// (kept while they keep their values; the jet is formed again when first asked for at new values).
template <class T>
ConstantBasis& constantBasisAt(const Body& b, Workspace<T>& ws, int i, const VecXT<T>& q, const VecXT<T>& qd,
                               const VecXT<T>& qdd) {
  const BodyInertia& in = b.inertia;
  const BasisState<T>& bs = ws.basis[i];
  ConstantBasis& cb = ws.constant_basis[i];
  const int ne = in.ne, e0 = b.elastic_dof, nc = in.nc();
  bool same = cb.valid;
  for (int j = 0; j < ne && same; ++j)
    same = cb.key(j) == q(e0 + j).value() && cb.key(ne + j) == qd(e0 + j).value() &&
           cb.key(2 * ne + j) == qdd(e0 + j).value();
  if (same) return cb;
  for (int j = 0; j < ne; ++j) {
    cb.key(j) = q(e0 + j).value();
    cb.key(ne + j) = qd(e0 + j).value();
    cb.key(2 * ne + j) = qdd(e0 + j).value();
  }
  for (int r = 0; r < nc; ++r) {
    cb.basis.c(r) = bs.c(r).value();
    cb.basis.cd(r) = bs.cd(r).value();
    cb.basis.cdd(r) = bs.cdd(r).value();
    for (int j = 0; j < ne; ++j) cb.basis.D(r, j) = bs.D(r, j).value();
  }
  basisProducts(in, cb.basis.c, cb.basis.cd, cb.basis.cdd, cb.prod);
  cb.valid = true;
  cb.jet.valid = false;
  return cb;
}

// Inertia forces of body i (body_forces.hxx) from its frame's â, α, ω. In an AD pass, the basis
// products are formed in double when the body's own coordinates are not seeded (c, ċ, c̈ and D
// then carry zero derivatives; cached across passes at the same point); when they are, from the
// double products and their preaccumulated derivatives (basis_jet.hxx), the c-only products in
// double when only q̇ or q̈ are seeded.
template <class T>
void bodyInertiaForces(const Model& m, int i, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd,
                       const VecXT<T>& qdd, const Vec3T<T>& ahat, const Vec3T<T>& alpha, const Vec3T<T>& omega,
                       Vec3T<T>& F, Vec3T<T>& Tq, T* H) {
  const Body& b = m.bodies[i];
  const BodyInertia& in = b.inertia;
  const BasisState<T>& bs = ws.basis[i];
  if (in.ne == 0) {
    rigidFrameForces(in, ahat, alpha, omega, F, Tq);
    return;
  }
  if constexpr (std::is_same_v<T, double>) {
    BasisProducts<double, double>& p = ws.body_products[static_cast<std::size_t>(i)];
    basisProducts(in, bs.c, bs.cd, bs.cdd, p);
    frameForces(in, p, bs.D, ahat, alpha, omega, ws.g, F, Tq, H);
  } else {
    const bool use_jet = in.Strace.rows() == in.nc() && in.ne >= kJetMinShapes;  // a finalized body
    const bool sq = elasticSeeded(b, q), sqd = elasticSeeded(b, qd), sqdd = elasticSeeded(b, qdd);
    if (sq && !use_jet) {
      basisProducts(in, bs.c, bs.cd, bs.cdd, ws.prod);
      frameForces(in, ws.prod, bs.D, ahat, alpha, omega, ws.g, F, Tq, H);
      return;
    }
    ConstantBasis& cb = constantBasisAt(b, ws, i, q, qd, qdd);
    const int e0 = b.elastic_dof;
    if (sq) {
      jetBasisProducts(in, cb, q.data() + e0, qd.data() + e0, qdd.data() + e0, sq, sqd, sqdd, bs, ws.prod);
      frameForces(in, ws.prod, bs.D, ahat, alpha, omega, ws.g, F, Tq, H);
      return;
    }
    if (sqd || sqdd) {  // q̇ or q̈ columns: only the rate part in AD
      BasisProducts<double, T>& p = ws.prod_dt;
      if (use_jet) {
        jetRateProducts(in, cb, qd.data() + e0, qdd.data() + e0, sqd, sqdd, bs, p);
      } else {
        copyPositionProducts(in, cb.prod, p);
        basisRateProducts(in, bs.cd, bs.cdd, p);
      }
      frameForces(in, p, cb.basis.D, ahat, alpha, omega, ws.g, F, Tq, H);
      return;
    }
    frameForces(in, cb.prod, cb.basis.D, ahat, alpha, omega, ws.g, F, Tq, H);
  }
}

}  // namespace detail

namespace detail {

// The torque of the generator torque law at the generator speed of q̇ (0 without a law).
template <class TK>
TK generatorLawTorque(const Model& m, const VecXT<TK>& qd) {
  const GeneratorTorqueLaw& gen = m.generator;
  if (!gen.active()) return TK(0);
  TK speed(0);
  for (const auto& [d, g] : m.outputs[gen.speed_output].terms) speed += g * qd(d);
  return generatorTorque(gen, speed);
}

// The scale of point load l: its input (or 1), plus the torque law's torque on the generator-torque input.
template <class TK, class T>
T pointLoadScale(const Model& m, const PointLoad& l, const VecXT<T>& u, const TK& law) {
  T scale = inputScale(u, l.input);
  if (m.generator.active() && l.input == m.roles.generator_torque_input) scale += T(law);
  return scale;
}

}  // namespace detail

template <class TK, class T>
void addInputLoads(const Model& m, const Workspace<TK>& ws, const VecXT<TK>& qd, const VecXT<T>& u, VecXT<T>& e) {
  // The generator torque law adds its torque at the generator speed to the generator-torque input.
  const TK law = detail::generatorLawTorque(m, qd);
  for (const PointLoad& l : m.point_loads) {
    // The load scaled by its input (or 1): its generalized force is scale × that of the unit load,
    // formed in TK; only the final products carry the scalar of u.
    const T scale = detail::pointLoadScale(m, l, u, law);
    // A zero scale that carries no derivative adds nothing (value and derivatives are scale × …):
    // the input loads of a linear model at u = 0, and in a double evaluation every input at zero
    // (six unit loads of an ElastoDyn deck, each a projection onto its support, at every residual).
    if (valueOf(scale) == 0.0 && (std::is_same_v<T, double> || !detail::seeded(scale))) continue;
    const FrameState<TK>& f = ws.frames[l.body];
    Vec3T<TK> Fb, Mb;
    if (l.body_frame) {
      Fb = l.force.cast<TK>();
      Mb = l.moment.cast<TK>();
    } else {
      Fb = f.R.transpose() * l.force.cast<TK>();
      Mb = f.R.transpose() * l.moment.cast<TK>();
    }
    detail::addPointForce(m, ws, l.body, l.point, Fb, Mb, scale, e);
  }
  for (const DofLoad& l : m.dof_loads) e(l.dof) += l.value * detail::inputScale(u, l.input);
}

template <class T>
bool residual(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
              const VecXT<T>& u, VecXT<T>& e, const AeroInflow* frozen, AeroRecord* record, const AdPass& pass) {
  assert(u.size() == m.ninput() && e.size() == m.ndof());
  forwardKinematics(m, ws, q, qd, qdd, pass);
  bool complete = true;
  const int nb = static_cast<int>(m.bodies.size());
  for (int k = 0; k < m.ndof(); ++k) e(k) = T(0);
  const Vec3T<T> gravity = m.gravity.cast<T>();
  T* H = ws.h.data();  // elastic forces of one body (sized to the largest ne)
  for (int i = 0; i < nb; ++i) {
    const Body& b = m.bodies[i];
    if (b.inertia.massless && b.inertia.ne == 0) continue;  // no inertia forces
    if constexpr (!std::is_same_v<T, double>)
      if (pass.derivativesOnly() && !detail::bodyVaries(m, i, q, qd, qdd)) {
        complete = false;
        continue;
      }
    const FrameState<T>& f = ws.frames[i];
    const Mat3T<T> Rt = f.R.transpose();
    const Vec3T<T> ahat = Rt * (f.a - gravity);
    const Vec3T<T> alpha = Rt * f.dw;
    const Vec3T<T> omega = Rt * f.w;
    Vec3T<T> F, Tq;
    detail::bodyInertiaForces(m, i, ws, q, qd, qdd, ahat, alpha, omega, F, Tq, H);
    const Vec3T<T> Fw = f.R * F, Tw = f.R * Tq;
    for (int s : m.support[i]) e(s) += f.Jv.col(s).dot(Fw) + f.Jw.col(s).dot(Tw);
    if (b.inertia.ne > 0) {
      const int e0 = b.elastic_dof, ne = b.inertia.ne;
      for (int j = 0; j < ne; ++j) {
        T s = H[j];
        for (int k = 0; k < ne; ++k) s -= b.elastic.K(j, k) * q(e0 + k) + b.elastic.D(j, k) * qd(e0 + k);
        if (b.elastic.A.size() > 0)
          for (int k = 0; k < ne; ++k) s -= b.elastic.A(j, k) * qdd(e0 + k);
        e(e0 + j) += s;
      }
    }
  }
  if constexpr (std::is_same_v<T, double>) ws.body_products_current = true;
  // The load terms depend on q and u — and on q̇ with aerodynamics or a generator torque law: a pass
  // seeding none of these (q̈ columns, or q̇ without them) skips them.
  bool loads = true;
  if constexpr (!std::is_same_v<T, double>)
    if (pass.derivativesOnly())
      loads = detail::anySeeded(q) || detail::anySeeded(u) ||
              ((m.aero.active() || m.generator.active()) && detail::anySeeded(qd));
  if (loads) {
    addInputLoads(m, ws, qd, u, e);
    // An AD pass that seeds nothing a blade's elements depend on (its frame, its own coordinates, the
    // inputs) leaves that blade out, as the inertia forces of an unseeded body are left out above.
    std::uint64_t skip = 0;
    if constexpr (!std::is_same_v<T, double>)
      if (pass.derivativesOnly() && !detail::anySeeded(u))
        for (std::size_t b = 0; b < m.aero.blades.size() && b < 64; ++b)
          if (!detail::bodyVaries(m, m.aero.blades[b].body, q, qd, qdd)) skip |= std::uint64_t{1} << b;
    if (skip) complete = false;
    addAeroLoads(m, ws, q, u, frozen, record, e, skip);
    detail::addMooringLoads(m, ws, e);
  } else {
    complete = false;
  }
  for (const DofSpring& s : m.springs) e(s.dof) -= s.k * (q(s.dof) - s.q0) + s.c * qd(s.dof);
  for (const BodyMatrices& bm : m.body_matrices) {
    const int d0 = m.bodies[bm.body].joint_dof;
    for (int r = 0; r < 6; ++r) {
      T s(0);
      for (int c = 0; c < 6; ++c)
        s += bm.K(r, c) * (q(d0 + c) - bm.x0(c)) + bm.C(r, c) * qd(d0 + c) + bm.A(r, c) * qdd(d0 + c);
      e(d0 + r) -= s;
    }
  }
  return complete;
}

}  // namespace whirl

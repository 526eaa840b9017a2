#pragma once
/// \file
/// Frozen-wake AD passes through a blade's elements by preaccumulation (Griewank & Walther 2008,
/// §10): a blade's load sums depend on the pass's seeded directions only through a few variables z
/// of the blade body (BladeJet in workspace.hpp: the frame's small rotation and height, q_e, pitch;
/// v, ω, q̇_e and the wind speed). Their derivatives ∂S/∂z are formed once per point — the
/// position-level ones by one AD evaluation of the elements with z seeded, the velocity-level ones
/// in closed form, since with the induction frozen an element's loads depend on v, ω, q̇_e and U
/// only through its relative velocity, linearly through the section's (vx, vy) derivatives — and
/// every pass then chains ∂S/∂z with its own derivatives of z: a small matrix product instead of
/// the elements' kinematics and loads in the pass's AD scalar. The same first derivatives as
/// evaluating the elements in the pass, to round-off.
#include <cmath>
#include <type_traits>

#include "src/base/skew.hpp"
#include "src/dynamics/aero_element.hxx"
#include "src/dynamics/kinematics.hxx"

namespace whirl::detail {

/// Number of variables z of a blade jet for a body with ne elastic coordinates, and their offsets.
struct BladeJetLayout {
  int ne, nc;
  int ns() const { return 6 + nc + ne; }
  int nz() const { return 12 + 2 * ne; }
  int npos() const { return 5 + ne; }  ///< δθ (3), r_z, q_e, pitch: formed by AD
  int rz() const { return 3; }
  int qe() const { return 4; }
  int pitch() const { return 4 + ne; }
  int v() const { return 5 + ne; }
  int w() const { return 8 + ne; }
  int qed() const { return 11 + ne; }
  int speed() const { return 11 + 2 * ne; }
};

template <class X>
Eigen::Matrix<double, kChunk, 1> derivativesOf(const X& x) {
  if constexpr (std::is_same_v<X, double>) return Eigen::Matrix<double, kChunk, 1>::Zero();
  else return x.derivatives();
}

/// The values a blade jet is formed at (BladeJet::key).
template <class TK, class T>
void bladeJetKey(const BladeMotion<TK>& bm, int ne, const T& speed, const AeroInflow& frozen, int index0, int n,
                 VecX& key) {
  key.resize(18 + 2 * ne + 2 + 2 * n);
  int k = 0;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) key(k++) = valueOf(bm.R(i, j));
  for (int i = 0; i < 3; ++i) key(k++) = valueOf(bm.r(i));
  for (int i = 0; i < 3; ++i) key(k++) = valueOf(bm.v(i));
  for (int i = 0; i < 3; ++i) key(k++) = valueOf(bm.w(i));
  for (int j = 0; j < ne; ++j) key(k++) = valueOf(bm.qe[j]);
  for (int j = 0; j < ne; ++j) key(k++) = valueOf(bm.cd(1 + j));  // ċ = [0; q̇_e; …] (evalBasis)
  key(k++) = valueOf(bm.pitch);
  key(k++) = valueOf(speed);
  for (int i = 0; i < n; ++i) {
    key(k++) = frozen.axial(index0 + i);
    key(k++) = frozen.tangential(index0 + i);
  }
}

/// Whether a jet formed at key a serves values b: equal to round-off (the AD passes' kinematics
/// rounds differently from the double kinematics of the same point).
inline bool sameJetKey(const VecX& a, const VecX& b) {
  if (a.size() != b.size()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!(std::abs(a(i) - b(i)) <= 1e-12 * (1.0 + std::abs(a(i))))) return false;
  return true;
}

/// Offset of q_e in a blade jet's key (bladeJetKey): R (9), r, v, ω (3 each); q̇_e follows q_e.
inline constexpr int kJetKeyElastic = 18;

/// The values a blade jet is formed at, unpacked from its key (bladeJetKey): the body frame R₀ and
/// origin r₀, its velocities v₀, ω₀ (ground components), pitch [rad] and the wind speed U₀ [m/s].
/// q_e and q̇_e are read from the key where used.
struct BladeJetValues {
  Mat3 R0;
  Vec3 r0, v0, w0;
  double pitch0, U0;
};

/// The frame, velocities, pitch and wind speed in `key` (bladeJetKey) of a body with ne elastic coordinates.
inline BladeJetValues unpackBladeJetKey(const VecX& key, int ne) {
  BladeJetValues x;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) x.R0(i, j) = key(3 * j + i);
  for (int i = 0; i < 3; ++i) {
    x.r0(i) = key(9 + i);
    x.v0(i) = key(12 + i);
    x.w0(i) = key(15 + i);
  }
  x.pitch0 = key(kJetKeyElastic + 2 * ne);
  x.U0 = key(kJetKeyElastic + 2 * ne + 1);
  return x;
}

/// The AD direction of variable `var` of z in the chunk of directions c0 … c0 + kChunk − 1, or −1.
inline int jetChunkDirection(int var, int c0) { return var >= c0 && var < c0 + kChunk ? var - c0 : -1; }

/// One chunk's seeded frame (ground components): R = (I + [δθ]×) R₀, r = r₀ + r_z e_z, v = v₀, ω = ω₀,
/// with the chunk's directions among δθ (3) and r_z.
inline void seedBladeJetFrame(const BladeJetLayout& L, const BladeJetValues& x, int c0, Mat3T<ADChunk>& R,
                              Vec3T<ADChunk>& r, Vec3T<ADChunk>& v, Vec3T<ADChunk>& w) {
  using Der = ADChunk::DerType;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) R(i, j) = ADChunk(x.R0(i, j), Der::Zero());
  for (int a = 0; a < 3; ++a)
    if (const int d = jetChunkDirection(a, c0); d >= 0) {
      const Mat3 dR = skew(Vec3(Vec3::Unit(a))) * x.R0;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) R(i, j).derivatives()(d) = dR(i, j);
    }
  for (int i = 0; i < 3; ++i) {
    r(i) = ADChunk(x.r0(i), Der::Zero());
    v(i) = ADChunk(x.v0(i), Der::Zero());
    w(i) = ADChunk(x.w0(i), Der::Zero());
  }
  if (const int d = jetChunkDirection(L.rz(), c0); d >= 0) r(2).derivatives()(d) = 1.0;
}

/// One chunk's seeded elastic state in the jet's AD buffers: q_e (with the chunk's directions among
/// L.qe()), q̇_e, q̈_e = 0 and the basis c, ċ at them (evalBasis; c = [1], ċ = [0] for a rigid body).
inline void seedBladeJetElastic(const BodyInertia& in, const BladeJetLayout& L, const VecX& key, int c0,
                                BladeJet& jet) {
  using Der = ADChunk::DerType;
  const int ne = L.ne;
  VecXT<ADChunk>&qe = jet.qe_ad, &qed = jet.qed_ad, &qdd = jet.qdd_ad;
  BasisState<ADChunk>& basis = jet.basis_ad;
  for (int j = 0; j < ne; ++j) {
    qe(j) = ADChunk(key(kJetKeyElastic + j), Der::Zero());
    if (const int d = jetChunkDirection(L.qe() + j, c0); d >= 0) qe(j).derivatives()(d) = 1.0;
    qed(j) = ADChunk(key(kJetKeyElastic + ne + j), Der::Zero());
    qdd(j) = ADChunk(0.0, Der::Zero());
  }
  if (ne > 0) {
    initBasisD(in, basis);
    evalBasis(in, qe.data(), qed.data(), qdd.data(), basis);
  } else {
    basis.c(0) = ADChunk(1.0, Der::Zero());
    basis.cd(0) = ADChunk(0.0, Der::Zero());
  }
}

/// Sizes the jet's AD buffers for a body with ne elastic and nc basis coordinates (once; no
/// allocation when the sizes hold).
inline void sizeBladeJetAdBuffers(int ne, int nc, BladeJet& jet) {
  jet.qe_ad.resize(ne);
  jet.qed_ad.resize(ne);
  jet.qdd_ad.resize(ne);
  jet.basis_ad.c.resize(nc);
  jet.basis_ad.cd.resize(nc);
  jet.basis_ad.cdd.resize(nc);
  jet.basis_ad.D.resize(nc, ne);
}

/// One AD evaluation of blade bi's elements with the chunk c0 … c0 + kChunk − 1 of the position-level
/// variables (δθ, r_z, q_e, pitch) seeded: jet.S (from the first chunk) and those columns of jet.dS.
inline void formBladeJetPositionChunk(const Model& m, int bi, int index0, const VecX& key, const BladeJetValues& x,
                                      const Vec3& hub, const Vec3& disk, const Vec3& wind_dir, const AeroInflow& frozen,
                                      int c0, std::vector<BemRoot>& bem, AeroJets& jets) {
  using Der = ADChunk::DerType;
  const Body& body = m.bodies[m.aero.blades[static_cast<std::size_t>(bi)].body];
  const BladeJetLayout L{body.inertia.ne, body.inertia.nc()};
  BladeJet& jet = jets.blades[static_cast<std::size_t>(bi)];
  Mat3T<ADChunk> R;
  Vec3T<ADChunk> r, v, w;
  seedBladeJetFrame(L, x, c0, R, r, v, w);
  seedBladeJetElastic(body.inertia, L, key, c0, jet);
  ADChunk pitch(x.pitch0, Der::Zero());
  if (const int d = jetChunkDirection(L.pitch(), c0); d >= 0) pitch.derivatives()(d) = 1.0;
  Vec3T<ADChunk> hub_ad, disk_ad;
  for (int i = 0; i < 3; ++i) {
    hub_ad(i) = ADChunk(hub(i), Der::Zero());
    disk_ad(i) = ADChunk(disk(i), Der::Zero());
  }
  const ADChunk speed(x.U0, Der::Zero()), weight(1.0, Der::Zero());
  const BasisState<ADChunk>& basis = jet.basis_ad;
  const BladeMotion<ADChunk> bm{R, r, v, w, basis.c, basis.cd, jet.qe_ad.data(), pitch};
  const RotorInflow<ADChunk, ADChunk> inflow{hub_ad, disk_ad, speed, wind_dir, weight, &frozen};
  BodyLoadSum<ADChunk> sum(L.ne, L.nc);
  bladeLoads<ADChunk, ADChunk>(m, bi, index0, bm, inflow, bem, jets.sections, nullptr, nullptr, sum);
  for (int i = 0; i < L.ns(); ++i) {
    const ADChunk s = sum.bodySum(i);
    if (c0 == 0) jet.S(i) = s.value();
    for (int var = c0; var < std::min(c0 + kChunk, L.npos()); ++var) jet.dS(i, var) = s.derivatives()(var - c0);
  }
}

/// The double basis c, ċ of the jet's body at the key's q_e, q̇_e with q̈_e = 0 (c = [1], ċ = [0] rigid).
inline void evalBladeJetBasis(const BodyInertia& in, const VecX& key, int ne, int nc, BasisState<double>& bd) {
  bd.c.resize(nc);
  bd.cd.resize(nc);
  bd.cdd.setZero(nc);
  bd.D.resize(nc, ne);
  if (ne > 0) {
    initBasisD(in, bd);
    evalBasis(in, key.data() + kJetKeyElastic, key.data() + kJetKeyElastic + ne, bd.cdd.data(), bd);
  } else {
    bd.c(0) = 1.0;
    bd.cd(0) = 0.0;
  }
}

/// r = aᵀ ∂rel_b/∂[v_b, ω_b, q̇_e, U] = [−aᵀ, (a × s)ᵀ, −(Dᵀ Pᵀ a)ᵀ, a·ŵ_b] (7 + ne entries; body
/// components, ŵ_b the wind at U = 1 m/s, D the basis' nc × ne derivative, column-major). Plain loops:
/// the vectors are a few entries long, where Eigen's dynamic-size expressions cost more than the arithmetic.
inline void relativeVelocityRow(const Vec3& a, const Vec3& s, const BodyPoint& pt, const Vec3& wb, const double* D,
                                int ne, int nc, double* r) {
  r[0] = -a(0);
  r[1] = -a(1);
  r[2] = -a(2);
  r[3] = a(1) * s(2) - a(2) * s(1);
  r[4] = a(2) * s(0) - a(0) * s(2);
  r[5] = a(0) * s(1) - a(1) * s(0);
  const double* P = pt.P.data();  // 3 × nc, column-major
  for (int j = 0; j < ne; ++j) {
    double t = 0;
    for (int k = 0; k < nc; ++k) t += D[k + j * nc] * (P[3 * k] * a(0) + P[3 * k + 1] * a(1) + P[3 * k + 2] * a(2));
    r[6 + j] = -t;
  }
  r[6 + ne] = a.dot(wb);
}

/// An element's load rows into jet.u1, u2, u3: u_1 = weight [x_a; s × x_a; Pᵀ x_a; ·],
/// u_2 = weight [y_a; s × y_a; Pᵀ y_a; ·], u_3 = weight [·; z_a; ·; θᵀ z_a] (body components; the rows of
/// Fb, Mb, fk, gθ; entries marked · are not written and not read).
inline void elementLoadRows(const ElementFrame<double>& g, const BodyPoint& pt, double wt, int ne, int nc,
                            BladeJet& jet) {
  double *p1 = jet.u1.data(), *p2 = jet.u2.data(), *p3 = jet.u3.data();
  const Vec3 sx = wt * g.s.cross(g.xnb), sy = wt * g.s.cross(g.yab);
  for (int i = 0; i < 3; ++i) {
    p1[i] = wt * g.xnb(i);
    p2[i] = wt * g.yab(i);
    p1[3 + i] = sx(i);
    p2[3 + i] = sy(i);
    p3[3 + i] = wt * g.znb(i);
  }
  const double* P = pt.P.data();
  for (int k = 0; k < nc; ++k) {
    p1[6 + k] = wt * (P[3 * k] * g.xnb(0) + P[3 * k + 1] * g.xnb(1) + P[3 * k + 2] * g.xnb(2));
    p2[6 + k] = wt * (P[3 * k] * g.yab(0) + P[3 * k + 1] * g.yab(1) + P[3 * k + 2] * g.yab(2));
  }
  const double* th = pt.theta.data();  // 3 × ne
  for (int j = 0; j < ne; ++j)
    p3[6 + nc + j] = wt * (th[3 * j] * g.znb(0) + th[3 * j + 1] * g.znb(1) + th[3 * j + 2] * g.znb(2));
}

/// jet.vel += u_1 r_1ᵀ + u_2 r_2ᵀ + u_3 r_3ᵀ, row-major (ns × nv); u_1, u_2 are zero on the gθ rows and
/// u_3 on the Fb and fk rows.
inline void accumulateVelocityRows(int ns, int nc, int nv, BladeJet& jet) {
  double* Vd = jet.vel.data();
  const double *p1 = jet.u1.data(), *p2 = jet.u2.data(), *p3 = jet.u3.data();
  const double *q1 = jet.r1.data(), *q2 = jet.r2.data(), *q3 = jet.r3.data();
  for (int i = 0; i < 6 + nc; ++i) {
    double* vi = Vd + static_cast<std::ptrdiff_t>(i) * nv;
    const double a1 = p1[i], a2 = p2[i];
    for (int k = 0; k < nv; ++k) vi[k] += a1 * q1[k] + a2 * q2[k];
  }
  for (int i = 3; i < ns; ++i) {
    if (i == 6) i = 6 + nc;  // u3 is zero on the fk rows
    if (i >= ns) break;
    double* vi = Vd + static_cast<std::ptrdiff_t>(i) * nv;
    const double a3 = p3[i];
    for (int k = 0; k < nv; ++k) vi[k] += a3 * q3[k];
  }
}

/// The jet's velocity-level columns of dS (v, ω in ground components, q̇_e, U) in closed form.
/// With the induced velocities frozen, an element's loads depend on them through its relative
/// velocity alone, in body components
///   rel_b = Rᵀ (wind − vel) = U Rᵀ ŵ(z) − Rᵀ v + s × (Rᵀ ω) − P D q̇_e   (ŵ: the wind at U = 1),
/// through the section jet's ∂(fx, fy, mz)/∂(vx, vy) (vx = rel_b·x_a, vy = rel_b·y_a in body
/// components). ∂S/∂rel_b = Σ_i u_i a_iᵀ has rank 3: a_1 = ∂fx/∂rel_b with
/// u_1 = weight [x_a; s × x_a; Pᵀ x_a; 0] (the rows of Fb, Mb, fk, gθ), a_2 = ∂fy/∂rel_b with y_a, and
/// a_3 = ∂mz/∂rel_b with u_3 = weight [0; z_a; 0; θᵀ z_a]. Row-major accumulation of
/// Σ u_i (a_iᵀ ∂rel_b/∂[v_b, ω_b, q̇_e, U]); v and ω turn to ground components at the end.
inline void formBladeJetVelocityColumns(const Model& m, int bi, int index0, const VecX& key, const BladeJetValues& x,
                                        const Vec3& wind_dir, AeroJets& jets) {
  const AeroModel& am = m.aero;
  const AeroBlade& blade = am.blades[static_cast<std::size_t>(bi)];
  const Body& body = m.bodies[blade.body];
  const BladeJetLayout L{body.inertia.ne, body.inertia.nc()};
  const int ne = L.ne, nc = L.nc;
  BladeJet& jet = jets.blades[static_cast<std::size_t>(bi)];
  BasisState<double>& bd = jet.basis;
  evalBladeJetBasis(body.inertia, key, ne, nc, bd);
  const BladeMotion<double> bm{x.R0, x.r0, x.v0, x.w0, bd.c, bd.cd, key.data() + kJetKeyElastic, x.pitch0};
  const BladeAxes<double> axes = bladeAxes(body, bm);
  const int ns = L.ns(), nv = 7 + ne;
  auto& V = jet.vel;
  V.setZero(ns, nv);
  jet.u1.resize(ns);
  jet.u2.resize(ns);
  jet.u3.resize(ns);
  jet.r1.resize(nv);
  jet.r2.resize(nv);
  jet.r3.resize(nv);
  const double* D = bd.D.data();
  for (std::size_t si = 0; si < blade.stations.size(); ++si) {
    const AeroStation& st = blade.stations[si];
    const BodyPoint& pt = body.points[st.point];
    const SectionJet& sj = jets.sections[static_cast<std::size_t>(index0) + si];
    const ElementFrame<double> g = elementFrame(body, pt, bm, axes, st.curve);
    elementLoadRows(g, pt, st.weight, ne, nc, jet);
    const Vec3 wb = x.R0.transpose() * steadyWind(am.wind, wind_dir, 1.0, g.pos(2));
    relativeVelocityRow(sj.J[0][0] * g.xnb + sj.J[0][1] * g.yab, g.s, pt, wb, D, ne, nc, jet.r1.data());
    relativeVelocityRow(sj.J[1][0] * g.xnb + sj.J[1][1] * g.yab, g.s, pt, wb, D, ne, nc, jet.r2.data());
    relativeVelocityRow(sj.J[2][0] * g.xnb + sj.J[2][1] * g.yab, g.s, pt, wb, D, ne, nc, jet.r3.data());
    accumulateVelocityRows(ns, nc, nv, jet);
  }
  const Mat3 Rt = x.R0.transpose();
  jet.dS.middleCols<3>(L.v()) = V.leftCols<3>() * Rt;
  jet.dS.middleCols<3>(L.w()) = V.middleCols<3>(3) * Rt;
  jet.dS.middleCols(L.qed(), ne) = V.middleCols(6, ne);
  jet.dS.col(L.speed()) = V.col(6 + ne);
}

/// Forms blade bi's jet at the values in `key` (bladeJetKey), the frozen inflow and the hub at
/// (hub, disk) [m, ground]: the position-level derivatives by AD, 8 at a time, then the
/// velocity-level ones in closed form. Needs the section jets of its elements (formed here when missing).
inline void formBladeJet(const Model& m, int bi, int index0, const VecX& key, const Vec3& hub, const Vec3& disk,
                         const AeroInflow& frozen, std::vector<BemRoot>& bem, AeroJets& jets) {
  const Body& body = m.bodies[m.aero.blades[static_cast<std::size_t>(bi)].body];
  const BladeJetLayout L{body.inertia.ne, body.inertia.nc()};
  BladeJet& jet = jets.blades[static_cast<std::size_t>(bi)];
  const BladeJetValues x = unpackBladeJetKey(key, L.ne);
  const Vec3 wind_dir = windDirection(m.aero.wind);
  jet.S.resize(L.ns());
  jet.dS.setZero(L.ns(), L.nz());
  sizeBladeJetAdBuffers(L.ne, L.nc, jet);
  for (int c0 = 0; c0 < L.npos(); c0 += kChunk)
    formBladeJetPositionChunk(m, bi, index0, key, x, hub, disk, wind_dir, frozen, c0, bem, jets);
  formBladeJetVelocityColumns(m, bi, index0, key, x, wind_dir, jets);
  jet.key = key;
  jet.valid = true;
}

/// e += blade bi's loads, from its jet (formed when the values of its variables changed) chained with
/// the pass's derivatives of those variables. For passes with the induction frozen and no totals
/// or record; TK the kinematics' scalar (double in a pass that seeds only inputs), T = ADChunk.
template <class TK, class T>
void addBladeJetLoads(const Model& m, int bi, int index0, const BladeMotion<TK>& bm, const Vec3T<TK>& hub,
                      const Vec3T<TK>& disk, const T& speed, const AeroInflow& frozen, Workspace<TK>& ws,
                      AeroJets& jets, VecXT<T>& e) {
  static_assert(std::is_same_v<T, ADChunk>, "blade jets serve AD passes");
  const AeroBlade& blade = m.aero.blades[static_cast<std::size_t>(bi)];
  const Body& body = m.bodies[blade.body];
  const BladeJetLayout L{body.inertia.ne, body.inertia.nc()};
  const int ne = L.ne, n = static_cast<int>(blade.stations.size());
  BladeJet& jet = jets.blades[static_cast<std::size_t>(bi)];
  bladeJetKey(bm, ne, speed, frozen, index0, n, jet.pass_key);
  if (!(jet.valid && sameJetKey(jet.key, jet.pass_key))) {
    Vec3 h, dk;
    for (int i = 0; i < 3; ++i) {
      h(i) = valueOf(hub(i));
      dk(i) = valueOf(disk(i));
    }
    formBladeJet(m, bi, index0, jet.pass_key, h, dk, frozen, ws.bem, jets);
  }
  // The pass's derivatives of the sums, Σ_z ∂S/∂z ż over the variables it moves (a C pass: the
  // velocity-level ones only). Column i of dT: the derivatives of S_i (the buffer dsum, ns × kChunk,
  // seen as kChunk × ns).
  using Der = Eigen::Matrix<double, kChunk, 1>;
  jet.dsum.setZero(L.ns(), kChunk);
  Eigen::Map<Eigen::Matrix<double, kChunk, Eigen::Dynamic>> dT(jet.dsum.data(), kChunk, L.ns());
  const int ns = L.ns();
  auto chain = [&](int z, const Der& dz) {
    if (dz.isZero(0.0)) return;
    const double* col = jet.dS.data() + static_cast<std::ptrdiff_t>(z) * ns;
    for (int i = 0; i < ns; ++i)
      if (col[i] != 0.0) dT.col(i).noalias() += col[i] * dz;
  };
  if constexpr (!std::is_same_v<TK, double>) {
    // δθ from Ṙ Rᵀ (skew): its antisymmetric part, per direction.
    Der t0 = Der::Zero(), t1 = Der::Zero(), t2 = Der::Zero();
    for (int j = 0; j < 3; ++j) {
      const double R0j = bm.R(0, j).value(), R1j = bm.R(1, j).value(), R2j = bm.R(2, j).value();
      const Der& d0 = bm.R(0, j).derivatives();
      const Der& d1 = bm.R(1, j).derivatives();
      const Der& d2 = bm.R(2, j).derivatives();
      t0 += 0.5 * (R1j * d2 - R2j * d1);
      t1 += 0.5 * (R2j * d0 - R0j * d2);
      t2 += 0.5 * (R0j * d1 - R1j * d0);
    }
    chain(0, t0);
    chain(1, t1);
    chain(2, t2);
    chain(L.rz(), bm.r(2).derivatives());
    for (int j = 0; j < ne; ++j) {
      chain(L.qe() + j, bm.qe[j].derivatives());
      chain(L.qed() + j, bm.cd(1 + j).derivatives());
    }
    chain(L.pitch(), bm.pitch.derivatives());
    for (int i = 0; i < 3; ++i) {
      chain(L.v() + i, bm.v(i).derivatives());
      chain(L.w() + i, bm.w(i).derivatives());
    }
  }
  chain(L.speed(), derivativesOf(speed));
  // The sums with the pass's derivatives, projected (as BodyLoadSum::project).
  auto at = [&](Eigen::Index i) { return T(jet.S(i), dT.col(i)); };
  const Vec3T<T> zero = Vec3T<T>::Constant(T(0.0, T::DerType::Zero()));
  const Vec3T<T> Fb(at(0), at(1), at(2)), Mb(at(3), at(4), at(5));
  const Eigen::Index nc = L.nc;
  projectBodySums(
      m, ws, blade.body, zero, zero, Fb, Mb, [&](Eigen::Index k) { return at(6 + k); },
      [&](Eigen::Index j) { return at(6 + nc + j); }, e);
}

}  // namespace whirl::detail

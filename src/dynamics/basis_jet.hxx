#pragma once
/// \file
/// Stage 1 of the inertia forces (body_forces.hxx) in an AD pass that seeds a body's own elastic
/// coordinates, from their preaccumulated derivatives (BasisJet): the products' values are those of
/// the double evaluation at the same point (ConstantBasis), their derivatives the jet's ne columns
/// times the pass's derivatives of q_e, q̇_e, q̈_e. The AD evaluation of y = S c contracts S (nr × nc)
/// with c's nc derivative rows in every pass; with c = [1; q; q_i q_j] (nc = 45 for 8 shapes) the
/// jet's S D(q) (nr × ne) is formed once per point, a Jacobian preaccumulation (Griewank & Walther
/// 2008, §10) like the blade jets of aero_blade_jet.hxx.
#include <array>
#include <vector>

#include "src/dynamics/body_forces.hxx"
#include "src/dynamics/workspace.hpp"

namespace whirl {
namespace detail {

// Basis index → (i, j) of its product q_i q_j, in evalBasis' order (−1 for 1 and q).
inline void basisPairs(const BodyInertia& in, std::vector<std::array<int, 2>>& pair) {
  pair.assign(static_cast<std::size_t>(in.nc()), {-1, -1});
  if (!in.quadratic) return;
  int p = 1 + in.ne;
  for (int i = 0; i < in.ne; ++i)
    for (int j = i; j < in.ne; ++j, ++p) pair[static_cast<std::size_t>(p)] = {i, j};
}

// D₂(x): ∂c/∂q_e's quadratic rows with the values x (x_j in column i, x_i in column j of the row of
// q_i q_j), zero elsewhere (nc × ne).
inline void quadraticRows(const BodyInertia& in, const std::vector<std::array<int, 2>>& pair, const double* x,
                          MatX& D) {
  D.setZero(in.nc(), in.ne);
  for (int p = 1 + in.ne; p < in.nc(); ++p) {
    const auto [i, j] = pair[static_cast<std::size_t>(p)];
    D(p, i) += x[j];
    D(p, j) += x[i];
  }
}

// out = S D on S's block rows (nr × ne): the block's values (row-major) times D's rows of its columns,
// gathered into `rows` (a buffer kept with the jet: forming allocates nothing once sized).
inline void blockTimesD(const ShapeIntegralBlock& S, const MatX& D, MatX& rows, MatX& out) {
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const auto nr = static_cast<Eigen::Index>(S.rows.size()), ncol = static_cast<Eigen::Index>(S.cols.size());
  const Eigen::Map<const RowMajor> V(S.values.data(), nr, ncol);
  rows.resize(ncol, D.cols());
  for (Eigen::Index k = 0; k < ncol; ++k) rows.row(k) = D.row(S.cols[static_cast<std::size_t>(k)]);
  out.resize(nr, D.cols());
  out.noalias() = V * rows;
}

// The jet at cb's values (a finalized body: its S_block and Strace_block set); D(q) is cb.basis.D.
inline void formBasisJet(const BodyInertia& in, const ConstantBasis& cb, BasisJet& jet) {
  const int ne = in.ne;
  if (static_cast<int>(jet.pair.size()) != in.nc()) basisPairs(in, jet.pair);
  const double* qd = cb.key.data() + ne;
  const double* qdd = qd + ne;
  jet.rates = !cb.key.segment(ne, ne).isZero(0.0);
  jet.accelerations = !cb.key.segment(2 * ne, ne).isZero(0.0);
  const MatX& Dq = cb.basis.D;
  MatX& D2 = jet.quadratic;
  if (jet.rates) quadraticRows(in, jet.pair, qd, D2);
  for (int kl = 0; kl < 9; ++kl) {
    blockTimesD(in.S_block[kl], Dq, jet.rows, jet.Sq[kl]);
    if (kl % 4 != 0 && jet.rates) blockTimesD(in.S_block[kl], D2, jet.rows, jet.Sqd[kl]);
  }
  blockTimesD(in.Strace_block, Dq, jet.rows, jet.Tq);
  if (jet.rates) blockTimesD(in.Strace_block, D2, jet.rows, jet.Tqd);
  if (jet.accelerations) {
    quadraticRows(in, jet.pair, qdd, D2);
    blockTimesD(in.Strace_block, D2, jet.rows, jet.Tqdd);
  }
  jet.valid = true;
}

// d (directions × ne): column i the derivatives of x[i].
template <class T>
void gatherDerivatives(const T* x, int ne, MatX& d) {
  d.resize(x[0].derivatives().size(), ne);
  for (int i = 0; i < ne; ++i) d.col(i) = x[i].derivatives();
}

// y = the double values y0 (first n entries), no derivatives.
template <class T>
void setValues(const VecX& y0, int n, VecXT<T>& y) {
  for (int r = 0; r < n; ++r) y(r) = T(y0(r));
}

// The derivatives of y on S's block rows += scale · J dxᵀ, row by row in the derivative type (a
// GEMM's call and packing cost more than its nr × ne × directions products). Only the coordinates
// the pass seeds enter (a chunk often holds a few of a body's coordinates).
template <class T>
void addJetProduct(const MatX& J, const ShapeIntegralBlock& S, const MatX& dx, double scale, VecXT<T>& y) {
  using Der = typename T::DerType;
  constexpr int kMaxListed = 64;
  const int ne = static_cast<int>(J.cols());
  std::array<int, kMaxListed> seeded{};
  int ns = 0;
  for (int i = 0; i < ne && ns <= kMaxListed; ++i)
    if (!dx.col(i).isZero(0.0)) {
      if (ns < kMaxListed) seeded[static_cast<std::size_t>(ns)] = i;
      ++ns;
    }
  if (ns == 0) return;
  const bool listed = ns <= kMaxListed;
  for (Eigen::Index a = 0; a < J.rows(); ++a) {
    Der d = Der::Zero(dx.rows());
    if (listed) {
      for (int k = 0; k < ns; ++k)
        d += J(a, seeded[static_cast<std::size_t>(k)]) * dx.col(seeded[static_cast<std::size_t>(k)]);
    } else {
      for (int i = 0; i < ne; ++i) d += J(a, i) * dx.col(i);
    }
    y(S.rows[static_cast<std::size_t>(a)]).derivatives() += scale * d;
  }
}

// z_kl (k ≠ l) and s of type T: their values from prod, derivatives from the jet and dq, dqd, dqdd
// (the pass's; sq, sqd, sqdd: which carry seeded directions).
template <class TQ, class T>
void jetRateProducts(const BodyInertia& in, const BasisProducts<double, double>& prod, BasisJet& jet, bool sq, bool sqd,
                     bool sqdd, BasisProducts<TQ, T>& p) {
  for (int kl = 0; kl < 9; ++kl) {
    if (kl % 4 == 0) continue;
    setValues(prod.z[kl], in.len[kl / 3], p.z[kl]);
    if (sqd) addJetProduct(jet.Sq[kl], in.S_block[kl], jet.dqd, 1.0, p.z[kl]);
    if (sq && jet.rates) addJetProduct(jet.Sqd[kl], in.S_block[kl], jet.dq, 1.0, p.z[kl]);
  }
  setValues(prod.scdd, in.nc(), p.scdd);
  if (sqdd) addJetProduct(jet.Tq, in.Strace_block, jet.dqdd, 1.0, p.scdd);
  if (sqd && jet.rates) addJetProduct(jet.Tqd, in.Strace_block, jet.dqd, 2.0, p.scdd);
  if (sq && jet.accelerations) addJetProduct(jet.Tqdd, in.Strace_block, jet.dq, 1.0, p.scdd);
}

// The products of the positions alone (y, Pc, m1c) from the double ones at the point: a pass that seeds
// none of the body's q_e takes them as they are.
template <class T>
void copyPositionProducts(const BodyInertia& in, const BasisProducts<double, double>& from,
                          BasisProducts<double, T>& to) {
  for (int k = 0; k < 9; ++k) to.y[k].head(in.len[k / 3]) = from.y[k].head(in.len[k / 3]);
  to.Pc = from.Pc;
  to.m1c = from.m1c;
}

}  // namespace detail

/// Stage 1 in an AD pass whose seeded directions reach the body's own elastic coordinates (sq: q_e,
/// sqd: q̇_e, sqdd: q̈_e), for a finalized body with cb formed at the pass's values: the same
/// products as basisProducts(in, c, ċ, c̈, p) to round-off. c, ċ, c̈ (AD) enter only the sums.
template <class T>
void jetBasisProducts(const BodyInertia& in, ConstantBasis& cb, const T* qe, const T* qde, const T* qdde, bool sq,
                      bool sqd, bool sqdd, const BasisState<T>& bs, BasisProducts<T, T>& p) {
  BasisJet& jet = cb.jet;
  if (!jet.valid) detail::formBasisJet(in, cb, jet);
  const int ne = in.ne;
  if (sq) detail::gatherDerivatives(qe, ne, jet.dq);
  if (sqd) detail::gatherDerivatives(qde, ne, jet.dqd);
  if (sqdd) detail::gatherDerivatives(qdde, ne, jet.dqdd);
  for (int kl = 0; kl < 9; ++kl) {
    detail::setValues(cb.prod.y[kl], in.len[kl / 3], p.y[kl]);
    if (sq) detail::addJetProduct(jet.Sq[kl], in.S_block[kl], jet.dq, 1.0, p.y[kl]);
  }
  detail::positionSums(in, bs.c, p);
  detail::jetRateProducts(in, cb.prod, jet, sq, sqd, sqdd, p);
  detail::rateDots(in, bs.cd, bs.cdd, p);
}

/// The rate part alone (q_e not seeded): y, Pc, m1c in double from cb, the rest of type T.
template <class T>
void jetRateProducts(const BodyInertia& in, ConstantBasis& cb, const T* qde, const T* qdde, bool sqd, bool sqdd,
                     const BasisState<T>& bs, BasisProducts<double, T>& p) {
  BasisJet& jet = cb.jet;
  if (!jet.valid) detail::formBasisJet(in, cb, jet);
  const int ne = in.ne;
  if (sqd) detail::gatherDerivatives(qde, ne, jet.dqd);
  if (sqdd) detail::gatherDerivatives(qdde, ne, jet.dqdd);
  detail::copyPositionProducts(in, cb.prod, p);
  detail::jetRateProducts(in, cb.prod, jet, false, sqd, sqdd, p);
  detail::rateDots(in, bs.cd, bs.cdd, p);
}

}  // namespace whirl

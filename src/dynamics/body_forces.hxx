#pragma once
/// \file
/// Inertia and gravity forces of one body on its own virtual motions, body-frame components
/// [BranlardGeisler2022, eq. 13–15, A1–A19]:
///   F = −∫ a_P dm,  T = −∫ s × a_P dm (about the origin),  H = −Dᵀ ∫ Pᵀ a_P dm,
/// with a_P = â + A s + 2 W ṡ + s̈, â = a − g, A = α̃ + ω̃ω̃, W = ω̃, s = P c.
///
/// Evaluated in two stages so an AD pass differentiates only what varies:
///  1. basisProducts: the shape integrals contracted with c, ċ, c̈ (the O(nc²) part);
///  2. frameForces: the products combined with â, α, ω (3 × 3 algebra and O(nc ne)).
/// Stage 1 has two scalar types: TQ for what depends on c (position level) and TR for what involves
/// ċ or c̈. An AD pass instantiates them as double when the body's own elastic coordinates carry no
/// seeded direction (K columns of another body, every C column for TQ, the pitch columns of Q):
/// the derivatives are the same, the work is that of a double evaluation.
#include <array>
#include <type_traits>

#include "src/dynamics/kinematics.hpp"

namespace whirl {
namespace detail {

// y[0..rows) = S[0..rows, 0..cols) x for a small dense double matrix and a vector of T (no
// temporaries, no mixed-type GEMV); zero entries of S are skipped.
template <class T>
void matvec(const MatX& S, const VecXT<T>& x, int rows, int cols, VecXT<T>& y) {
  for (int i = 0; i < rows; ++i) y(i) = T(0);
  for (int j = 0; j < cols; ++j) {
    const T& xj = x(j);
    const double* col = S.data() + static_cast<Eigen::Index>(j) * S.rows();
    for (int i = 0; i < rows; ++i)
      if (col[i] != 0.0) y(i) += col[i] * xj;
  }
}

// y[0..rows) = S x over the nonzero block of S (BodyInertia::S_block): the other rows are zero; each
// row of the block sums a fixed number of terms in a register, in the order of the dense loop above
// (not FMA-contracted: equal to it to round-off). Summing into y column by column stored and reloaded
// y's entry at every term, a dependency through memory that made these products a quarter of a
// structural simulation's time; a list of nonzeros gave the same sums as this block, bitwise.
template <class T>
void matvec(const ShapeIntegralBlock& S, const VecXT<T>& x, int rows, VecXT<T>& y) {
  T* __restrict yd = y.data();
  const T* __restrict xd = x.data();
  for (int i = 0; i < rows; ++i) yd[i] = T(0);
  const int nr = static_cast<int>(S.rows.size()), ncol = static_cast<int>(S.cols.size());
  const int* __restrict cols = S.cols.data();
  const double* __restrict v = S.values.data();
  for (int a = 0; a < nr; ++a, v += ncol) {
    T sum(0);
    for (int b = 0; b < ncol; ++b) sum += v[b] * xd[cols[b]];
    yd[S.rows[static_cast<std::size_t>(a)]] = sum;
  }
}

// y1 = S x1 and y2 = S x2 in one sweep over the block (each value and column index loaded once for
// both): the sums of two calls of matvec above, equal to round-off (the compiler may contract them
// differently).
template <class T>
void matvec2(const ShapeIntegralBlock& S, const VecXT<T>& x1, const VecXT<T>& x2, int rows, VecXT<T>& y1,
             VecXT<T>& y2) {
  T* __restrict y1d = y1.data();
  T* __restrict y2d = y2.data();
  const T* __restrict x1d = x1.data();
  const T* __restrict x2d = x2.data();
  for (int i = 0; i < rows; ++i) y1d[i] = y2d[i] = T(0);
  const int nr = static_cast<int>(S.rows.size()), ncol = static_cast<int>(S.cols.size());
  const int* __restrict cols = S.cols.data();
  const double* __restrict v = S.values.data();
  for (int a = 0; a < nr; ++a, v += ncol) {
    T s1(0), s2(0);
    for (int b = 0; b < ncol; ++b) {
      s1 += v[b] * x1d[cols[b]];
      s2 += v[b] * x2d[cols[b]];
    }
    const int r = S.rows[static_cast<std::size_t>(a)];
    y1d[r] = s1;
    y2d[r] = s2;
  }
}

// y = S_k x (k = 3j + l, len[j] × len[l]): sparse for a finalized body (Strace set), dense otherwise.
template <class T>
void shapeProduct(const BodyInertia& in, int k, const VecXT<T>& x, VecXT<T>& y) {
  const int rows = in.len[k / 3], cols = in.len[k % 3];
  if (in.Strace.rows() == in.nc()) matvec(in.S_block[k], x, rows, y);
  else matvec(in.S[k], x, rows, cols, y);
}

// T_i = −ε_ijk Q(j, k) with Qt = Qᵀ, Qt(k, j) = ∫ s_j (a_P)_k dm: the inertia moment about the origin.
template <class T>
void momentOfSecondMoments(const Mat3T<T>& Qt, Vec3T<T>& Tq) {
  Tq(0) = -(Qt(2, 1) - Qt(1, 2));
  Tq(1) = -(Qt(0, 2) - Qt(2, 0));
  Tq(2) = -(Qt(1, 0) - Qt(0, 1));
}

// Σ_k a[k·stride] x(k), k < n.
template <class T>
T dot(const double* a, int stride, const VecXT<T>& x, int n) {
  T s(0);
  for (int k = 0; k < n; ++k) s += a[k * stride] * x(k);
  return s;
}

}  // namespace detail

namespace detail {

// Pc and m1c from the products y (the position part after its nine products).
template <class TQ, class TR>
void positionSums(const BodyInertia& in, const VecXT<TQ>& c, BasisProducts<TQ, TR>& p) {
  const std::array<int, 3>& len = in.len;
  // The three sums of a row l side by side: three independent chains of additions instead of one
  // (each sum in the same order as alone).
  for (int l = 0; l < 3; ++l) {
    const TQ* y0 = p.y[3 * l].data();
    const TQ* y1 = p.y[3 * l + 1].data();
    const TQ* y2 = p.y[3 * l + 2].data();
    TQ a0(0), a1(0), a2(0);
    for (int r = 0; r < len[l]; ++r) {
      a0 += c(r) * y0[r];
      a1 += c(r) * y1[r];
      a2 += c(r) * y2[r];
    }
    p.Pc(l, 0) = a0;
    p.Pc(l, 1) = a1;
    p.Pc(l, 2) = a2;
  }
  for (int k = 0; k < 3; ++k) p.m1c(k) = dot(in.m1.data() + k, 3, c, len[k]);
}

// Pcd, Pcdd, m1cd, m1cdd (the rate part after its products z).
template <class TQ, class TR>
void rateDots(const BodyInertia& in, const VecXT<TR>& cd, const VecXT<TR>& cdd, BasisProducts<TQ, TR>& p) {
  const std::array<int, 3>& len = in.len;
  for (int l = 0; l < 3; ++l) {  // six independent sums per row l, as in positionSums
    TR b[3] = {TR(0), TR(0), TR(0)}, d[3] = {TR(0), TR(0), TR(0)};
    for (int r = 0; r < len[l]; ++r)
      for (int j = 0; j < 3; ++j) {
        const TQ& y = p.y[3 * l + j](r);
        b[j] += cd(r) * y;
        d[j] += cdd(r) * y;
      }
    for (int j = 0; j < 3; ++j) {
      p.Pcd(l, j) = b[j];
      p.Pcdd(l, j) = d[j];
    }
  }
  for (int k = 0; k < 3; ++k) {
    p.m1cd(k) = dot(in.m1.data() + k, 3, cd, len[k]);
    p.m1cdd(k) = dot(in.m1.data() + k, 3, cdd, len[k]);
  }
}

// s = Σ_k S_kk c̈.
template <class TQ, class TR>
void traceProduct(const BodyInertia& in, const VecXT<TR>& cdd, BasisProducts<TQ, TR>& p) {
  const std::array<int, 3>& len = in.len;
  if (in.ne == 0) return;
  const int nc = in.nc();
  if (in.Strace.rows() == nc) {
    matvec(in.Strace_block, cdd, nc, p.scdd);
  } else {  // a body that was never finalized
    for (int r = 0; r < nc; ++r) p.scdd(r) = TR(0);
    for (int k = 0; k < 3; ++k) {
      matvec(in.S[4 * k], cdd, len[k], len[k], p.z[4 * k]);  // z_kk as scratch
      for (int r = 0; r < len[k]; ++r) p.scdd(r) += p.z[4 * k](r);
    }
  }
}

// Pcd, Pcdd, m1cd, m1cdd, s (the rate part after its products z).
template <class TQ, class TR>
void rateSums(const BodyInertia& in, const VecXT<TR>& cd, const VecXT<TR>& cdd, BasisProducts<TQ, TR>& p) {
  rateDots(in, cd, cdd, p);
  traceProduct(in, cdd, p);
}

}  // namespace detail

/// Stage 1: with S_kl = ∫ P_kᵀ P_l dm and m1 = ∫ P dm (entries beyond len[k] are zero),
///   y_kl = S_kl c, z_kl = S_kl ċ (k ≠ l; W has a zero diagonal), s = Σ_k S_kk c̈,
///   Pc(l,j) = c·y_lj, Pcd(l,j) = ċ·y_lj, Pcdd(l,j) = c̈·y_lj, m1c = m1 c, m1cd = m1 ċ, m1cdd = m1 c̈.
/// Position part: y, Pc, m1c.
template <class TQ, class TR>
void basisPositionProducts(const BodyInertia& in, const VecXT<TQ>& c, BasisProducts<TQ, TR>& p) {
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) detail::shapeProduct(in, 3 * k + l, c, p.y[3 * k + l]);
  detail::positionSums(in, c, p);
}

/// Rate part: z, Pcd, Pcdd, m1cd, m1cdd, s (needs the position part's y).
template <class TQ, class TR>
void basisRateProducts(const BodyInertia& in, const VecXT<TR>& cd, const VecXT<TR>& cdd, BasisProducts<TQ, TR>& p) {
  if (in.ne > 0)
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        if (k != l) detail::shapeProduct(in, 3 * k + l, cd, p.z[3 * k + l]);
  detail::rateSums(in, cd, cdd, p);
}

/// Both parts. With one scalar type and a finalized body, y_kl = S_kl c and z_kl = S_kl ċ (k ≠ l)
/// are formed in one sweep over each block (detail::matvec2).
template <class TQ, class TR>
void basisProducts(const BodyInertia& in, const VecXT<TQ>& c, const VecXT<TR>& cd, const VecXT<TR>& cdd,
                   BasisProducts<TQ, TR>& p) {
  if constexpr (std::is_same_v<TQ, TR>) {
    if (in.ne > 0 && in.Strace.rows() == in.nc()) {
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          const int kl = 3 * k + l;
          if (k == l) detail::matvec(in.S_block[kl], c, in.len[k], p.y[kl]);
          else detail::matvec2(in.S_block[kl], c, cd, in.len[k], p.y[kl], p.z[kl]);
        }
      detail::positionSums(in, c, p);
      detail::rateSums(in, cd, cdd, p);
      return;
    }
  }
  basisPositionProducts(in, c, p);
  basisRateProducts(in, cd, cdd, p);
}

/// Stage 2: F = −(m â + A m1c + 2 W m1ċ + m1c̈), T_i = −ε_ijk Q(j,k) with
/// Qᵀ = A Pc + 2 W Pcd + Pcdd + â m1cᵀ, and H = −Dᵀ G, G = m1ᵀ â + Σ_kl (A_kl y_kl + 2 W_kl z_kl) + s.
/// \param[in]  D  ∂c/∂q_e (nc × ne), scalar TQ
/// \param      G  scratch (dim ≥ nc)
/// \param[out] H  ne elastic forces
template <class T, class TQ, class TR>
void frameForces(const BodyInertia& in, const BasisProducts<TQ, TR>& p, const MatXT<TQ>& D, const Vec3T<T>& ahat,
                 const Vec3T<T>& alpha, const Vec3T<T>& omega, VecXT<T>& G, Vec3T<T>& F, Vec3T<T>& Tq, T* H) {
  const Mat3T<T> W = skew(omega);
  const Mat3T<T> A = skew(alpha) + W * W;
  for (int k = 0; k < 3; ++k) {
    T s = in.mass * ahat(k);
    s += p.m1cdd(k);
    for (int l = 0; l < 3; ++l) {
      s += A(k, l) * p.m1c(l);
      s += 2.0 * W(k, l) * p.m1cd(l);
    }
    F(k) = -s;
  }
  Mat3T<T> Qt;  // Qt(k, j) = ∫ s_j (a_P)_k dm
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      T s = ahat(k) * p.m1c(j);
      s += p.Pcdd(k, j);
      for (int l = 0; l < 3; ++l) {
        s += A(k, l) * p.Pc(l, j);
        s += 2.0 * W(k, l) * p.Pcd(l, j);
      }
      Qt(k, j) = s;
    }
  detail::momentOfSecondMoments(Qt, Tq);
  if (in.ne == 0) return;
  const int nc = in.nc();
  const std::array<int, 3>& len = in.len;
  // Row by row, each G(r) summed in a register (the same terms in the same order as adding each
  // product into G in turn, which stored and reloaded G(r) at every term).
  Mat3T<T> W2;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) W2(k, l) = 2.0 * W(k, l);
  for (int r = 0; r < nc; ++r) {
    T s = in.m1(0, r) * ahat(0);
    s += in.m1(1, r) * ahat(1);
    s += in.m1(2, r) * ahat(2);
    s += p.scdd(r);
    for (int k = 0; k < 3; ++k) {
      if (r >= len[k]) continue;
      for (int l = 0; l < 3; ++l) {
        s += A(k, l) * p.y[3 * k + l](r);
        if (k != l) s += W2(k, l) * p.z[3 * k + l](r);
      }
    }
    G(r) = s;
  }
  for (int j = 0; j < in.ne; ++j) {
    T s(0);
    for (int r = 0; r < nc; ++r) s += D(r, j) * G(r);
    H[j] = -s;
  }
}

/// Stage 2 of a rigid body (ne = 0, c = [1]), whose stage 1 is constant: m1c = m1, Pc(l, j) = S_lj,
/// and no rate terms. The same sums as frameForces without the zero terms (and without the nine
/// 1 × 1 products a rigid body's stage 1 would evaluate at every residual: five of the NREL 5MW
/// deck's nine bodies are rigid).
template <class T>
void rigidFrameForces(const BodyInertia& in, const Vec3T<T>& ahat, const Vec3T<T>& alpha, const Vec3T<T>& omega,
                      Vec3T<T>& F, Vec3T<T>& Tq) {
  const Mat3T<T> W = skew(omega);
  const Mat3T<T> A = skew(alpha) + W * W;
  for (int k = 0; k < 3; ++k) {
    T s = in.mass * ahat(k);
    for (int l = 0; l < 3; ++l) s += A(k, l) * in.m1(l, 0);
    F(k) = -s;
  }
  Mat3T<T> Qt;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      T s = ahat(k) * in.m1(j, 0);
      for (int l = 0; l < 3; ++l) s += A(k, l) * in.S[3 * l + j](0, 0);
      Qt(k, j) = s;
    }
  detail::momentOfSecondMoments(Qt, Tq);
}

}  // namespace whirl

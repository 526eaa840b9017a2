#pragma once
/// \file
/// Per-evaluation buffers (Pinocchio's Data): sized once from a Model, reused by every call so the
/// hot path does not allocate.
#include <vector>

#include "src/model/model.hpp"

namespace whirl {

/// Pose and motion of one body frame, ground components.
/// Jv, Jw (3 × ndof): partial velocities ∂v/∂q̇ and ∂ω/∂q̇ (Kane); a and dw include q̈.
template <class T>
struct FrameState {
  Mat3T<T> R;   ///< body → ground rotation
  Vec3T<T> r;   ///< origin position [m]
  Vec3T<T> v;   ///< origin velocity [m/s]
  Vec3T<T> a;   ///< origin acceleration [m/s²]
  Vec3T<T> w;   ///< angular velocity [rad/s]
  Vec3T<T> dw;  ///< angular acceleration [rad/s²]
  Mat3XT<T> Jv, Jw;
};

/// Buffers of one body's Ritz basis: c(q_e) and its time derivatives, D = ∂c/∂q_e.
template <class T>
struct BasisState {
  VecXT<T> c, cd, cdd;  ///< nc
  MatXT<T> D;           ///< nc × ne
};

template <class T>
struct Workspace {
  explicit Workspace(const Model& m);
  std::vector<FrameState<T>> frames;  ///< per body
  std::vector<BasisState<T>> basis;   ///< per body
  // Scratch for the body inertia forces (sized to the largest nc).
  std::vector<VecXT<T>> ukl;  ///< 9 vectors u_kl = A_kl c + 2 W_kl ċ + δ_kl c̈
  VecXT<T> g;                 ///< Σ_k ∫ P_kᵀ (a_P)_k dm
  VecXT<T> tmp;
  /// Set by AD Jacobian passes, which read only derivatives: residual() then skips the inertia
  /// forces of bodies none of whose coordinates carries a seeded direction (their values in e are
  /// then incomplete). Never set when the values of e are used.
  bool derivatives_only = false;
  VecXT<T> h;                 ///< elastic generalized inertia forces of one body (largest ne)
};

}  // namespace whirl

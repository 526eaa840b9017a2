#pragma once
/// \file
/// Dynamic inflow of AeroDyn's DBEMT_Mod 3: Øye's model (Øye 1991; Snel & Schepers 1995) in the
/// continuous form AeroDyn integrates and linearizes (DBEMT.f90, `DBEMT_CalcContStateDeriv`, `ComputeTau2`;
/// Branlard 2017, §"dynamic inflow"), per blade element and per component (axial, tangential):
///
///   dv1/dt = (−v1 + (1 − k) v_qs) / τ1,   dv/dt = (v1 − v + k v_qs) / τ2,
///
/// with v the induced velocity the loads see [m/s], v1 the intermediate state, v_qs the quasi-steady
/// (BEM) induced velocity, k = 0.6 (Øye's k), τ1 = `tau1_const` [s] and τ2 = (0.39 − 0.26 (r/R)²) τ1,
/// r/R the element's distance from the rotor axis over the largest one. Eliminating v1 gives the
/// second-order filter τ1 τ2 v̈ + (τ1 + τ2) v̇ + v = v_qs + k τ1 v̇_qs; AeroDyn's linearization states
/// are v and v̇ (`vind`, "first time derivative of vind"). Steady state: v1 = (1 − k) v_qs, v = v_qs.
#include "src/base/scalar.hpp"

namespace whirl::aero {

inline constexpr double kOyeK = 0.6;  ///< AeroDyn DBEMT p%k_0ye [-]

/// τ2 = (0.39 − 0.26 (r/R)²) τ1 [s] (AeroDyn ComputeTau2).
inline double dbemtTau2(double tau1, double span_ratio) { return (0.39 - 0.26 * span_ratio * span_ratio) * tau1; }

/// The two states of one component.
template <class T>
struct OyeState {
  T v1, v;  ///< intermediate and filtered induced velocity [m/s]
};

/// dx/dt of one component for the quasi-steady induced velocity v_qs [m/s] (DBEMT_CalcContStateDeriv).
template <class T>
OyeState<T> oyeDerivative(const OyeState<T>& x, const T& v_qs, double tau1, double tau2) {
  return {(-x.v1 + (1.0 - kOyeK) * v_qs) / tau1, (x.v1 - x.v + kOyeK * v_qs) / tau2};
}

/// The steady state for a constant v_qs: v1 = (1 − k) v_qs, v = v_qs.
template <class T>
OyeState<T> oyeSteady(const T& v_qs) {
  return {(1.0 - kOyeK) * v_qs, v_qs};
}

}  // namespace whirl::aero

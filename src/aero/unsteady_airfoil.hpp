#pragma once
/// \file
/// The continuous unsteady-airfoil model UA_Mod 4 of OpenFAST AeroDyn: the Hansen–Gaunaa–Madsen (HGM)
/// dynamic-stall model with four first-order states per blade element (Hansen, Gaunaa & Madsen 2004,
/// Risø-R-1354; as AeroDyn writes it, UnsteadyAero.f90: `Get_HGM_constants`, `UA_CalcContStateDeriv`,
/// `HGM_Steady`, `UA_CalcOutput`, `UA_BlendSteady`). Written once as templates on the scalar (double and
/// ADChunk, instantiated in unsteady_airfoil.cpp), like the rest of the equations.
///
/// States (AeroDyn's names and units):
/// - x1, x2 [rad]: the shed-vorticity (circulatory) lag of the angle of attack, Jones's two-term
///   approximation of Wagner's function: dx_i/dt = b_i/Tu (A_i α34 − x_i);
/// - x3 [-]: the lagged attached lift coefficient (leading-edge pressure lag), dx3/dt = (Cl_p − x3)/(T_p Tu),
///   Cl_p = C_lalpha (αE − alpha0) + π Tu ω;
/// - x4 [-]: the lagged separation point (boundary-layer lag), dx4/dt = (f_st(αF) − x4)/(T_f0 Tu),
///   αF = x3/C_lalpha + alpha0;
/// with Tu = c/(2U) [s] (U ≥ 0.01 m/s, Tu within [0.001, 50] s) and the effective angle
/// αE = α34 (1 − A1 − A2) + x1 + x2.
/// Loads (Cl, Cd, Cm about the section's reference point, as AeroDyn's eqs. 16–18 of its UA manual):
///   Cl = x4 Cl_fa(αE) + (1 − x4) Cl_fs(αE) + π Tu ω,
///   Cd = Cd(αE) + (α34 − αE) Cl_circ + (Cd(αE) − Cd0) Δ + Cl_circ Tu ω,
///        Δ = ½(√f_st(αE) − √x4) − ¼(f_st(αE) − x4),
///   Cm = Cm(αE) − π/2 Tu ω (0 without a Cm column),
/// then blended towards the static polar at the section's α near UACutout and at U below 1 m/s
/// (AeroDyn's UA_BlendSteady). Tu ω is limited to ±1.5 as AeroDyn does.
///
/// UA_Mod 6 (Øye's dynamic stall, AeroDyn's UA_OYE) goes through the same functions with
/// UaSection::ua_mod = 6: only x4 moves, towards f_st(α34) with T_f0 Tu; x1 = x2 = 0 and αE = α34; Cl =
/// x4 Cl_fa(α34) + (1 − x4) Cl_fs(α34), Cd and Cm static at α34 (no ω terms), then the same blending.
///
/// Left out (as AeroDyn's UA_Mod 4): vortex lift (UA_Mod 5's fifth state), the U̇ terms, and the 2π
/// wrap of α34 relative to x1/A1 (AddOrSub2Pi: it matters only when α crosses ±180°).
#include "src/aero/polar.hpp"
#include "src/aero/ua_coefficients.hpp"

namespace whirl::aero {

/// The section inputs of one element (AeroDyn's UA_InputType).
template <class T>
struct UaInput {
  T alpha_34;  ///< angle of attack at 3/4 chord [rad] (AeroDyn Get_Alpha34)
  T alpha_ac;  ///< angle of attack at the aerodynamic centre [rad] (u%alpha: cut-out blending only)
  T u;         ///< relative speed at the aerodynamic centre [m/s]
  T omega;     ///< pitch rate of the section [rad/s] (positive nose up)
};

/// The four HGM states [x1, x2, x3, x4].
template <class T>
struct HgmState {
  T x1, x2, x3, x4;
};

/// One element's airfoil: the static polar, its UA table and the chord.
struct UaSection {
  const Polar* polar = nullptr;  ///< static Cl, Cd, Cm (not owned)
  const UaTable* ua = nullptr;   ///< UA constants and separation columns (not owned)
  double chord = 0;              ///< [m]
  bool has_cm = true;            ///< the table has a Cm column (AeroDyn ColCm > 0)
  int ua_mod = 4;                ///< 4 (HGM) or 6 (Øye)
};

/// Tu = c / (2 max(U, 0.01)), within [0.001, 50] s (AeroDyn Get_Tu).
template <class T>
T hgmTimeScale(const T& u, double chord);

/// dx/dt of the HGM states [1/s units of each state].
template <class T>
HgmState<T> hgmDerivative(const UaSection& s, const HgmState<T>& x, const UaInput<T>& in);

/// The steady state for constant inputs: dx/dt = 0 exactly, x1 = A1 α34, x2 = A2 α34,
/// x3 = C_lalpha (α34 − alpha0) + π Tu ω, x4 = f_st(x3/C_lalpha + alpha0). (AeroDyn's HGM_Steady leaves
/// the π Tu ω term out of x3, so with ω ≠ 0 its start is not the equilibrium.)
template <class T>
HgmState<T> hgmSteady(const UaSection& s, const UaInput<T>& in);

/// Cl, Cd, Cm of the element from its states and inputs (cl, cd, cm of the result).
template <class T>
Coefficients<T> hgmLoads(const UaSection& s, const HgmState<T>& x, const UaInput<T>& in);

}  // namespace whirl::aero

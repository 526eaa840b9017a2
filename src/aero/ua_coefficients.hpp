#pragma once
/// \file
/// The unsteady-airfoil (UA) constants of one airfoil table and the columns the continuous UA models
/// read beside the static polar: the separation function f_st(α), the fully separated lift
/// coefficient Cl_fs(α) and the fully attached one Cl_fa(α), all as OpenFAST AeroDyn computes them
/// (AirfoilInfo.f90: `ReadAFfile` for the documented defaults, `CalculateUACoeffs` for the values
/// computed from the polar, `ComputeUASeparationFunction_onCl` and `ComputeUASeparationFunction_zero`
/// for the columns).
///
/// What AeroDyn computes from the polar when a constant is absent or "default" (its order matters:
/// each step uses the previous ones):
/// 1. Cd0 = the smallest Cd with |α| ≤ 20°, Cn = Cl cos α + (Cd − Cd0) sin α per row.
/// 2. alphaUpper / alphaLower: the ends of the linear region, where the Cn slope (per segment,
///    smoothed by a triweight kernel of radius 2°) falls below 0.9 of its largest value, walking up
///    (down) from the segment of minimum drag.
/// 3. C_nalpha, C_lalpha, alpha0: least-squares lines through Cn and Cl on the rows between
///    alphaLower and alphaUpper less 20 % of their distance at each end; alpha0 from the Cn line.
/// 4. Cm0 = Cm(alpha0), linear interpolation (0 without a Cm column).
/// 5. The columns (on Cl, UA_Mod 4 and 6; Hansen, Gaunaa & Madsen 2004, Risø-R-1354, eqs. 59–64):
///    Cl_fa = C_lalpha (α − alpha0), f_st = (2 √(Cl / Cl_fa) − 1)² in [0, 1],
///    Cl_fs = (Cl − Cl_fa f_st) / (1 − f_st) (Cl/2 where f_st = 1); outside the first minimum of f_st
///    below alphaLower and above alphaUpper, f_st = 0 and Cl_fs = Cl (monotonic separation); then f_st
///    recomputed from the two as (Cl − Cl_fs) / (Cl_fa − Cl_fs) so that
///    Cl = f_st Cl_fa + (1 − f_st) Cl_fs holds on every row.
/// A polar that looks like a cylinder (Cd constant or Cl below 0.01 for |α| ≤ 20°) gets alpha0 = 0,
/// slopes 0, Cn1 = Cn2 = 0, alpha1/2 = ±10°, alphaLower/Upper = ∓5°, and f_st = 0 (AeroDyn then runs
/// no UA on it). The stall angles alpha1/alpha2 and Cn1/Cn2 are used only by the discrete
/// Beddoes–Leishman models (UA_Mod 2, 3), which whirl does not model: they are kept as given.
/// UA_Mod 5's separation function on Cn (`ComputeUA360_*`) is not implemented.
#include <optional>
#include <string>
#include <vector>

#include "src/aero/polar.hpp"

namespace whirl::aero {

/// The UA constants an airfoil table gives, in SI (angles in rad); nullopt = absent or "default".
struct UaGiven {
  std::optional<double> alpha0, alpha1, alpha2, alpha_upper, alpha_lower;  ///< [rad]
  std::optional<double> eta_e, c_nalpha, c_lalpha;                         ///< [-], [1/rad]
  std::optional<double> T_f0, T_V0, T_p, T_VL;                             ///< [-] (in units of c / 2U)
  std::optional<double> b1, b2, b5, A1, A2, A5;                            ///< [-]
  std::optional<double> S1, S2, S3, S4, Cn1, Cn2, St_sh, Cd0, Cm0;         ///< [-]
  std::optional<double> k0, k1, k2, k3, k1_hat, x_cp_bar;                  ///< [-]
  std::optional<double> ua_cutout, ua_cutout_delta;                        ///< [rad]
  std::optional<double> filt_cutoff;                                       ///< [-]
};

/// The UA constants of one table with every default filled in (AeroDyn's AFI_UA_BL_Type).
struct UaConstants {
  double alpha0 = 0, alpha_upper = 0, alpha_lower = 0;  ///< zero-lift angle, ends of the linear region [rad]
  std::optional<double> alpha1, alpha2, Cn1, Cn2;       ///< stall constants, as given (not computed, see file)
  double eta_e = 1, c_nalpha = 0, c_lalpha = 0;         ///< [-], normal-force and lift slopes [1/rad]
  double T_f0 = 3, T_V0 = 6, T_p = 1.7, T_VL = 11;      ///< time constants in units of c / (2U) [-]
  double b1 = 0.14, b2 = 0.53, b5 = 5;                  ///< indicial exponents [-]
  double A1 = 0.3, A2 = 0.7, A5 = 1;                    ///< indicial amplitudes [-]
  double S1 = 0, S2 = 0, S3 = 0, S4 = 0, St_sh = 0.19;  ///< [-]
  double Cd0 = 0, Cm0 = 0;                              ///< drag at minimum, moment at alpha0 [-]
  double k0 = 0, k1 = 0, k2 = 0, k3 = 0, k1_hat = 0, x_cp_bar = 0.2;           ///< [-]
  double ua_cutout = 0.785398163397448, ua_cutout_delta = 0.0872664625997165;  ///< 45°, 5° [rad]
  double ua_cutout_blend = 0.698131700797732;  ///< max(0, |UACutout| − |UACutout_delta|) [rad]
  double filt_cutoff = 0.5;                    ///< [-]
};

/// One table's UA data: the constants and the separation columns on the polar's knots.
struct UaTable {
  UaConstants c;
  bool included = false;  ///< AeroDyn InclUAdata after its checks (false for a constant table)
  bool cylinder = false;  ///< the polar looked like a cylinder (see file comment)
  /// Columns as a polar on the same knots and interpolation as the static one, so that they are
  /// evaluated exactly as AeroDyn's AFI_ComputeAirfoilCoefs evaluates them with Cl, Cd, Cm:
  /// `cl` holds f_st, `cd` Cl_fs and `cm` Cl_fa (see separationAt).
  Polar columns;
};

/// The UA data of a table with knots alpha [rad] and coefficients cl, cd, cm (cm empty: no Cm column),
/// interpolated as `interp`, for UA model `ua_mod` (4 or 6: separation on Cl).
/// Throws InputError (starting with `source`) when the table has no row with |α| ≤ 20°, or ua_mod is 5
/// (separation on Cn: not implemented).
UaTable uaTable(const UaGiven& given, const std::vector<double>& alpha, const std::vector<double>& cl,
                const std::vector<double>& cd, const std::vector<double>& cm, PolarInterp interp, int ua_mod,
                const std::string& source);

/// f_st, Cl_fs and Cl_fa at α [rad] (wrapped as the polar wraps it).
template <class T>
struct Separation {
  T f_st, cl_fs, cl_fa;
};
template <class T>
Separation<T> separationAt(const UaTable& t, const T& alpha) {
  const Coefficients<T> c = evaluate(t.columns, alpha);
  return {c.cl, c.cd, c.cm};
}

/// Triweight kernel smoothing of f(x) with radius r (NWTC Library `kernelSmoothing`, kernelType 3):
/// each value replaced by the kernel-weighted mean of all values, weights 35/32 (1 − u²)³ with
/// u = (x_i − x_j)/r clipped to [−1, 1].
std::vector<double> triweightSmoothing(const std::vector<double>& x, const std::vector<double>& f, double r);

}  // namespace whirl::aero

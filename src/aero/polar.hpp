#pragma once
/// \file
/// An airfoil's steady polar (lift, drag and pitching-moment coefficients against angle of attack) and
/// its interpolation exactly as OpenFAST AeroDyn v15 (AirfoilInfo.f90, `AFI_ComputeAirfoilCoefs1D`) does it:
///
/// - The angle of attack is first wrapped with NWTC `MPi2Pi`: α ← modulo(α, 2π), then α ← α − 2π if α > π,
///   so the wrapped angle lies in (−π, π] (π itself stays π).
/// - Outside the table (α ≤ α₁ or α ≥ α_N) the end rows are returned unchanged (`CubicSplineInterpM`).
/// - Inside, segment i with α_i ≤ α < α_{i+1} (`LocateBin`) is evaluated as the cubic
///   c₀ + c₁ x + c₂ x² + c₃ x³, x = α − α_i.
/// - `InterpOrd = 1` (AeroDyn's default, used by the NREL 5MW airfoils, "DEFAULT" → 1 in `ReadAFfile`):
///   `CubicLinSplineInitM`, piecewise linear, c₂ = c₃ = 0.
/// - `InterpOrd = 3`: NWTC `CubicSplineInitM`. This is neither a natural nor a not-a-knot spline: with
///   h_i = α_{i+1} − α_i, s_i = (y_{i+1} − y_i)/h_i and M_i = y''(α_i), the N−1 unknowns M_1..M_{N−1}
///   solve (1-based, as in the Fortran)
///       2(h_1 + h_2) M_1 + h_1 M_2                       = 6 (s_2 − s_1)                (row 1)
///       h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (s_i − s_{i−1}),  i = 2..N−1
///   with M_N = 0 (natural at the last knot only; row 1 is an unusual condition at the first knot, not
///   the interior equation of knot 2, whose right-hand side it reuses). Reproduced here as written,
///   by the same forward elimination and back substitution.
/// - A table with fewer than 3 rows, or whose rows are all equal, is constant (`ConstData`).
///
/// Several tables on the Reynolds number (AeroDyn `AFTabMod = 2`, AeroDyn v14 `MultiTab = RENUM`): each
/// table is evaluated at α as above and the two whose Reynolds numbers bracket the element's are
/// interpolated linearly in log Re (AeroDyn v15, `AFI_ComputeAirfoilCoefs2D` with `secondVals` = log Re)
/// or in Re (AeroDyn v14's table IDs); below the first (above the last) the end table alone. UserProp
/// tables (`AFTabMod = 3`) are not modelled.
#include <array>
#include <string>
#include <vector>

namespace whirl::aero {

/// Interpolation order of the polar (AeroDyn airfoil-file key `InterpOrd`).
enum class PolarInterp {
  Linear,      ///< InterpOrd = 1 (AeroDyn default)
  CubicSpline  ///< InterpOrd = 3 (NWTC CubicSplineInitM, see the file comment for its end conditions)
};

/// One airfoil table. Angles in rad; coefficients dimensionless (Cm about the aerodynamic reference point,
/// positive nose up, as in the AeroDyn airfoil files).
struct Polar {
  std::string name;
  std::vector<double> alpha, cl, cd, cm;  ///< knots (alpha strictly increasing, covering [−π, π]) [rad], [-]
  PolarInterp interp = PolarInterp::Linear;
  bool constant = false;  ///< AeroDyn's ConstData: fewer than 3 rows or all rows equal → row 0 everywhere
  /// Polynomial coefficients per segment i (alpha[i] ≤ α < alpha[i+1]): y = c[0] + c[1] x + c[2] x² + c[3] x³,
  /// x = α − alpha[i]; one vector per coefficient (size alpha.size() − 1).
  std::vector<std::array<double, 4>> ccl, ccd, ccm;
  /// Tables on the Reynolds number, the first being this one's own (empty: this table at every Re).
  std::vector<Polar> re_tables;
  std::vector<double> re_axis;  ///< per table: log Re (re_log) or Re, strictly increasing
  bool re_log = true;           ///< interpolate in log Re (AeroDyn v15) or in Re (AeroDyn v14)
};

/// How an airfoil's tables on the Reynolds number are interpolated.
enum class ReynoldsInterp {
  None,   ///< the first table only (AFTabMod = 1, MultiTab = SINGLE)
  Log,    ///< linear in log Re (AeroDyn v15, AFTabMod = 2)
  Linear  ///< linear in Re (AeroDyn v14, MultiTab = RENUM)
};

/// `tables` (each from makePolar, at Reynolds number re[k] > 0) as one polar on the Reynolds number.
/// Throws InputError (message starting with sources[k]) when the Reynolds numbers are not positive or
/// not strictly increasing.
Polar reynoldsPolar(std::vector<Polar> tables, const std::vector<double>& re, ReynoldsInterp interp,
                    const std::vector<std::string>& sources);

/// Builds a polar from a table (alpha in rad). Throws InputError (message starting with `source`, e.g.
/// "file:line: ...") when alpha is not strictly increasing, sizes differ, the table is empty, values are
/// non-finite, or the table does not cover −π..π (within 1e-3 rad).
Polar makePolar(std::string name, std::vector<double> alpha, std::vector<double> cl, std::vector<double> cd,
                std::vector<double> cm, PolarInterp interp, const std::string& source);

template <class T>
struct Coefficients {
  T cl, cd, cm;
};

/// Coefficients at alpha [rad] (any real; wrapped into (−π, π] as AeroDyn's MPi2Pi does). T = double or
/// ADChunk: the segment is chosen from the value of alpha and the polynomial is evaluated in T, so the
/// derivatives are exact (zero outside the table and for a constant table; one-sided, from the segment
/// to the right, at a knot).
template <class T>
Coefficients<T> evaluate(const Polar& p, const T& alpha);

/// Coefficients at alpha [rad] and Reynolds number re (> 0; AeroDyn limits it to ≥ 0.001): evaluate(p,
/// alpha) when p has no tables on the Reynolds number, else the interpolation of the file comment, in T
/// through both arguments (the bracket from their values).
template <class T>
Coefficients<T> evaluate(const Polar& p, const T& alpha, const T& re);

/// Wraps an angle [rad] into (−π, π] exactly as NWTC MPi2Pi (modulo(a, 2π), then −2π above π).
double wrapMPi2Pi(double a);

}  // namespace whirl::aero

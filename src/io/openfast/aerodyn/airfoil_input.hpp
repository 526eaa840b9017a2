#pragma once
/// \file
/// AeroDyn airfoil files (OpenFAST's AirfoilInfo format): the interpolation order, one or more tables
/// of lift, drag and pitching-moment coefficients against the angle of attack, and the unsteady-aero
/// (Beddoes–Leishman) constants of each table. Plain data in the file's units (angles in degrees,
/// Reynolds number in millions); building an interpolating polar from it is the aero layer's job.
///
/// The format (AirfoilInfo v1.00–v1.01, OpenFAST v2–v5): comment lines start with '!' (also '#', '%')
/// and are skipped; then `InterpOrd`, `RelThickness` (v4+, optional), `NonDimArea`, `NumCoords`
/// (a count, or `@"file"` naming a coordinates file, not read), `BL_file` (optional), `NumTabs`, and per
/// table `Re`, `UserProp` (`Ctrl` before v3), `InclUAdata` [30-odd UA constants], `NumAlf` and NumAlf
/// rows of numbers. Which column holds α, Cl, Cd and Cm is chosen by the AeroDyn main file (`InCol_*`).
/// The first line of the file must be a comment or blank (every AirfoilInfo file has a header comment).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/aero/polar.hpp"

namespace whirl::io {

/// Columns of the coefficient tables, 1-based as AeroDyn's `InCol_Alfa`, `InCol_Cl`, `InCol_Cd`,
/// `InCol_Cm` (0 = the tables have no Cm column).
struct AirfoilColumns {
  int alpha = 1;
  int cl = 2;
  int cd = 3;
  int cm = 4;
};

/// Unsteady-aerodynamics constants of one table, kept for later (whirl's airfoils are quasi-steady).
/// Each is nullopt when the line is absent or reads "default" (OpenFAST then computes or defaults it).
/// Units as in the file: angles in degrees, C_nalpha and C_lalpha per radian, the rest dimensionless.
struct AirfoilUAData {
  bool included = false;  ///< InclUAdata: the table carries UA constants
  /// "file:line: key: reason" of the first constant unusable by a UA model (a time constant ≤ 0, |alpha0|
  /// > 180°); empty when all are usable. AeroDyn checks them only for the airfoils of elements with UA
  /// (UnsteadyAero.f90, UA_ValidateAFI), so the reader keeps the reason and io::airfoilUa raises it.
  std::string invalid;
  std::optional<double> alpha0, alpha1, alpha2;  ///< zero-lift and stall angles (deg)
  std::optional<double> alphaUpper, alphaLower;  ///< UA_Mod 7 limits (deg), OpenFAST v3.4+
  std::optional<double> eta_e;                   ///< recovery factor (-)
  std::optional<double> C_nalpha, C_lalpha;      ///< normal-force / lift slopes (1/rad)
  std::optional<double> T_f0, T_V0, T_p, T_VL;   ///< time constants (-)
  std::optional<double> b1, b2, b5, A1, A2, A5;  ///< indicial-function constants (-)
  std::optional<double> S1, S2, S3, S4;          ///< f-curve fit constants (-)
  std::optional<double> Cn1, Cn2;                ///< critical normal-force coefficients (-)
  std::optional<double> St_sh;                   ///< Strouhal shedding number (-)
  std::optional<double> Cd0, Cm0;                ///< drag and moment coefficients at zero lift (-)
  std::optional<double> k0, k1, k2, k3, k1_hat;  ///< centre-of-pressure fit constants (-)
  std::optional<double> x_cp_bar;                ///< vortex centre-of-pressure constant (-)
  std::optional<double> UACutout;                ///< angle above which UA is off (deg)
  std::optional<double> UACutout_delta;          ///< blending width above UACutout (deg)
  std::optional<double> filtCutOff;              ///< AoA filter cut-off (reduced frequency or Hz, per version)
};

/// One coefficient table of an airfoil file.
struct AirfoilTable {
  double re = 0.0;                ///< Reynolds number (millions), `Re`
  double user_prop = 0.0;         ///< user property (control setting), `UserProp` or `Ctrl`
  AirfoilUAData ua;               ///< unsteady-aero constants (not used by whirl)
  std::vector<double> alpha_deg;  ///< angle of attack (deg), strictly increasing
  std::vector<double> cl;         ///< lift coefficient (-)
  std::vector<double> cd;         ///< drag coefficient (-)
  std::vector<double> cm;         ///< pitching-moment coefficient (-); empty when InCol_Cm = 0
  int re_line = 0;                ///< line of `Re` (start of the table's block)
  int num_alf_line = 0;           ///< line of `NumAlf`
  int first_row_line = 0;         ///< line of the first row of numbers
  std::vector<int> row_lines;     ///< line of every row
};

/// An airfoil file.
struct AirfoilInput {
  std::string name;                     ///< file name without folder and extension, e.g. "DU21_A17"
  std::filesystem::path path;           ///< the file read
  int interp_order = 1;                 ///< `InterpOrd`: 1 linear, 3 cubic spline ("default" = 1, as OpenFAST)
  bool interp_order_default = false;    ///< true when the file says "default"
  std::optional<double> rel_thickness;  ///< `RelThickness` (-), OpenFAST v4+; nullopt when absent/default
  double non_dim_area = 1.0;            ///< `NonDimArea`, area / chord² (unused by AeroDyn)
  std::optional<int> num_coords;        ///< `NumCoords` when a number (coordinates follow inline, not kept)
  std::optional<std::filesystem::path> coords_file;  ///< `NumCoords` given as @"file" (resolved, not read)
  std::optional<std::string> bl_file;  ///< `BL_file` as written (aeroacoustics only), absent in older files
  std::vector<AirfoilTable> tables;    ///< `NumTabs` tables, in file order
};

/// Reads an airfoil file, taking α, Cl, Cd and Cm from the columns `columns` gives.
/// Throws InputError "file:line: key: reason" when the file is missing, a key is missing or malformed,
/// `InterpOrd` is not 1 or 3, `Re` is not positive, a table has fewer rows than `NumAlf` (truncated),
/// a row has fewer numbers than the columns asked for, a value is NaN or infinite, or α does not
/// strictly increase.
AirfoilInput readAirfoil(const std::filesystem::path& file, const AirfoilColumns& columns = {});

/// The quasi-steady polar of an airfoil file as AeroDyn uses it with AFTabMod = 1: the first table, α
/// in rad, `InterpOrd` 3 as the cubic spline, Cm zero when the file has none or `use_cm` is false
/// (AeroDyn's UseBlCm). Shared by the OpenFAST deck and the YAML case.
/// \throws InputError "file:line: reason" when the file has no table or the table is not a valid polar
///         (makePolar: α must cover −180° to 180°).
aero::Polar airfoilPolar(const AirfoilInput& af, bool use_cm,
                         aero::ReynoldsInterp reynolds = aero::ReynoldsInterp::None);

}  // namespace whirl::io

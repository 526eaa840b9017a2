#pragma once
/// \file
/// AeroDyn v14 airfoil files (the `AeroData/*.dat` of the FAST 8 certification tests), read into the
/// same AirfoilInput as AeroDyn v15's AirfoilInfo files.
///
/// The layout (AeroDyn v14, Laino and Hansen 2002), read by position: two title lines; the number of
/// tables N; then one line each with N values (one per table) and a description: table ID (Reynolds
/// number in millions or a control setting), stall angle (deg), three unused lines, the angle of zero
/// normal force (deg), the normal-force slope (1/rad), the normal-force coefficients at positive and
/// negative stall, the angle of minimum drag (deg) and the minimum drag coefficient; then rows to the
/// end of the file: α (deg) followed, per table, by Cl, Cd and — when AeroDyn's UseCm = USE_CM — Cm.
/// Numbers and words after those a row needs are ignored, as AeroDyn's list-directed reads ignore them.
#include <filesystem>

#include "src/io/openfast/aerodyn/airfoil_input.hpp"

namespace whirl::io {

/// Reads an AeroDyn v14 airfoil file; `use_cm` (UseCm = USE_CM) says whether the rows carry Cm. The N
/// tables become AirfoilInput tables (re = table ID; ua.alpha0, alpha1, C_nalpha, Cn1, Cn2 and Cd0 from
/// the header, kept for later), `interp_order` 1 (AeroDyn v14 interpolates linearly).
/// Throws InputError "file:line: what: reason": a header line without N numbers, N < 1, a row with too
/// few numbers or a word that is not a number, NaN or infinite values, α not strictly increasing, no rows.
AirfoilInput readAirfoil14(const std::filesystem::path& file, bool use_cm);

}  // namespace whirl::io

#pragma once
/// \file
/// The WAMIT output files HydroDyn reads for a linear model: the hydrostatic restoring matrix (`.hst`)
/// and the added mass at infinite frequency (`.1`). The excitation (`.3`) is not read: no waves.
#include "src/io/openfast/offshore/hydrodyn_input.hpp"

namespace whirl::io {

/// The linear potential-flow matrices of a WAMIT body, dimensional, about the WAMIT origin.
struct WamitMatrices {
  Mat6 hydrostatic = Mat6::Zero();  ///< restoring C of the `.hst` file (N/m, N, N m/rad)
  Mat6 added_mass = Mat6::Zero();   ///< added mass at infinite frequency of the `.1` file (kg, kg m, kg m²)
};

/// The same files as WAMIT writes them: nondimensional coefficients (C̄_ij of the `.hst`, Ā_ij of the
/// `.1` at infinite frequency) and the length scale L = WAMITULEN. What the deck reader keeps
/// (readOpenFastTurbine): the turbine scales them with its water density and gravity (dimensional).
struct WamitCoefficients {
  Mat6 hydrostatic = Mat6::Zero();
  Mat6 added_mass = Mat6::Zero();
  double L = 1.0;  ///< WAMITULEN [m]
};

/// `<PotFile><ext>`, or the unique file of its folder whose name matches it ignoring case (the
/// certification decks were written on Windows: `Spar` for `spar.hst`).
/// \throws InputError naming PotFile when there is none.
std::filesystem::path wamitFile(const HydroDynInput& hd, const std::string& ext);

/// Reads `<PotFile>.hst` and `<PotFile>.1` (rows "PER I J A [B]"; the infinite-frequency added mass is
/// the rows with PER = 0, zero period, as WAMIT writes it and HydroDyn reads it; PER < 0 is the zero
/// frequency) and redimensionalizes them with ρ, g and L = WAMITULEN (WAMIT's
/// conventions: C_ij ρ g L^k with k = 2, 3, 4 for 0, 1, 2 rotational indices; A_ij ρ L^k with k = 3,
/// 4, 5). A file missing, a row that is not numbers, an index outside 1..6, or no infinite-frequency
/// row → InputError "file:line: reason". A name that differs from the files only by case is accepted
/// when the match is unique (the certification decks were written on Windows: `Spar` for `spar.hst`).
WamitMatrices readWamit(const HydroDynInput& hd, double rho, double g);

/// The files of readWamit, not yet redimensionalized (same errors).
WamitCoefficients readWamitCoefficients(const HydroDynInput& hd);

/// C_ij = C̄_ij ρ g L^k, A_ij = Ā_ij ρ L^k (WAMIT's conventions, readWamit).
WamitMatrices dimensional(const WamitCoefficients& c, double rho, double g);

}  // namespace whirl::io

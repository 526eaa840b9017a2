#pragma once
/// \file
/// Aerodynamic roots of a rotor's modes (issue 47, item 4): the roots that the blade elements'
/// aerodynamic states (the unsteady-airfoil states, linearize/unsteady_aero.hpp) add to the structure's.
/// A model with nz aerodynamic states has nz more eigenvalues than its structure: the nz with the largest
/// participation in those states (modal/participation.hpp; a complex pair counts as two) are the
/// aerodynamic roots, the others the structure's, as many as without the states. A share threshold alone
/// (e.g. over half) does not separate them: on the NREL 5MW with UA above 8 m/s the states split off
/// heavily damped roots from the first flap modes (real, or oscillating at 0.2 Hz) with 26–48 % of their
/// participation in the states, which would take structural lines, while the flap modes themselves keep
/// 4–16 % (campbell --unsteady-aero --wind 4:2:24). The aerodynamic roots are named `aero 1`, `aero 2`, …
/// in order of frequency at each operating point, listed apart (campbell_aero.csv,
/// src/writers/campbell_aero.hpp) and left out of the mode tracking (modal/tracking.hpp), so that none can
/// take a structural line's place; the structural modes are named from their structural coordinates alone.
///
/// Which coordinates are aerodynamic: the rotating first-order states (a state of its own with a blade,
/// RotorCoordinates::blade ≥ 0), the only ones whirl has being the blade elements' UA and DBEMT states.
#include <string>
#include <vector>

#include "modal/modes.hpp"

namespace whirl {

/// The share of `mode`'s participation in the coordinates flagged by `aero` (dim of the participation).
double aeroShare(const Mode& mode, const std::vector<bool>& aero);

/// Whether `mode` is an aerodynamic root, as nameAeroRoots marked it (first-order, named "aero <k>").
bool isAeroRoot(const Mode& mode);

/// Which of a set of roots are the aerodynamic ones: by decreasing `share` (each root's participation
/// share in the aerodynamic states), as many roots as there are aerodynamic states, `count`; a complex pair
/// (`pair`) counts two and, when only one is left, is skipped for a single root further down with at least
/// half its share, else taken (it then holds the last state's root and a structural first-order one); a
/// root with `excluded` (a rigid-body mode) never is one.
std::vector<bool> pickAeroRoots(const std::vector<double>& share, const std::vector<bool>& pair,
                                const std::vector<bool>& excluded, int count);

/// Whether state or coordinate `name` is a blade element's aerodynamic state ("UA x1 blade 2 element 7",
/// after the multiblade transform "UA x1 element 7 cos"; the dynamic-inflow states "DBEMT v axial blade 2
/// element 7", "DBEMT v1 tangential element 7 sin": src/dynamics/aero_unsteady.hpp).
bool isAeroStateName(const std::string& name);

/// Marks (Mode::first_order) and names the aerodynamic roots of `modes` (sorted by frequency, each real
/// root a mode of its own): by decreasing aeroShare, as many roots as `aero` flags coordinates (one state
/// each), a complex pair counting two (as pickAeroRoots); named "aero 1", "aero 2", … in the
/// order of `modes`, their name evidence the aerodynamic share. \return the number of aerodynamic modes.
int nameAeroRoots(std::vector<Mode>& modes, const std::vector<bool>& aero);

}  // namespace whirl

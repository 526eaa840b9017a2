#pragma once
/// \file
/// Which blade elements carry unsteady-airfoil states, as AeroDyn decides it:
/// - by span (AeroDyn.f90, Init_MiscVars → UA_Init's UAOff_innerNode / UAOff_outerNode): with
///   frac_j = rLocal_j / rMax (the element's distance from the rotor axis over the largest of all
///   elements), UA is off from the root up to the last element with frac < UAStartRad and from the first
///   element with frac > UAEndRad to the tip;
/// - by airfoil (UnsteadyAero.f90, UA_TurnOff_param): off for a constant table (no UA data, e.g. a
///   cylinder), a separation function that is 0 everywhere, or C_lalpha = 0 (UA_Mod 4 and 6).
/// An element without UA is quasi-steady and has no states (OpenFAST's .lin files list none for it).
#include <vector>

#include "src/aero/ua_coefficients.hpp"

namespace whirl::aero {

/// Per element (root to tip) of one blade: inside [UAStartRad, UAEndRad] by AeroDyn's rule.
/// r_local [m] per element, r_max [m] > 0 the largest over all blades, start ≤ end fractions in [0, 1].
std::vector<bool> uaSpanMask(const std::vector<double>& r_local, double r_max, double start, double end);

/// Whether a table can carry UA states (UA_TurnOff_param).
bool uaPossible(const UaTable& t);

}  // namespace whirl::aero

#pragma once
/// \file
/// Blade-element loads with unsteady-airfoil states (AeroDyn UA_Mod 4 or 6, src/aero/unsteady_airfoil.hpp)
/// on the frozen wake of an operating point: the loads of the linear model's first-order aerodynamic
/// states. Per element that carries states (AeroStation::ua), the section inputs of AeroDyn's UA
/// (UA_InputType) from the element's motion:
/// - the relative flow with the frozen induction, x = Vx + AxInd, y = Vy + TnInd, as aero::frozenLoads:
///   φ = atan2(x, y), α = φ − θ, U = |(x, y)| (AeroDyn SetInputs_for_UA);
/// - ω = the section's angular velocity about the span axis z_a of its annulus frame, positive nose up
///   (towards larger α: about body +x, aero_model.hpp), the body frame's and the elastic twist's
///   (AeroDyn: RotationVel · the airfoil frame's z axis);
/// - α34 = atan2(U sin α + ω c/2, U cos α), the angle at 3/4 chord (AeroDyn Get_Alpha34 with AoA34 true,
///   the aerodynamic centre at 1/4 chord);
/// and Cl, Cd, Cm from the states (aero::hgmLoads), whose rates are aero::hgmDerivative. Elements without
/// states, and all elements when no states are given, take the quasi-steady frozen-wake loads
/// (aero::frozenLoads), as addAeroLoads with a frozen wake. Written once for double and ADChunk, so that
/// the linear model's rows and columns of the states come from AD (linearize/unsteady_aero.hpp).
#include <string>
#include <vector>

#include "src/aero/unsteady_airfoil.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// States per element that carries them: 4 (UA_Mod 4: x1..x4) or 1 (UA_Mod 6: x4); 0 without UA.
int uaStatesPerElement(const AeroModel& am);
/// The number of unsteady-airfoil states of the model (elements with AeroStation::ua, all blades).
int uaStateCount(const AeroModel& am);
/// Their names, "UA x1 blade 2 element 7" (elements numbered from the root, 1-based, as AeroDyn's nodes),
/// and groups "UA x1 blade 2" (one per state kind and blade: the rotating group of the multiblade transform).
void uaStateNames(const AeroModel& am, std::vector<std::string>& names, std::vector<std::string>& groups);
/// Takes the unsteady-airfoil data out of the model (ua_mod 0, no tables, no element with states): the
/// quasi-steady polar everywhere, whatever a linearization asks (`--quasi-steady-aero`).
void removeUnsteadyAirfoils(AeroModel& am);

/// e += the generalized aerodynamic forces (dim ndof) at the kinematics already in ws (forwardKinematics at
/// q, qd), with the induced velocities `frozen` and the UA states z (dim uaStateCount, elements in order
/// and per element its states); zdot (if given, dim uaStateCount) = the states' rates. z null: every element
/// quasi-steady (zdot untouched). `inputs` (if given) receives the UA inputs of the elements with states.
template <class T>
void addUnsteadyAeroLoads(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& u,
                          const AeroInflow& frozen, const VecXT<T>* z, VecXT<T>& e, VecXT<T>* zdot,
                          std::vector<aero::UaInput<T>>* inputs = nullptr);

/// The airfoil of a station for the UA functions (the polar, its UA table and Cm rule, the chord).
aero::UaSection uaSection(const AeroModel& am, const AeroStation& st);

}  // namespace whirl

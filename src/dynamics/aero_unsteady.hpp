#pragma once
/// \file
/// Blade-element loads with unsteady-airfoil states (AeroDyn UA_Mod 4 or 6, src/aero/unsteady_airfoil.hpp)
/// and dynamic-inflow states (DBEMT_Mod 3, src/aero/dynamic_inflow.hpp), or on the frozen wake of an operating point:
/// the loads of the linear model's first-order aerodynamic states. Per element that carries states (AeroStation::ua),
/// the section inputs of AeroDyn's UA (UA_InputType) from the element's motion:
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
#include "src/dynamics/aero_loads.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// States per element that carries them: 4 (UA_Mod 4: x1..x4) or 1 (UA_Mod 6: x4); 0 without UA.
int uaStatesPerElement(const AeroModel& am);
/// The number of unsteady-airfoil states of the model (elements with AeroStation::ua, all blades).
int uaStateCount(const AeroModel& am);
/// Their names, "UA x1 blade 2 element 7" (elements numbered from the root, 1-based, as AeroDyn's nodes),
/// and groups "UA x1 blade 2" (one per state kind and blade: the rotating group of the multiblade transform).
void uaStateNames(const AeroModel& am, std::vector<std::string>& names, std::vector<std::string>& groups);
/// Dynamic-inflow states per element (AeroDyn DBEMT_Mod 3 on the BEM induction, src/aero/dynamic_inflow.hpp):
/// 4 (v and v1, each axial and tangential), on every element as AeroDyn; 0 without.
int inflowStatesPerElement(const AeroModel& am);
/// The number of dynamic-inflow states of the model (every element of every blade).
int inflowStateCount(const AeroModel& am);
/// The aerodynamic states of the model: uaStateCount + inflowStateCount (in that order in z).
int aeroStateCount(const AeroModel& am);
/// The dynamic-inflow states' names, per element "DBEMT v axial blade 2 element 7", "DBEMT v tangential …",
/// "DBEMT v1 axial …", "DBEMT v1 tangential …" (v the induced velocity the loads see, v1 Øye's intermediate
/// state; AeroDyn's `vind` and the one its .lin calls "First time derivative of vind"), and groups
/// "DBEMT v axial blade 2" (the rotating group of the multiblade transform).
void inflowStateNames(const AeroModel& am, std::vector<std::string>& names, std::vector<std::string>& groups);
/// Takes the dynamic inflow out of the model (dbemt_mod 0): the frozen wake in the linear model.
void removeDynamicInflow(AeroModel& am);
/// Takes the unsteady-airfoil data out of the model (ua_mod 0, no tables, no element with states): the
/// quasi-steady polar everywhere, whatever a linearization asks (`--quasi-steady-aero`).
void removeUnsteadyAirfoils(AeroModel& am);

/// e += the generalized aerodynamic forces (dim ndof) at the kinematics already in ws (forwardKinematics at
/// q, qd), with the induced velocities `frozen` and the aerodynamic states z (dim aeroStateCount: the UA
/// states, elements in order and per element its states, then the dynamic-inflow states, inflowStateNames'
/// order); zdot (if given, same dim) = the states' rates. z null: every element quasi-steady on the frozen
/// wake (zdot untouched). With dynamic-inflow states the elements see their states v instead of the frozen
/// induction (AeroDyn calculate_Inductions_from_DBEMT; the elements with fixed inductions, at a loss constant
/// of 0, the BEM ones, as AeroDyn), and v̇, v̇1 are driven by the quasi-steady BEM induced velocity at the
/// current inflow (aero::quasiSteadyInducedVelocity: the root solved in double, its derivatives by the
/// implicit-function theorem). `inputs` (if given) receives the UA inputs of the elements with states;
/// `quasi_steady` (if given, dim 2 nstations, with dynamic-inflow states) the quasi-steady induced velocities,
/// axial and tangential per element. `element` ≥ 0 (an element over all blades, in AeroModel order) evaluates
/// that element alone: e receives its loads only, zdot and `quasi_steady` its entries only (the rest untouched),
/// `inputs` its UA inputs only. `minus_quasi_steady`: e receives the loads less the quasi-steady frozen-wake loads at
/// the same kinematics (what z null gives), formed in the same pass over the elements: their frames once for both, one
/// sum of the differences, and the elements without states or dynamic inflow (a difference of zero) skipped; not
/// with `totals`. In the AD scalar it takes each element whose states the pass does not seed through its section
/// jet (aero_unsteady_section.hxx: the airfoil and inflow equations evaluated once per element and point). A state of
/// an element enters only that element's loads and rates, so its Jacobian columns come from that element alone
/// (linearize/unsteady_aero.cpp). `totals` (if given) receives the rotor thrust and torque of the loads in e and
/// each blade's resultant force and moment about its body origin (ground components, as addAeroLoads forms them):
/// the load outputs with the states (evaluateOutputs); blades without the element asked for keep zero resultants.
/// `only_blade` ≥ 0 evaluates that blade's elements alone (as `element` one element): the coordinates that move one
/// blade only can then share a derivative direction in linearize/unsteady_aero.cpp.
template <class T>
void addUnsteadyAeroLoads(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& u,
                          const AeroInflow& frozen, const VecXT<T>* z, VecXT<T>& e, VecXT<T>* zdot,
                          std::vector<aero::UaInput<T>>* inputs = nullptr, VecXT<T>* quasi_steady = nullptr,
                          int element = -1, bool minus_quasi_steady = false, RotorTotals<T>* totals = nullptr,
                          int only_blade = -1);

/// The airfoil of a station for the UA functions (the polar, its UA table and Cm rule, the chord).
aero::UaSection uaSection(const AeroModel& am, const AeroStation& st);

}  // namespace whirl

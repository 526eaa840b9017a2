#pragma once
/// \file
/// The state of the blade elements at an operating point: the induced velocities that a frozen-wake
/// linearization holds fixed, and per element what the BEM solution was (for tables and checks).
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// One element at an operating point (annulus frame of aero_model.hpp; per unit span).
struct AeroElementState {
  double vx = 0, vy = 0;      ///< relative velocity without induction, normal / in-plane [m/s]
  double r = 0;               ///< distance from the rotor axis [m]
  double phi = 0, alpha = 0;  ///< inflow angle, angle of attack [rad]
  double a = 0, ap = 0;       ///< axial and tangential induction factors [-]
  double w = 0;               ///< relative speed [m/s]
  double cl = 0, cd = 0, cm = 0;
  double fx = 0, fy = 0, m = 0;  ///< normal and in-plane force [N/m], pitching moment [N m/m]
  bool bem_valid = true;         ///< false: BEM had no valid inflow angle, φ is the geometric one (AeroDyn GeomPhi)
};

/// Induced velocities per element, blades in order, elements root to tip (AeroModel::nstations()):
/// AeroDyn's frozen wake (BEMT `computeFrozenWake`): AxInd = −Vx a, TnInd = Vy a', so that the
/// inflow angle is atan2(Vx + AxInd, Vy + TnInd) whatever the structure does.
struct AeroInflow {
  VecX axial;       ///< AxInd [m/s]
  VecX tangential;  ///< TnInd [m/s]
  bool empty() const { return axial.size() == 0; }
};

/// What a double evaluation of the aerodynamic loads found, element by element.
struct AeroRecord {
  std::vector<AeroElementState> elements;
  double thrust = 0;  ///< Σ of the element forces along the rotor axis (AeroDyn RtAeroFxh) [N]
  double torque = 0;  ///< their moment about the rotor axis through the apex (RtAeroMxh) [N m]
  /// The induced velocities of these elements (the frozen wake of this point).
  AeroInflow inflow() const;
};

}  // namespace whirl

#pragma once
/// \file
/// The aerodynamic states of a linear model (issue 47): the unsteady-airfoil states (AeroDyn UA_Mod 4 or 6)
/// and the dynamic-inflow states (DBEMT_Mod 3, which replace the frozen wake's induction): with z the states
/// of the elements that carry them (src/dynamics/aero_unsteady.hpp) the linearized
/// equations are
///   M δq̈ + (C + ΔC) δq̇ + (K + ΔK) δq = (Q + ΔQ) δu + G δz,
///   δż = Z_q δq + Z_q̇ δq̇ + A_zz δz + Z_u δu,
/// with ΔK = −∂(e_UA − e_QS)/∂q, ΔC = −∂(e_UA − e_QS)/∂q̇, ΔQ = ∂(e_UA − e_QS)/∂u: the UA loads' derivatives
/// at fixed states replace the quasi-steady frozen-wake ones that K, C, Q hold (e_UA, e_QS: the blade
/// loads with and without states, same kinematics and frozen induction), G = ∂e_UA/∂z. Everything by one
/// forward-AD evaluation per chunk of columns; z at its steady value for the point's inputs (aero::hgmSteady;
/// the dynamic inflow's v = v_qs, v1 = (1 − k) v_qs: the BEM induction of the point). With dynamic inflow the
/// rows of v̇ take the quasi-steady induction's derivatives (the converged BEM residual differentiated by the
/// implicit-function theorem), and the loads at fixed states see v (equal to the frozen wake's loads but at
/// the elements with fixed inductions, whose loads follow the BEM induction, as AeroDyn).
#include <vector>

#include "linearize/jacobian.hpp"
#include "linearize/operating_point.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

struct UnsteadyAeroLinear {
  VecX z;                                  ///< the states at the operating point (steady for its inputs), dim nz
  MatX dK, dC;                             ///< ndof × ncol: ΔK, ΔC on the columns asked for, all residual rows
  MatX dQ;                                 ///< ndof × ninput (or × 0 without inputs)
  MatX G;                                  ///< ndof × nz
  MatX Zq, Zqd;                            ///< nz × ncol
  MatX Zu;                                 ///< nz × ninput (or × 0)
  MatX Azz;                                ///< nz × nz
  std::vector<std::string> names, groups;  ///< uaStateNames, then inflowStateNames
};

/// The blocks above at op (its frozen induction: op.inflow), columns `cols` of q and q̇ (model coordinates),
/// the input columns when `inputs`. Requires aerodynamic states (aeroStateCount > 0) and an induction of every element
/// in op.inflow (ComputeError otherwise).
UnsteadyAeroLinear unsteadyAeroLinear(const Model& m, const OperatingPoint& op, const std::vector<int>& cols,
                                      bool inputs);

/// The same with the buffers of a sweep's linearizations (ws: the double evaluations of the steady states, jw.ws:
/// the AD passes), allocated once per model instead of once per call.
UnsteadyAeroLinear unsteadyAeroLinear(const Model& m, const OperatingPoint& op, const std::vector<int>& cols,
                                      bool inputs, Workspace<double>& ws, JacobianWorkspace& jw);

/// The same blocks at op with the states at `states` (dim aeroStateCount) instead of their steady values: the
/// Newton matrix of a time simulation (linearize/simulate_aero.hpp), whose states move away from them.
UnsteadyAeroLinear unsteadyAeroLinearAt(const Model& m, const OperatingPoint& op, const VecX& states,
                                        const std::vector<int>& cols, bool inputs);
UnsteadyAeroLinear unsteadyAeroLinearAt(const Model& m, const OperatingPoint& op, const VecX& states,
                                        const std::vector<int>& cols, bool inputs, Workspace<ADChunk>& ws);

/// The states' steady values at op (what unsteadyAeroLinear linearizes about).
VecX unsteadyAeroSteadyStates(const Model& m, const OperatingPoint& op);
VecX unsteadyAeroSteadyStates(const Model& m, const OperatingPoint& op, Workspace<double>& ws);

}  // namespace whirl

#pragma once
/// \file
/// The blade elements' first-order aerodynamic states in a time simulation (issue 47 item 5): the
/// unsteady-airfoil states (AeroDyn UA_Mod 4 or 6) and the dynamic-inflow states (DBEMT_Mod 3) the linear
/// model carries (linearize/unsteady_aero.hpp), integrated by simulate with the structure. The equations are
/// the linear model's own scalar templates (addUnsteadyAeroLoads, src/dynamics/aero_unsteady.hpp):
///   e = e_structure + e_QS(BEM) − e_QS(frozen at the BEM induction) + e_UA(z),   ż = f(q, q̇, u, z),
/// where residual() gives the first two terms (its loads on the quasi-steady BEM solved at the evaluation),
/// the third cancels them to round-off, and e_UA are the loads with the states: the linearization's
/// ΔK = −∂(e_UA − e_QS)/∂q on the same frozen induction. The induction the elements see is
///  - with dynamic inflow: the states v (their rates driven by the quasi-steady BEM induction, re-solved at
///    every evaluation, as AeroDyn's DBEMT);
///  - without: the quasi-steady BEM induction of the evaluation (AeroDyn solves the BEMT with the static
///    polar, then UA), or held at SimulationOptions::frozen_inflow (the frozen wake of a linear model:
///    `whirl verify`).
/// The states start at their steady values at the start point (aero::hgmSteady; v = v_qs, v1 = (1 − k) v_qs).
#include "linearize/simulate.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// The number of aerodynamic states a simulation of `m` integrates: aeroStateCount(m.aero) with
/// SimulationOptions::aero_states, else 0.
int simulationAeroStateCount(const Model& m, const SimulationOptions& opt);

/// The induced velocities of the elements at (q, q̇, u) from the quasi-steady BEM (a double residual
/// evaluation): what the states' steady values and the first evaluation take.
AeroInflow quasiSteadyInflow(const Model& m, const OperatingPoint& point);

/// The states' initial values: steady at `start` (its motion and inputs), on the induction the simulation
/// takes there (opt.frozen_inflow, or the quasi-steady BEM's). Dim simulationAeroStateCount.
VecX simulationAeroStart(const Model& m, const OperatingPoint& start, const SimulationOptions& opt);

/// The induction the elements see at (q, q̇, q̈, u) in a simulation without dynamic-inflow states driving
/// it: opt.frozen_inflow if given, else the quasi-steady BEM's of a double residual evaluated in ws (its
/// BEM roots start the searches). The load outputs with the states take it (the Recorder, evaluateOutputs),
/// as addAeroStateLoads does for the equations of motion.
AeroInflow simulationElementInflow(const Model& m, Workspace<double>& ws, const VecX& q, const VecX& qd,
                                   const VecX& qdd, const VecX& u, const SimulationOptions& opt);

/// Buffers of one evaluation of the states' loads and rates.
struct AeroStateLoads {
  explicit AeroStateLoads(const Model& m);
  VecX delta;  ///< e_UA − e_QS, dim ndof
  VecX e_qs;   ///< e_QS on the BEM inflow when the elements' inflow is held (else unused), dim ndof
};

/// e += e_UA(z) − e_QS and zdot = f(q, q̇, u, z) at the kinematics already in ws (residual() at q, q̇ just
/// evaluated with `bem`, its quasi-steady induction). `held` (non-empty): the induction the elements see
/// without dynamic inflow, instead of `bem`.
void addAeroStateLoads(const Model& m, Workspace<double>& ws, const VecX& q, const VecX& qd, const VecX& u,
                       const AeroInflow& bem, const AeroInflow& held, const VecX& z, AeroStateLoads& buffers, VecX& e,
                       VecX& zdot);

}  // namespace whirl

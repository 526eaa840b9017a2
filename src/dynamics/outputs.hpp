#pragma once
/// \file
/// The model's outputs y = h(q, q̇, q̈) (src/model/output.hpp), written once for any scalar T and
/// instantiated for double and ADChunk in outputs.cpp, so that C and D come from AD.
#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// Evaluates every output of the model (forward kinematics included when a point output needs it).
/// \param[in]  q, qd, qdd  all coordinates, frozen ones included (dim model.ndof())
/// \param[out] y           outputs (dim model.noutput()), in the units of each Output
/// \param[in]  u           inputs (dim model.ninput()); needed by rotor outputs (wind, generator torque)
/// \param[in]  frozen      induced velocities held (frozen wake) for the aerodynamic rotor outputs
/// \param[in]  pass        an AD pass that reads only derivatives copies unmoved frames (AdPass)
/// \param[in]  z           the aerodynamic states (dim aeroStateCount(model.aero): unsteady-airfoil, then
///                         dynamic-inflow; src/dynamics/aero_unsteady.hpp) or null: with them the load outputs
///                         take the loads the equations of motion take with the states (addUnsteadyAeroLoads,
///                         on the frozen induction, which is then required), without them the quasi-steady
///                         frozen-wake (or BEM) loads of addAeroLoads
/// Throws ComputeError when load outputs lack the inputs, or the states lack the frozen induction.
template <class T>
void evaluateOutputs(const Model& model, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
                     VecXT<T>& y, const VecXT<T>* u = nullptr, const AeroInflow* frozen = nullptr,
                     const AdPass& pass = {}, const VecXT<T>* z = nullptr);

}  // namespace whirl

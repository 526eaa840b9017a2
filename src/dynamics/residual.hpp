#pragma once
/// \file
/// The nonlinear equations of motion as a residual [BranlardGeisler2022, eq. 22]:
///   e(q, q̇, q̈, u) = F(q, q̇, u) − M(q) q̈ = f + f*   (Kane's method [BranlardGeisler2022, eq. 4–21])
/// written once for any scalar T and instantiated for double and ADChunk in residual.cpp.
#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// Evaluates e for every coordinate of the model (frozen ones included; callers drop those rows).
/// \param[in]  q, qd, qdd  coordinates and their rates (dim model.ndof())
/// \param[in]  u           inputs (dim model.ninput())
/// \param[out] e           residual (dim model.ndof()) [N or N m]
/// \param[in]  frozen      aerodynamic induced velocities held fixed (frozen wake, aero_inflow.hpp);
///                         null: the induction is solved at this geometry (BEM)
/// \param[out] record      if not null (double only): the state of every blade element
/// \param[in]  pass        an AD pass that reads only derivatives (AdPass) may leave terms out
/// \return whether every term was evaluated, so that the values of e are complete (always, unless
///         `pass` reads only derivatives)
template <class T>
bool residual(const Model& model, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
              const VecXT<T>& u, VecXT<T>& e, const AeroInflow* frozen = nullptr, AeroRecord* record = nullptr,
              const AdPass& pass = {});

/// Adds the terms of e that inputs scale (point loads and DOF loads, dim model.ndof()) at the
/// kinematics already in ws (forwardKinematics): e += Σ_l u_l g_l(q). The kinematics scalar TK and
/// the input scalar T may differ: ∂e/∂u of a load input (one that drives no coordinate) is an AD pass
/// over this function alone with double kinematics.
/// With a generator torque law (Model::generator) the torque at the generator speed of qd is added to
/// its input.
template <class TK, class T>
void addInputLoads(const Model& model, const Workspace<TK>& ws, const VecXT<TK>& qd, const VecXT<T>& u, VecXT<T>& e);

}  // namespace whirl

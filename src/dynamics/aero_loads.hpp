#pragma once
/// \file
/// Blade-element aerodynamic loads as generalized forces (AeroDyn v15 BEMT with the OpenFAST 3.x
/// "no sweep, pitch and twist" projection), written once for any scalar so that aerodynamic
/// stiffness, damping and the wind and pitch columns of the linear model come from the same AD
/// passes as the structure.
///
/// Per element: position and velocity of its point from the kinematics; wind at that height;
/// relative velocity Vx (along the annulus x_a), Vy (along y_a) — aero_model.hpp for the frames;
/// inflow angle φ (frozen: from the given induced velocities; otherwise the BEM solution of the
/// current geometry, differentiated by the implicit-function theorem); angle of attack
/// α = φ − θ with θ = twist + pitch + elastic twist; polar; force per unit span
/// (Cx q c, −Cy q c, 0) and moment (0, 0, Cm q c²) in the annulus frame, Cx = Cl cos φ + Cd sin φ,
/// Cy = Cl sin φ − Cd cos φ, q = ½ ρ W² (AeroDyn `SetOutputsFromBEMT`), times the element's span
/// weight, applied at the point.
#include <cstdint>
#include <vector>

#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/rotor_totals.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// e += generalized aerodynamic forces (dim model.ndof()) at the kinematics already in ws.
/// \param[in] q       coordinates (dim ndof), for the pitch angles; scalar of the kinematics
/// \param[in] u       inputs (dim ninput), for the wind speed
/// \param[in] frozen  induced velocities to hold fixed (frozen wake); null: solve BEM per element
/// \param[out] record if not null (double evaluations): each element's state
/// ws: the kinematics, and the BEM roots it keeps per element (Workspace::bem) for evaluations at the
/// same inputs.
/// \param[in]  skip   bit b set: leave out blade b (an AD pass in which nothing it depends on is seeded)
/// \param[in,out] jets the section and blade jets of frozen-wake AD passes (null: ws.jets); a pass
///                   that seeds only inputs, on double kinematics, shares those of the AD workspace
/// Throws ComputeError naming the blade and element when BEM has no solution.
template <class TK, class T>
void addAeroLoads(const Model& model, Workspace<TK>& ws, const VecXT<TK>& q, const VecXT<T>& u,
                  const AeroInflow* frozen, AeroRecord* record, VecXT<T>& e, std::uint64_t skip = 0,
                  RotorTotals<T>* totals = nullptr, AeroJets* jets = nullptr);

}  // namespace whirl

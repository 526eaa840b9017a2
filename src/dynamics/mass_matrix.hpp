#pragma once
/// \file
/// Generalized mass matrix assembled in double: M(q) = Σ_b Bᵀ M_b B [Branlard2019, eq. 8], with
/// B = [Rᵀ Jv; Rᵀ Jω; E_b] mapping q̈ to the body-frame accelerations and the body's q̈_e, and M_b
/// the body mass matrix from its shape integrals [Branlard2019, eq. 2; BranlardGeisler2022, eq. A2–A7].
/// Independent of the residual's q̈ path: tests check M = −∂e/∂q̈.
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// Body mass matrix (6 + ne square) at the body's basis state: rows/columns a', α', q̈_e.
MatX bodyMassMatrix(const BodyInertia& inertia, const BasisState<double>& basis);

/// \param[in]  q  all coordinates (dim model.ndof())
/// \param[out] M  ndof × ndof, symmetric
void massMatrix(const Model& model, Workspace<double>& ws, const VecX& q, MatX& M);

/// M at the positions of the kinematics already in ws (forwardKinematics at some q, with any rates:
/// only R, Jv, Jω, c and D are read): what massMatrix gives at that q, without evaluating the
/// kinematics again (a simulation's Newton step asks for M where it has just evaluated the residual).
/// After a double residual at those kinematics, the bodies' shape-integral products it formed
/// (y = S c, cᵀ y, m1 c) are reused too (Workspace::body_products).
/// \param[out] M  ndof × ndof, symmetric
void massMatrixAtKinematics(const Model& model, Workspace<double>& ws, MatX& M);

}  // namespace whirl

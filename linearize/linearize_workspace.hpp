#pragma once
/// \file
/// Buffers of the equilibrium solve and the linearization, reused across the operating points of
/// one model (azimuths, rotor speeds): allocating the AD workspace costs as much as a Jacobian pass.
#include "linearize/jacobian.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

struct LinearizeWorkspace {
  explicit LinearizeWorkspace(const Model& m) : ws(m), jw(m) {}
  Workspace<double> ws;  ///< double kinematics, residual and mass matrix
  JacobianWorkspace jw;  ///< AD passes
};

}  // namespace whirl

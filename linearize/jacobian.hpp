#pragma once
/// \file
/// Exact Jacobians of the residual (and of the outputs) by forward-mode AD in fixed-size chunks
/// (AD performance recipe, docs/dev/architecture.md): seed kChunk directions per pass, evaluate, extract.
///
/// Inputs that drive frozen coordinates (Input::dofs, q_d = value + gain · u) are differentiated
/// through them: the direction of u_i also seeds q_d with gain, so ∂/∂u is the total derivative.
#include <vector>

#include "src/base/scalar.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// The argument a Jacobian is taken with respect to.
/// Z: the aerodynamic states of the outputs (outputJacobian with z only).
enum class Wrt { Q, Qd, Qdd, U, Z };

/// Reusable AD buffers (the AD workspace and AD copies of the arguments).
struct JacobianWorkspace {
  explicit JacobianWorkspace(const Model& m);
  Workspace<ADChunk> ws;
  Workspace<double> kin;        ///< double kinematics at the point (constant frames, load-input columns)
  VecX kin_q, kin_qd, kin_qdd;  ///< the point kin was computed at (empty: not yet)
  VecXT<ADChunk> q, qd, qdd, u, e, y;
  VecXT<ADChunk> z;  ///< the aerodynamic states (outputJacobian with z; dim 0 otherwise)
};

/// ∂e/∂(wrt)[:, cols] for all ndof rows, at (q, qd, qdd, u) (dims as in residual()).
/// Columns of inputs that drive no coordinate (loads) differentiate only the load terms
/// (addInputLoads), with the kinematics in double: e is affine in those inputs.
/// \param[out] value  if given: e at the point (dim ndof) when one of the passes evaluated every term
///                    of the residual (no body skipped), else resized to 0 (evaluate it in double).
/// \param[in]  frozen aerodynamic induced velocities held fixed (frozen wake); null: the induction
///                    responds (quasi-steady BEM, src/dynamics/aero_loads.hpp)
MatX residualJacobian(const Model& model, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd,
                      const VecX& u, Wrt wrt, const std::vector<int>& cols, VecX* value = nullptr,
                      const AeroInflow* frozen = nullptr);

/// ∂y/∂(wrt)[:, cols] for all noutput rows (y = evaluateOutputs, src/dynamics/outputs.hpp).
/// `frozen`: the induced velocities the aerodynamic rotor outputs hold (frozen wake), as for residualJacobian.
/// `z` (if given, dim aeroStateCount; requires `frozen`): the aerodynamic states, whose loads the load outputs
/// take (evaluateOutputs); Wrt::Z differentiates with respect to them (cols: indices into z).
MatX outputJacobian(const Model& model, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd,
                    const VecX& u, Wrt wrt, const std::vector<int>& cols, const AeroInflow* frozen = nullptr,
                    const VecX* z = nullptr);

}  // namespace whirl

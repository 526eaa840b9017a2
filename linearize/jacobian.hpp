#pragma once
/// \file
/// Exact Jacobians of the residual by forward-mode AD in fixed-size chunks (GUIDE §3): seed kChunk
/// directions per pass, evaluate, extract.
#include <vector>

#include "src/dynamics/scalar.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// The argument a Jacobian is taken with respect to.
enum class Wrt { Q, Qd, Qdd, U };

/// Reusable AD buffers (the AD workspace and AD copies of the arguments).
struct JacobianWorkspace {
  explicit JacobianWorkspace(const Model& m);
  Workspace<ADChunk> ws;
  VecXT<ADChunk> q, qd, qdd, u, e;
};

/// ∂e/∂(wrt)[:, cols] for all ndof rows, at (q, qd, qdd, u) (dims as in residual()).
MatX residualJacobian(const Model& model, JacobianWorkspace& jw, const VecX& q, const VecX& qd, const VecX& qdd,
                      const VecX& u, Wrt wrt, const std::vector<int>& cols);

}  // namespace whirl

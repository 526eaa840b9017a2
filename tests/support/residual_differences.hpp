#pragma once
// Central differences of the residual e(q, q̇, q̈, u) with respect to one argument: the independent
// path the AD Jacobians are checked against (test_aero_loads.cpp, test_fe_blade_aero.cpp).
#include <vector>

#include "linearize/jacobian.hpp"
#include "linearize/operating_point.hpp"
#include "src/dynamics/residual.hpp"

namespace whirl::test {

/// ∂e/∂x for x = q, q̇ or u (`wrt`), the columns `cols` of x, step h on each side; the residual is
/// evaluated with `frozen` (the frozen-wake induction; null: solved). An input moves the coordinates it
/// drives with it (InputDofTarget), as the linearization's B does. Dimension ndof × cols.size().
inline MatX centralDifferences(const Model& m, const OperatingPoint& op, Wrt wrt, const std::vector<int>& cols,
                               const AeroInflow* frozen, double h = 1e-6) {
  Workspace<double> ws(m);
  MatX J(m.ndof(), cols.size());
  VecX ep(m.ndof()), em(m.ndof());
  for (std::size_t c = 0; c < cols.size(); ++c) {
    auto eval = [&](double step, VecX& e) {
      OperatingPoint p = op;
      VecX& x = wrt == Wrt::Q ? p.q : wrt == Wrt::Qd ? p.qd : p.u;
      x(cols[c]) += step;
      if (wrt == Wrt::U)
        for (const InputDofTarget& t : m.inputs[cols[c]].dofs) p.q(t.dof) += t.gain * step;
      residual(m, ws, p.q, p.qd, p.qdd, p.u, e, frozen);
    };
    eval(h, ep);
    eval(-h, em);
    J.col(static_cast<Eigen::Index>(c)) = (ep - em) / (2 * h);
  }
  return J;
}

}  // namespace whirl::test

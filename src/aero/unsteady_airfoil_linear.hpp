#pragma once
/// \file
/// The HGM model (unsteady_airfoil.hpp) linearized at one element's operating point, in the section's own
/// inputs: δẋ = A δx + B δu, δ[Cl, Cd, Cm] = C δx + D δu, x = [x1, x2, x3, x4], u = [α34, U, ω]. The
/// building block of the element's rows and columns in a turbine's linear model: the structure enters
/// through ∂u/∂(q, q̇) of the element and the loads through ∂e/∂[Cl, Cd, Cm]. Derivatives by forward AD
/// (one ADChunk pass over the 7 variables).
#include <Eigen/Core>

#include "src/aero/unsteady_airfoil.hpp"

namespace whirl::aero {

struct UaElementLinear {
  Eigen::Matrix4d A;              ///< ∂ẋ/∂x [1/s]
  Eigen::Matrix<double, 4, 3> B;  ///< ∂ẋ/∂[α34 (rad), U (m/s), ω (rad/s)]
  Eigen::Matrix<double, 3, 4> C;  ///< ∂[Cl, Cd, Cm]/∂x
  Eigen::Matrix<double, 3, 3> D;  ///< ∂[Cl, Cd, Cm]/∂[α34, U, ω] at fixed states
  /// The static (s → 0) gain D − C A⁻¹ B: the loads' response to slow changes of the inputs, the
  /// quasi-steady derivative of the model's steady loads (UA_Mod 4: A is Hurwitz, all its time constants
  /// positive; UA_Mod 6 leaves x1..x3 out and A singular: use its x4 row and column alone).
  Eigen::Matrix<double, 3, 3> staticGain() const;
};

/// The linear model at states x and inputs in (the cut-out blending input α_ac is held at in.alpha_ac).
UaElementLinear uaElementLinear(const UaSection& s, const HgmState<double>& x, const UaInput<double>& in);

}  // namespace whirl::aero

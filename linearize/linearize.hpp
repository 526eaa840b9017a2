#pragma once
/// \file
/// Linearization at an operating point [BranlardGeisler2022, eq. 25–26]:
///   M δq̈ + C δq̇ + K δq = Q δu,  M = −∂e/∂q̈, C = −∂e/∂q̇, K = −∂e/∂q, Q = ∂e/∂u,
/// on the active (non-frozen) coordinates; C, K, Q by chunked forward AD, M from the double
/// assembly. State space x = [δq; δq̇]: A = [[0, I], [−M⁻¹K, −M⁻¹C]], B = [[0], [M⁻¹Q]] (solved
/// with an LDLᵀ factorization of M, never inverted; ComputeError if M is not positive definite).
/// First-order states z on free joints (Model::body_states, ż = A_z z + B_z q̇, loads C_z z) follow:
/// x = [δq; δq̇; z], A = [[0, I, 0], [−M⁻¹K, −M⁻¹C, M⁻¹G], [0, B_z P, A_z]], G = Pᵀ C_z, P picking the
/// joint's six coordinates among the active ones; they rest at z = 0 at a static point.
/// With LinearizeOptions::unsteady_aero the blade elements' unsteady-airfoil and dynamic-inflow states follow
/// them (linearize/unsteady_aero.hpp): their loads replace the quasi-steady ones in K, C, Q, and their rows are
/// [Z_q, Z_q̇, A_zz] (B: Z_u), at their steady values for the point's inputs.
#include <string>
#include <vector>

#include "linearize/linearize_workspace.hpp"
#include "linearize/operating_point.hpp"

namespace whirl {

struct LinearModel {
  std::vector<int> dofs;                        ///< model coordinates of the states, in order
  std::vector<std::string> dof_names;           ///< dim n
  std::vector<std::string> input_names;         ///< dim nu
  MatX M, C, K;                                 ///< n × n
  MatX Q;                                       ///< n × nu
  MatX A;                                       ///< (2n + nz) × (2n + nz): states [δq; δq̇; z]
  MatX B;                                       ///< (2n + nz) × nu
  std::vector<std::string> first_order_names;   ///< states z (dim nz), e.g. "HydroDyn radiation surge 3"
  std::vector<std::string> first_order_groups;  ///< what each z belongs to, e.g. "HydroDyn radiation surge"
  VecX residual;                                ///< e at the operating point on the active coordinates (dim n)
  VecX first_order_values;              ///< z at the operating point (dim nz: 0 for body states, steady aero states)
  std::vector<int> first_order_blades;  ///< blade (0-based) of each z, −1 in the fixed frame (body states)
};

struct LinearizeOptions {
  /// Aerodynamics: hold the induced velocities of the operating point fixed (AeroDyn's frozen wake, as
  /// OpenFAST linearizes) or let the induction follow each perturbation at once (quasi-steady BEM:
  /// its derivative by the implicit-function theorem). No effect without aerodynamics.
  bool frozen_wake = true;
  /// The input columns Q and B (one more AD pass or two); an eigenanalysis needs only M, C, K and A,
  /// and leaves them out (Q and B are then n × 0 and 2n × 0).
  bool inputs = true;
  /// Unsteady airfoil aerodynamics as first-order states (a deck's UA_Mod 4 or 6, on the frozen wake): the
  /// elements' states in the model instead of the quasi-steady polar (linearize/unsteady_aero.hpp). On by
  /// default, so a model has the states its deck asks for (issue 47); false: the quasi-steady polar. No
  /// effect without UA data, or with frozen_wake = false. The same switch adds a deck's dynamic-inflow states
  /// (DBEMT_Mod 3: the elements see the states' induction instead of the frozen wake's).
  bool unsteady_aero = true;
};

LinearModel linearize(const Model& model, const OperatingPoint& op, LinearizeWorkspace& lw,
                      const LinearizeOptions& opt = {});
/// Same, with buffers of its own.
LinearModel linearize(const Model& model, const OperatingPoint& op, const LinearizeOptions& opt = {});

}  // namespace whirl

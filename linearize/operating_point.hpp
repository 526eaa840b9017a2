#pragma once
/// \file
/// Operating point: rates of the rotating coordinates, inputs and frozen coordinates are given;
/// unrestrained coordinates (a free yaw: linearize/unrestrained.hpp) are held at their given value;
/// the other active coordinates are solved for static/steady equilibrium e(q, q̇, 0, u) = 0 by
/// Newton with the AD stiffness K = −∂e/∂q.
#include <string>
#include <vector>

#include "linearize/linearize_workspace.hpp"
#include "linearize/load_jump.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/model/model.hpp"
#include "src/model/operating_condition.hpp"

namespace whirl {

struct LinearModel;

struct OperatingPoint {
  VecX q, qd, qdd, u;       ///< all coordinates (ndof) and inputs (ninput)
  std::vector<int> solved;  ///< coordinates solved for equilibrium
  /// Unrestrained coordinates (no stiffness along them: a free yaw) held at their given value; the
  /// load along them stays in the residual (residual_max_active) and moves them in the linear model.
  std::vector<int> held;
  VecX held_load;  ///< e on each held coordinate at the solution, in the order of `held` [N, N m]
  int iterations = 0;
  double residual_norm = 0;        ///< ‖e‖ over the solved coordinates at the solution [N, N m]
  double load_scale = 1;           ///< what the tolerance was relative to [N, N m]
  double residual_max_active = 0;  ///< max |e| over all active coordinates (rotating ones included)
  std::string residual_max_dof;    ///< where that maximum sits
  /// Aerodynamics: every blade element at the solution (induction solved on the deflected geometry) and
  /// its induced velocities, which a frozen-wake linearization holds fixed. Empty without aerodynamics.
  AeroRecord aero;
  AeroInflow inflow;
  VecX e;  ///< the residual at the solution, every coordinate (dim ndof; rotating and held ones too) [N, N m]
  /// Set (dof ≥ 0) when the equilibrium lies on a jump of the loads (linearize/load_jump.hpp): Newton
  /// stepped back and forth across it, and the point is the side with the smaller residual, which is
  /// then at most the jump's size.
  LoadJump load_jump;
};

struct EquilibriumOptions {
  int max_iterations = 50;
  double tolerance = 1e-10;  ///< on ‖e_solved‖ relative to the generalized gravity/centrifugal load scale
  /// A linearization at a nearby point (the previous azimuth of a periodic sweep): its K is used
  /// as the Newton matrix (chord iterations, no Jacobian) while the residual falls at least 4× per
  /// step; full Newton takes over otherwise. Must outlive the call.
  const LinearModel* chord = nullptr;
  /// As `chord`, the Newton matrix itself: K on the solved coordinates in their order (a solve of the
  /// same model at a nearby condition, `newton_matrix`). Used when `chord` is null. Must outlive the call.
  const MatX* chord_matrix = nullptr;
  /// If not null: receives the last Newton matrix (K on the solved coordinates) — after chord steps
  /// only, the chord matrix with their Broyden updates; untouched when the solve took no step.
  MatX* newton_matrix = nullptr;
  /// The tolerance's reference [N, N m]; 0: max(1, ‖e_solved‖∞ at the start). A warm start (a
  /// neighbouring point's equilibrium) passes the scale of the cold start it continues.
  double load_scale = 0;
  /// With load_scale 0: the point whose residual sets the reference instead of the start's — the cold
  /// start (initialPoint) that a warm start from a neighbouring condition stands in for, so that the
  /// tolerance is the cold start's. Must outlive the call.
  const OperatingPoint* scale_from = nullptr;
  /// The unrestrained coordinates, decided by an earlier solve of the same model at a neighbouring
  /// point (OperatingPoint::held of a periodic sweep's first azimuth), so that every azimuth holds
  /// the same ones and the decision (one structural Jacobian) is made once. Null: decided here
  /// (unrestrainedCoordinates at the start). Must outlive the call.
  const std::vector<int>* held = nullptr;
};

/// Starting point from the model: each coordinate at its value, each rate at its rate, q̈ = 0,
/// inputs at their values; a frozen coordinate driven by inputs at value + Σ gain · u.
OperatingPoint initialPoint(const Model& model);

/// Starting point of the model at an operating condition (src/model/operating_condition.hpp),
/// through the model's roles (ModelRoles): the model's initial point with
/// - the wind-speed and generator-torque inputs at the condition's values (before the inputs move
///   the frozen coordinates they drive),
/// - every rotating coordinate at the rotor speed (its rate) and, if given, at the azimuth,
/// - each blade's pitch coordinate at the collective pitch plus the blade's offset,
/// - the yaw coordinate at the yaw.
/// The model itself is not changed: one model serves every operating point.
/// \throws InputError naming the field the model cannot honour (e.g. "wind_speed: the model has no
/// wind-speed input"), or a value that is not finite.
OperatingPoint initialPoint(const Model& model, const OperatingCondition& condition);

/// Sets the deflections of `q` to those of `from` (both model.ndof()): the active coordinates that do not
/// rotate; the azimuth and the frozen coordinates stay. The warm start of an equilibrium from a
/// neighbouring one (another wind speed, rotor speed or pitch).
void copyDeflections(const Model& model, const VecX& from, VecX& q);

/// Solves the equilibrium of the non-rotating active coordinates starting from `start`; the
/// unrestrained ones (unrestrainedCoordinates, or EquilibriumOptions::held) stay at their start value.
/// Newton stepping back and forth between two points across a jump of the loads, with zero between
/// the two sides' residuals and a jump below kMaxLoadJump of the load scale, ends there: the side with
/// the smaller residual (OperatingPoint::load_jump).
/// Throws ComputeError when K is singular or Newton does not converge, or when a load acts on a held
/// coordinate at a time-invariant point (every rate 0: nothing turns, so nothing averages the load
/// out — a body falling along a free prismatic joint); when a joint coordinate is (nearly) without
/// stiffness the message names it, the load on it and how to hold it. (At rotor speed the load on a
/// held coordinate is periodic; linearizePeriodic checks its mean.)
OperatingPoint solveOperatingPoint(const Model& model, const OperatingPoint& start, const EquilibriumOptions& opt = {});
/// Same, with reused buffers.
OperatingPoint solveOperatingPoint(const Model& model, const OperatingPoint& start, const EquilibriumOptions& opt,
                                   LinearizeWorkspace& lw);
/// The equilibrium at an operating condition: solveOperatingPoint(model, initialPoint(model, condition), opt).
OperatingPoint solveOperatingPoint(const Model& model, const OperatingCondition& condition,
                                   const EquilibriumOptions& opt = {});

}  // namespace whirl

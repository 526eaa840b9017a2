#pragma once
/// \file
/// Where a turbine operates: rotor speed, azimuth, blade pitch, wind speed, generator torque, yaw.
/// A plain value, separate from the Model: the model is built once (and never changed afterwards);
/// each operating point of a sweep is a model plus a condition, turned into the starting point of
/// the equilibrium solve by initialPoint(model, condition) (linearize/operating_point.hpp) through
/// the roles the model gives its coordinates and inputs (ModelRoles, src/model/model.hpp).
///
/// Every field but the rotor speed is optional: absent, the model's own value stays (its DOF value
/// or input value). A field the model cannot honour — a wind speed without a wind-speed input, a
/// pitch without blade pitch coordinates, a yaw without a yaw coordinate, a rotor speed other than
/// 0 without a rotating coordinate — is an InputError naming the field.
#include <optional>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

struct Model;

struct OperatingCondition {
  /// Rotor speed [rad/s]: the rate of every rotating coordinate (ModelRoles::azimuth). Must be 0
  /// for a model without a rotating coordinate.
  double rotor_speed = 0.0;
  /// Rotor azimuth [rad]: the value of the rotating coordinates (in the model's convention, e.g.
  /// ElastoDyn's generator azimuth, 0 = blade 1 up); absent: the model's value. A periodic
  /// linearization starts its revolution here.
  std::optional<double> azimuth;
  /// Collective blade pitch [rad]: the angle of every blade's pitch coordinate
  /// (ModelRoles::blade_pitch), positive to feather as ElastoDyn's BlPitch; absent: each blade keeps
  /// the model's pitch (its coordinate's value plus what its pitch inputs add).
  std::optional<double> collective_pitch;
  /// Per-blade pitch offsets [rad], added to the collective pitch (or to the model's pitch of that
  /// blade); empty = none, otherwise one value per blade.
  std::vector<double> blade_pitch_offsets;
  /// Hub-height wind speed [m/s]: the operating value of the model's wind-speed input
  /// (ModelRoles::wind_speed_input).
  std::optional<double> wind_speed;
  /// Generator torque [N m, high-speed shaft]: the operating value of the model's generator-torque
  /// input (ModelRoles::generator_torque_input).
  std::optional<double> generator_torque;
  /// Nacelle yaw [rad]: the value of the model's yaw coordinate (ModelRoles::yaw_dof); for a free
  /// yaw the starting guess of the equilibrium, for a frozen one its value.
  std::optional<double> yaw;
};

/// The model's own condition: the rate of its first rotating coordinate as the rotor speed (0
/// without one), every optional field absent. initialPoint(model, modelCondition(model)) equals
/// initialPoint(model) for a model whose rotating coordinates share one rate.
OperatingCondition modelCondition(const Model& model);

/// Rotor speed [rad/s] of `rpm` revolutions per minute (rpm · 2π / 60, the conversion every
/// command uses, so that equal rpm give equal bits).
double rpmToRadPerSec(double rpm);

/// One operating point of a sweep: the condition the model is put at, with the values as the user
/// gave them (reported in tables and files as given, not converted back from SI units).
/// A schedule's wind speed and pitch label the point and reach the model through sweepCondition
/// where the model has the role (a wind-speed input, blade pitch coordinates); a model without
/// them ignores them, as whirl always has. Fields set in `condition` itself are strict: a model
/// that cannot honour one stops with an InputError naming it (initialPoint, linearize/operating_point.hpp).
struct SweepPoint {
  double rpm = 0;                    ///< rotor speed as given [rpm]
  std::optional<double> wind_speed;  ///< wind speed as given [m/s] (a schedule's)
  std::optional<double> pitch_deg;   ///< collective pitch as given [deg] (a schedule's)
  OperatingCondition condition;      ///< rotor speed [rad/s], and whatever else is set explicitly
  /// A trimmed point's equilibrium at azimuth 0 (all coordinates, dim ndof): where the point's first
  /// equilibrium starts. Empty: from the undeflected turbine.
  VecX deflections;
};

/// The point at `rpm` [rpm] (condition.rotor_speed = rpmToRadPerSec(rpm)) with a schedule's
/// optional wind speed [m/s] and collective pitch [deg].
SweepPoint sweepPoint(double rpm, std::optional<double> wind_speed = std::nullopt,
                      std::optional<double> pitch_deg = std::nullopt);

}  // namespace whirl

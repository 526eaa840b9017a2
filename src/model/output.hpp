#pragma once
/// \file
/// Outputs of a model: named measured quantities y = h(q, q̇, q̈) for state-space export (y = C x + D u).
/// Plain data inside the Model (indices are renumbered by finalize()); evaluated by
/// evaluateOutputs() (src/dynamics/outputs.hpp) and differentiated by AD (linearize/state_space.hpp).
///
/// Five kinds, the first three at a derivative order (0 value, 1 rate, 2 acceleration):
/// - DofCombination: Σ_k gain_k q_k^(order), e.g. a DOF value/rate/acceleration (one term), the
///   rotor speed (generator azimuth + drivetrain rates), the generator speed (gear ratio × rate), or
///   an elastic bending moment EI·Σ φ''(x) q (gains from the shapes' curvature, see beamMomentGains).
/// - Point: position, velocity or acceleration of a body point (body origin when point = −1), ground
///   (inertial) motion, projected on `direction` given in the axes of `frame_body` (−1 = ground):
///   y = direction · R_Fᵀ p^(order). With frame_body = the carrying body this is what a body-fixed
///   sensor (an IMU without gravity) measures along one axis.
/// - Angular: ground (inertial) angular velocity (order 1) or acceleration (order 2) of a body's frame,
///   y = direction · R_Fᵀ ω^(order−1), projected as a Point output: what a body-fixed gyroscope measures
///   with frame_body = the body, or ElastoDyn's inertial-frame PtfmRVxi … with frame_body = −1.
/// - Rotor: a rotor-level quantity (RotorQuantity: aerodynamic thrust, torque and power, generator
///   torque and power), functions of q, q̇ and u through the blade elements and the torque law.
/// - SubtreeLoadMoment: the moment about `body`'s origin of the loads on it and on every body it carries
///   (inertia −∫ a dm, gravity, the quasi-steady blade-element loads, point loads), projected as a Point
///   output: what the cut at the body's joint transmits to its parent, as ElastoDyn sums its blade-root
///   and tower-base moments (`MomH0B`) from the loads instead of from the curvature of its shapes.
#include <string>
#include <utility>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

enum class OutputKind { DofCombination, Point, Rotor, Angular, SubtreeLoadMoment };

/// Rotor-level quantities (OutputKind::Rotor), from the aerodynamic model and the generator torque law.
enum class RotorQuantity {
  AeroThrust,       ///< Σ of the blade-element forces along the rotor axis [N] (AeroDyn RtAeroFxh)
  AeroTorque,       ///< their moment about the rotor axis [N m] (RtAeroMxh)
  AeroPower,        ///< aerodynamic torque × rotor angular velocity about the axis [W] (RtAeroPwr)
  GeneratorTorque,  ///< torque law at the generator speed + generator-torque input [N m, HSS] (GenTq)
  GeneratorPower,   ///< generator torque × generator speed × efficiency [W] (GenPwr)
};

struct Output {
  std::string name;
  std::string unit;  ///< e.g. "rad/s", "m/s^2", "N m" (for exports)
  OutputKind kind = OutputKind::DofCombination;
  int order = 0;                              ///< 0 = value, 1 = rate, 2 = acceleration (Angular: 1 or 2)
  std::vector<std::pair<int, double>> terms;  ///< DofCombination: (DOF, gain)
  int body =
      -1;  ///< Point, Angular, SubtreeLoadMoment: the body carrying the point, whose frame turns, or whose subtree
  int point = -1;                  ///< Point: point index of `body`, −1 = body origin
  int frame_body = -1;             ///< Point, Angular, SubtreeLoadMoment: axes of `direction`, −1 = ground
  Vec3 direction = Vec3::UnitX();  ///< Point, Angular, SubtreeLoadMoment: unit vector in those axes
  RotorQuantity rotor_quantity = RotorQuantity::AeroThrust;  ///< Rotor: which
  /// Rotor blade (0-based) of an output in the rotating frame, −1 = fixed frame (MBC, `.lin` flag).
  /// finalize() sets it for a DofCombination whose DOFs all belong to one blade, when left at −1.
  int blade = -1;
};

/// An output of OutputKind::Rotor.
inline Output rotorOutput(const std::string& name, const std::string& unit, RotorQuantity quantity) {
  Output o;
  o.name = name;
  o.unit = unit;
  o.kind = OutputKind::Rotor;
  o.rotor_quantity = quantity;
  return o;
}

/// The outputs every aerodynamic model adds: AeroDyn's rotor channels RtAeroFxh, RtAeroMxh, RtAeroPwr (SI).
inline std::vector<Output> aeroRotorOutputs() {
  return {rotorOutput("RtAeroFxh", "N", RotorQuantity::AeroThrust),
          rotorOutput("RtAeroMxh", "N m", RotorQuantity::AeroTorque),
          rotorOutput("RtAeroPwr", "W", RotorQuantity::AeroPower)};
}

/// The outputs a generator torque law adds: ServoDyn's GenTq and GenPwr (SI).
inline std::vector<Output> generatorOutputs() {
  return {rotorOutput("GenTq", "N m", RotorQuantity::GeneratorTorque),
          rotorOutput("GenPwr", "W", RotorQuantity::GeneratorPower)};
}

}  // namespace whirl

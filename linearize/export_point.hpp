#pragma once
/// \file
/// The state-space models `whirl export` writes for one operating point: a periodic linearization
/// at N azimuths when the model has a rotating coordinate (the per-azimuth models, rotating frame)
/// and their multiblade average (≥ 3 blades), or the single model of a time-invariant system.
#include <optional>
#include <string>
#include <vector>

#include "linearize/state_space.hpp"

namespace whirl {

/// One operating point of an export.
struct ExportPoint {
  double rpm = 0.0;
  std::optional<double> wind_speed;       ///< m/s (from a schedule)
  std::optional<double> pitch_deg;        ///< collective pitch (from a schedule)
  StateSpaceModel model;                  ///< time invariant: the multiblade average, or the only model
  std::vector<StateSpaceModel> azimuths;  ///< per azimuth, rotating frame (periodic linearization); may be empty
  OperatingPoint equilibrium;             ///< the solved operating point (first azimuth)
};

struct StateSpaceExport {
  std::string source;  ///< case file
  std::string model_name;
  std::vector<ExportPoint> points;
};

struct ExportOptions {
  int azimuths = 36;                  ///< per revolution (rotating models)
  std::vector<std::string> inputs;    ///< keep these, in this order (empty = all)
  std::vector<std::string> outputs;   ///< keep these, in this order (empty = all)
  bool drop_azimuth = false;          ///< remove the azimuth displacement state (dropAzimuth)
  const VecX* deflections = nullptr;  ///< a trim's equilibrium to start from (PeriodicOptions::deflections)
  /// AeroDyn's frozen wake (the induction held in the perturbation), as OpenFAST linearizes; false: the
  /// induction follows at once (quasi-steady BEM, what a time simulation's BEM does).
  bool frozen_wake = true;
};

/// Solves the operating point of `model` from `start` (rates, pitch and inputs as set in the model) and
/// builds its state-space models. Rotor speed, wind speed and pitch are copied into the result as given.
/// \throws InputError for unknown input/output names or selections that break the multiblade sets.
ExportPoint exportOperatingPoint(const Model& model, const OperatingPoint& start, const ExportOptions& opt);
/// The same from the model's starting point at an operating condition (initialPoint(model, condition)).
ExportPoint exportOperatingPoint(const Model& model, const OperatingCondition& condition, const ExportOptions& opt);

}  // namespace whirl

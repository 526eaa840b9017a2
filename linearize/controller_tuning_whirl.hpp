#pragma once
/// \file
/// The one-state rotor model's sensitivities from whirl's own turbine (linearize/controller_tuning.hpp):
/// at each wind speed the trimmed operating point (linearize/trim.hpp), linearized at the azimuths of
/// one blade passage with the generator torque as a plain input (its torque law left out, so that the
/// rotor's damping is the aerodynamics' alone), and averaged over them:
///   ∂Q/∂β = Q[azimuth, collective pitch],  ∂Q/∂Ω = −C[azimuth, azimuth],  J = M[azimuth, azimuth],
/// the exact derivatives of the aeroelastic equations at the deflected equilibrium (frozen wake by
/// default, as OpenFAST linearizes; quasi-steady induction on request) instead of differences of a
/// tabulated Cp surface.
#include <vector>

#include "linearize/controller_tuning.hpp"
#include "linearize/trim.hpp"
#include "src/model/model.hpp"

namespace whirl {

struct WhirlTuningOptions {
  bool frozen_wake = true;  ///< AeroDyn's frozen wake (false: induction follows at once, quasi-steady BEM)
  TrimOptions trim;         ///< of the trimmed points; its `azimuths` also those of the linearization
};

/// One point per trimmed state; `above_rated` is the trim's. \throws InputError for a model without
/// a rotating coordinate, collective pitch input or generator-torque input; ComputeError from the trim.
std::vector<TuningPoint> whirlTuningSchedule(const Model& model, const std::vector<SteadyState>& trimmed,
                                             const WhirlTuningOptions& opt = {});

/// The rotor's inertia about the rotating coordinate, M[azimuth, azimuth] at rest [kg m²] (rotor and
/// generator referred to the low-speed shaft, when the coordinate is the low-speed azimuth).
double rotorInertia(const Model& model);

/// Generator speed per unit rotor speed: the gain of the model's "GenSpeed" output (or the torque law's
/// speed output) on the rotating coordinate. \throws InputError when there is none.
double gearboxRatio(const Model& model);

}  // namespace whirl

#pragma once
/// \file
/// Periodic operating point of a rotor at constant speed: the azimuth is stepped over one
/// revolution; at each azimuth the other active coordinates are solved for equilibrium under
/// gravity and centrifugal loads (warm-started from the previous azimuth) and the model is
/// linearized there. These per-azimuth models feed the multiblade transform (linearize/mbc.hpp).
/// A parked rotor (zero rotor speed) is linearized at its own azimuth only: it is time invariant
/// there, and the multiblade transform of that one model is exact.
#include <vector>

#include "linearize/linearize.hpp"

namespace whirl {

struct PeriodicOptions {
  int azimuths = 36;           ///< number of equally spaced azimuths over 2π
  int azimuth_dof = -1;        ///< the coordinate stepped; −1 = the first rotating coordinate
  LinearizeOptions linearize;  ///< of each azimuth's linearization
  /// If not null (dim ndof): the first azimuth's equilibrium starts from these values of the
  /// non-rotating coordinates (a trim's equilibrium), its tolerance still that of `start`.
  const VecX* deflections = nullptr;
};

struct PeriodicLinearization {
  int azimuth_dof = -1;
  double rotor_speed = 0;        ///< rad/s, the rate of the azimuth coordinate
  std::vector<double> azimuths;  ///< rad
  std::vector<OperatingPoint> points;
  std::vector<LinearModel> models;
};

/// The first rotating coordinate of the model, or −1.
int findAzimuthDof(const Model& model);

/// Throws InputError when the model has no rotating coordinate or azimuths < 1.
PeriodicLinearization linearizePeriodic(const Model& model, const OperatingPoint& start, const PeriodicOptions& opt);
/// The same from the model's starting point at an operating condition (initialPoint(model, condition)):
/// the revolution at the condition's rotor speed, from its azimuth (or the model's).
PeriodicLinearization linearizePeriodic(const Model& model, const OperatingCondition& condition,
                                        const PeriodicOptions& opt);

}  // namespace whirl

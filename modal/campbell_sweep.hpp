#pragma once
/// \file
/// Campbell sweep: for each operating point (rotor speed, optionally wind speed and collective
/// pitch) the periodic operating point is solved and linearized at N azimuths, transformed to
/// multiblade coordinates and analysed (modal/rotor_modes.hpp). The loop over the points is the
/// shared sweep of linearize/sweep.hpp (SweepPoint, SweepOptions, rpmRange are declared there).
#include "linearize/operating_point.hpp"
#include "linearize/sweep.hpp"
#include "modal/campbell.hpp"
#include "src/model/model.hpp"

namespace whirl {

/// Modes at one operating point from its starting point `start` (the model at the point's
/// condition), sorted by frequency; rpm, wind speed and pitch copied from `point` as given.
CampbellPoint campbellPoint(const Model& model, const SweepPoint& point, const OperatingPoint& start,
                            const SweepOptions& opt);

/// Modes at one operating point, from initialPoint(model, sweepCondition(model, point)). Depends on
/// the point only (each point starts from the model's initial point, not from a neighbour's
/// equilibrium), so points can be computed in any order, on any rank, with the same bits.
CampbellPoint campbellPoint(const Model& model, const SweepPoint& point, const SweepOptions& opt);

/// Modes at every point (lines not yet tracked): sweepOperatingPoints over campbellPoint. Under
/// mpirun the points are spread over the ranks and gathered in order on rank 0; other ranks get an
/// empty vector. The result on rank 0 is identical, bit for bit, to a run on one rank.
std::vector<CampbellPoint> campbellSweep(const Model& model, const std::vector<SweepPoint>& points,
                                         const SweepOptions& opt);

/// The same for one model per parameter set: `model_of(set)` for set = 0 … sets − 1, every set at
/// every point; result k = (set k / P, point k mod P).
std::vector<CampbellPoint> campbellSweep(int sets, const std::function<const Model&(int)>& model_of,
                                         const std::vector<SweepPoint>& points, const SweepOptions& opt);

}  // namespace whirl

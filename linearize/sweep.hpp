#pragma once
/// \file
/// Sweeps over operating points — the one loop behind `whirl campbell`, `whirl export` and
/// `whirl study`. A sweep is a built model (or one model per parameter set) and a list of
/// operating points; at each point the model's starting point comes from the point's operating
/// condition (initialPoint(model, condition), linearize/operating_point.hpp) — the model itself is
/// never copied or changed — and a caller's function turns it into a result (a Campbell point, an
/// exported state-space model). Tasks are spread over MPI ranks (src/parallel/parallel_map.hpp):
/// each depends on its own point only, so K ranks give the bits of one process.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linearize/operating_point.hpp"
#include "src/base/error.hpp"
#include "src/model/model.hpp"
#include "src/model/operating_condition.hpp"
#include "src/parallel/parallel_map.hpp"

namespace whirl {

/// Values START:STEP:STOP, STOP included within round-off, or one value V (V:1:V); InputError naming
/// `option` on a bad range.
std::vector<double> parseRange(const std::string& spec, const std::string& option);

/// Points START:STEP:STOP (rpm), STOP included within round-off. InputError on a bad range.
std::vector<SweepPoint> rpmRange(const std::string& spec);

struct SweepOptions {
  int azimuths = 36;  ///< per revolution, for the periodic linearization of a rotating model
  /// Unsteady-airfoil states in each linearization when the model has them (LinearizeOptions::unsteady_aero).
  bool unsteady_aero = true;
  /// Called after each point with (points done, points total); used for progress on stderr.
  /// Under mpirun: rank 0 only, counting its own share of the points.
  std::function<void(int, int)> progress;
  /// An InputError or ComputeError at point p (its start or its computation, not the model's
  /// construction) is re-thrown with "<context(p)>(<sweepPointLabel>): " in front of its message;
  /// without a context, "operating point <p+1> ". Every failing point names its rotor speed, wind
  /// speed, pitch and azimuth (issue 41).
  std::function<std::string(int)> context;
  /// Called with each point's model and solved periodic operating points (the validity check of the
  /// commands, linearize/point_validity.hpp); returns the problems to keep in the point's metadata,
  /// or throws to stop the sweep.
  std::function<std::vector<std::string>(const Model&, const std::vector<OperatingPoint>&, const SweepPoint&)>
      check_point;
};

/// The condition `model` is put at for `point`: point.condition, plus (where the condition does not
/// set them) point.wind_speed as the wind speed when the model has a wind-speed input
/// (ModelRoles::wind_speed_input) and point.pitch_deg · π / 180 as the collective pitch when it has
/// blade pitch coordinates (ModelRoles::blade_pitch).
OperatingCondition sweepCondition(const Model& model, const SweepPoint& point);

/// "9 rpm, wind 12 m/s, pitch 3.5 deg, azimuth 0 deg": the operating point `model` is put at for
/// `point` (rotor speed; the wind speed, collective pitch and starting azimuth where the model has
/// them), for error messages.
std::string sweepPointLabel(const Model& model, const SweepPoint& point);

/// The sweep: task k = (set k / P, point k mod P) of sets × P tasks (P = points.size()) computes
/// `compute(model_of(set), points[p], initialPoint(model_of(set), sweepCondition(...)))` → T.
/// `model_of(set)` returns the set's model (built once, e.g. lazily per rank; a reference that stays
/// valid). Results travel as `encode(T)` bytes, `decode(bytes)` → T, and come back in task order on
/// rank 0 (an empty vector on the other ranks). Errors: parallel::parallelMap's (the lowest failing
/// task's, on every rank).
template <class T, class ModelOf, class Compute, class Encode, class Decode>
std::vector<T> sweepOperatingPoints(int sets, ModelOf&& model_of, const std::vector<SweepPoint>& points,
                                    Compute&& compute, Encode&& encode, Decode&& decode, const SweepOptions& opt) {
  const int P = static_cast<int>(points.size());
  parallel::MapOptions map;
  map.progress = opt.progress;
  return parallel::parallelMap<T>(
      sets * P,
      [&](int k) {
        const Model& model = model_of(k / P);
        const SweepPoint& point = points[static_cast<size_t>(k % P)];
        auto run = [&]() -> T { return compute(model, point, initialPoint(model, sweepCondition(model, point))); };
        auto where = [&] {
          const std::string head = opt.context ? opt.context(k % P)
                                               : "operating point " + std::to_string(k % P + 1) + " ";
          return head + "(" + sweepPointLabel(model, point) + "): ";
        };
        try {
          return run();
        } catch (const InputError& e) {
          throw InputError(where() + e.what());
        } catch (const ComputeError& e) {
          throw ComputeError(where() + e.what());
        }
      },
      encode, decode, map);
}

/// One model: sweepOperatingPoints with a single set.
template <class T, class Compute, class Encode, class Decode>
std::vector<T> sweepOperatingPoints(const Model& model, const std::vector<SweepPoint>& points, Compute&& compute,
                                    Encode&& encode, Decode&& decode, const SweepOptions& opt) {
  return sweepOperatingPoints<T>(
      1, [&](int) -> const Model& { return model; }, points, compute, encode, decode, opt);
}

}  // namespace whirl

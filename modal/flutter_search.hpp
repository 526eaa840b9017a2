#pragma once
/// \file
/// The flutter search of `whirl flutter` and Python's `Model.flutter`: the rotor speed raised beyond rated
/// (still air, or a given wind with the pitch held) until the least-damped oscillating mode's damping
/// crosses zero, then bisected on the rotor speed; the onset is zero damping interpolated linearly in the
/// final bracket (the flutter limit as the rotor speed of zero damping, Hansen 2007, "Aeroelastic
/// instability problems for wind turbines"). Each rotor speed is a periodic linearization averaged in
/// multiblade coordinates (the path of `whirl modes`), with the model's aerodynamic states if it has them.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linearize/periodic.hpp"
#include "src/model/model.hpp"

namespace whirl {

struct FlutterSearchOptions {
  double wind = 0;          ///< hub-height wind speed [m/s] (models with a wind input)
  double rpm_min = 0;       ///< first rotor speed [rpm], > 0
  double rpm_max = 0;       ///< last rotor speed searched [rpm], > rpm_min; (rpm_max − rpm_min) / rpm_step ≤
                            ///< limits::kMaxSweepPoints
  double rpm_step = 1;      ///< step of the search before bisection [rpm], in [1e-3, 1e3]
  double tolerance = 0.01;  ///< width of the final bracket [rpm], in [1e-6, 1e3]
  double min_freq = 0.1;    ///< modes below this damped frequency are not candidates [Hz], in [0, 1e3]
  int azimuths = 36;        ///< of each multiblade average
};

/// The least-damped oscillating mode at one rotor speed: rigid-body and first-order roots and modes below
/// FlutterSearchOptions::min_freq (drivetrain and controller roots, damped by the torque law) excluded.
struct FlutterPoint {
  double rpm = 0;
  double damping = 0;  ///< damping ratio [-]
  double freq_hz = 0;  ///< damped frequency [Hz]
  std::string mode;
};

struct FlutterOnset {
  double rpm = 0;      ///< zero damping, interpolated in the final bracket [rpm]
  double freq_hz = 0;  ///< the mode's frequency there [Hz]
  std::string mode;    ///< the mode unstable above the onset
};

struct FlutterSearch {
  std::vector<FlutterPoint> points;   ///< every rotor speed evaluated, in the order of the search
  std::optional<FlutterOnset> onset;  ///< none: stable up to rpm_max
};

/// Called with each rotor speed's periodic linearization before its modes are taken (the front ends check
/// the points' validity there and may throw), then with the point found.
struct FlutterCallbacks {
  std::function<void(const PeriodicLinearization&, double rpm)> check;
  std::function<void(const FlutterPoint&)> progress;
};

/// The searched range: `rpm_min`, or the model's initial rotor speed (the deck's `RotSpeed`); `rpm_max`, or
/// 3 × the first. Checked by flutterSearch.
void setRotorSpeedRange(const Model& model, std::optional<double> rpm_min, std::optional<double> rpm_max,
                        FlutterSearchOptions& options);

/// The search. Throws InputError for options outside their ranges, ComputeError when no mode oscillates
/// above min_freq or the first rotor speed is already unstable (start lower).
FlutterSearch flutterSearch(const Model& model, const FlutterSearchOptions& opt,
                            const FlutterCallbacks& callbacks = {});

}  // namespace whirl

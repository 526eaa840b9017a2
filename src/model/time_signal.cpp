#include "src/model/time_signal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace whirl {

SignalValue evaluateSignal(const TimeSignal& s, double base, double t) {
  const std::vector<double>& p = s.parameters;
  switch (s.kind) {
    case TimeSignal::Kind::Step: return {base + (t >= p[0] ? p[1] : 0.0), 0.0, 0.0};
    case TimeSignal::Kind::Ramp: {
      if (t < p[0]) return {base, 0, 0};
      if (t >= p[1]) return {base + p[2], 0, 0};
      const double slope = p[2] / (p[1] - p[0]);
      return {base + slope * (t - p[0]), slope, 0};
    }
    case TimeSignal::Kind::Sine: {
      const double w = 2 * std::numbers::pi * p[1];
      return {base + p[0] * std::sin(w * t), p[0] * w * std::cos(w * t), -p[0] * w * w * std::sin(w * t)};
    }
    case TimeSignal::Kind::Spinup: {
      const double T = p[0], w = p[1], k = 2 * std::numbers::pi / T;
      if (t <= 0) return {base, 0, 0};
      if (t >= T) return {base + w * T / 2 + w * (t - T), w, 0};  // θ(T) = w T/2
      return {base + (w / T) * (t * t / 2 + (std::cos(k * t) - 1) / (k * k)), (w / T) * (t - std::sin(k * t) / k),
              (w / T) * (1 - std::cos(k * t))};
    }
    case TimeSignal::Kind::Table: {
      const std::vector<double>& x = s.time;
      if (t < x.front()) return {s.values.front(), 0, 0};
      if (t >= x.back()) return {s.values.back(), 0, 0};
      const auto k = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin()) - 1;
      const double slope = (s.values[k + 1] - s.values[k]) / (x[k + 1] - x[k]);
      return {s.values[k] + slope * (t - x[k]), slope, 0};
    }
  }
  return {base, 0, 0};
}

std::vector<double> signalBreakpoints(const TimeSignal& s) {
  switch (s.kind) {
    case TimeSignal::Kind::Step: return {s.parameters[0]};
    case TimeSignal::Kind::Ramp: return {s.parameters[0], s.parameters[1]};
    case TimeSignal::Kind::Sine: return {};
    case TimeSignal::Kind::Spinup: return {s.parameters[0]};  // the jerk jumps at the end of the spin-up
    case TimeSignal::Kind::Table: return s.time;
  }
  return {};
}

}  // namespace whirl

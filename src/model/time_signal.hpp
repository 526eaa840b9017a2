#pragma once
/// \file
/// A prescribed function of time for an input u(t) of a simulation (linearize/simulate.hpp): a step,
/// a ramp, a sine, or a table interpolated linearly. Plain data; parseTimeSignal (src/io) reads the
/// command-line form `step(t0,a)`, `ramp(t0,t1,a)`, `sin(A,f)` or a CSV file.
#include <string>
#include <vector>

namespace whirl {

/// Value and time derivatives of a signal at one instant (units of the input per s, per s²).
struct SignalValue {
  double value = 0, rate = 0, acceleration = 0;
};

struct TimeSignal {
  enum class Kind { Step, Ramp, Sine, Table };
  Kind kind = Kind::Step;
  /// Step: {t0 [s], a}; Ramp: {t0 [s], t1 [s], a}; Sine: {A, f [Hz]}. Step, ramp and sine add to the
  /// input's operating value (`relative`), a table gives the value itself.
  std::vector<double> parameters;
  std::vector<double> time, values;  ///< Table: strictly increasing times [s] and the values
  std::string source;                ///< as written by the user, for messages
  bool relative() const { return kind != Kind::Table; }
};

/// u(t) and its derivatives: `base` + the signal for the relative kinds, the table value otherwise
/// (held constant before the first and after the last row). Derivatives are one-sided from the right
/// at a kink (the ramp's ends, a table's rows) and 0 across a step.
SignalValue evaluateSignal(const TimeSignal& s, double base, double t);

/// The instants where the signal or its rate jumps (step time, ramp ends, table rows): an integrator
/// restarts there instead of stepping over the discontinuity.
std::vector<double> signalBreakpoints(const TimeSignal& s);

}  // namespace whirl

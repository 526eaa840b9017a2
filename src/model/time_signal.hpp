#pragma once
/// \file
/// A prescribed function of time for an input u(t) or a driven coordinate q(t) of a simulation
/// (linearize/simulate.hpp): a step, a ramp, a sine, a smooth spin-up, or a table interpolated
/// linearly. Plain data; parseTimeSignal (src/io) reads the command-line form `step(t0,a)`,
/// `ramp(t0,t1,a)`, `sin(A,f)`, `spinup(T,w)` or a CSV file.
#include <string>
#include <vector>

namespace whirl {

/// Value and time derivatives of a signal at one instant (units of the input per s, per s²).
struct SignalValue {
  double value = 0, rate = 0, acceleration = 0;
};

struct TimeSignal {
  enum class Kind { Step, Ramp, Sine, Spinup, Table };
  Kind kind = Kind::Step;
  /// Step: {t0 [s], a}; Ramp: {t0 [s], t1 [s], a}; Sine: {A, f [Hz]}; Spinup: {T [s], w [1/s]}, the
  /// angle whose acceleration is (w/T)(1 − cos 2πt/T) until T, then constant rate w (Kane's driver
  /// experiment: T = 15 s, w = 6 rad/s, θ̈ = (2/5)(1 − cos(πt/7.5)) [Branlard2019, §5.2]).
  /// Step, ramp, sine and spin-up add to the operating value (`relative`), a table gives the value itself.
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

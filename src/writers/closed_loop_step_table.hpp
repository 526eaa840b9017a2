#pragma once
/// \file
/// `whirl verify --closed-loop` files: closed_loop_step.csv (time, the wind, then per compared signal its
/// nonlinear and linear change from the steady value, SI units) and closed_loop_step.gp (one panel per
/// signal, nonlinear and linear on top of each other).
#include <string>

#include "modal/closed_loop_step.hpp"

namespace whirl {

std::string closedLoopStepCsv(const ClosedLoopStep& r, double wind_speed, const ClosedLoopStepOptions& opt);
std::string closedLoopStepGnuplot(const ClosedLoopStep& r, double wind_speed, const ClosedLoopStepOptions& opt);

}  // namespace whirl

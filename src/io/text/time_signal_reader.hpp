#pragma once
/// \file
/// Reads the time signal of a simulation input (src/model/time_signal.hpp) from its command-line form.
#include <string>
#include <utility>

#include "src/model/time_signal.hpp"

namespace whirl {

/// `step(t0,a)`, `ramp(t0,t1,a)` (t1 > t0), `sin(A,f)` (f ≥ 0), `spinup(T,w)` (T > 0), or the path of a CSV file whose
/// first two columns are the time [s] (strictly increasing) and the value (at least one row). \param[in] key  what
/// messages name (e.g. "--input thrust") \throws InputError "key: reason", or "file:line: column: reason" for a file
TimeSignal parseTimeSignal(const std::string& text, const std::string& key);

/// "NAME=signal" → {NAME, signal text}, blanks around both trimmed.
/// \throws InputError "key: expected NAME=..." without '=' or with an empty name
std::pair<std::string, std::string> splitAssignment(const std::string& text, const std::string& key);

}  // namespace whirl

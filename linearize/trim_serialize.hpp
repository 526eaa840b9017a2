#pragma once
/// \file
/// A trimmed steady state as bytes (CBOR through nlohmann::json, linearize/cbor_bytes.hpp), so the
/// points of a trim schedule computed on one MPI rank arrive on the others exactly as computed: every
/// double travels as its 8 bytes.
///
/// What travels: the condition, the balance's values and the equilibria at the azimuths
/// (SteadyState::azimuth_q: the sweeps and the closed-loop modes start each point's periodic
/// equilibrium from them, so a point must carry them wherever it is linearized). Not the Newton
/// matrices (SteadyState::azimuth_stiffness): only the next wind speed of the same chain starts from
/// them, and a chain runs on one rank (trimSchedule); a decoded state has none.
#include <string>
#include <vector>

#include "linearize/trim.hpp"

namespace whirl {

std::string encodeSteadyState(const SteadyState& state);

/// Throws ComputeError ("steady state: corrupt result bytes (…)") on bytes that are not an encoded
/// SteadyState (truncated, altered, another type).
SteadyState decodeSteadyState(const std::string& bytes);

/// A list of states (a chain of the trim schedule) as one byte string, in order.
std::string encodeSteadyStates(const std::vector<SteadyState>& states);

/// Throws ComputeError ("steady states: corrupt result bytes (…)") as decodeSteadyState.
std::vector<SteadyState> decodeSteadyStates(const std::string& bytes);

}  // namespace whirl

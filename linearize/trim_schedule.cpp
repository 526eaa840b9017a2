// The trim schedule (linearize/trim.hpp): the wind speeds as warm-started chains, one per MPI rank.
#include <string>
#include <vector>

#include "linearize/trim.hpp"
#include "linearize/trim_serialize.hpp"
#include "src/base/error.hpp"
#include "src/parallel/blocks.hpp"
#include "src/parallel/parallel_map.hpp"
#include "src/parallel/session.hpp"

namespace whirl {
namespace {

// Where the trim at `w` is expected from the chain's points so far (`out`, the last one the neighbour):
// the tip-speed ratio held, the pitch extrapolated linearly from the last two above rated, the
// neighbour's equilibria and Newton matrices as starts. Cold (an empty guess) for a chain's first point.
TrimGuess neighbourGuess(const std::vector<SteadyState>& out, double w) {
  TrimGuess g;
  const std::size_t n = out.size();
  if (n == 0) return g;
  const SteadyState& p = out[n - 1];
  const double pw = *p.condition.wind_speed;
  g.rotor_speed = p.condition.rotor_speed / pw * w;  // the tip-speed ratio held
  g.pitch = *p.condition.collective_pitch;
  g.q = p.azimuth_q;
  g.stiffness = p.azimuth_stiffness;
  (p.above_rated ? g.pitch_slope : g.speed_slope) = p.search_slope;
  if (n >= 2 && out[n - 2].above_rated && p.above_rated) {
    const SteadyState& pp = out[n - 2];
    const double dw = pw - *pp.condition.wind_speed;
    if (dw != 0) g.pitch += (g.pitch - *pp.condition.collective_pitch) / dw * (w - pw);
  }
  return g;
}

// The winds of `b` as one chain, its first point started cold; `progress(done, b's size)` after each.
std::vector<SteadyState> trimChain(const Model& m, const std::vector<double>& winds, parallel::Block b,
                                   const TrimOptions& opt, const std::function<void(int, int)>& progress) {
  std::vector<SteadyState> out;
  for (int k = b.begin; k < b.end; ++k) {
    const double w = winds[static_cast<std::size_t>(k)];
    out.push_back(trimAtWindSpeed(m, w, neighbourGuess(out, w), opt));
    if (progress) progress(static_cast<int>(out.size()), b.end - b.begin);
  }
  return out;
}

}  // namespace

// One chain per rank (parallel::mapSize): a chain needs its neighbours, so the winds are cut into
// contiguous blocks rather than dealt out cyclically as the sweep's points are. On one rank the one
// chain is today's schedule, bit for bit; on N ranks the first point of each later block starts cold
// and equals the one-rank point to the trim's tolerance (TrimOptions::tolerance), not bit for bit.
// Every rank gets the whole schedule (the distributed sweep that follows needs every point on each).
std::vector<SteadyState> trimSchedule(const Model& m, const std::vector<double>& winds, const TrimOptions& opt) {
  const int n = static_cast<int>(winds.size());
  const std::vector<parallel::Block> blocks = parallel::contiguousBlocks(n, parallel::mapSize());
  if (blocks.size() <= 1) return trimChain(m, winds, {0, n}, opt, opt.progress);
  parallel::MapOptions map;
  map.every_rank = true;
  // Progress on rank 0, over its own block: a callback's exception stops the schedule (as a
  // std::runtime_error with its message, the way parallelMapBytes reports a task's other errors).
  const std::function<void(int, int)> progress = parallel::rank() == 0 ? opt.progress : nullptr;
  const std::vector<std::string> chains = parallel::parallelMapBytes(
      static_cast<int>(blocks.size()),
      [&](int k) {
        return encodeSteadyStates(trimChain(m, winds, blocks[static_cast<std::size_t>(k)], opt, progress));
      },
      map);
  std::vector<SteadyState> out;
  out.reserve(winds.size());
  for (const std::string& bytes : chains)
    for (SteadyState& s : decodeSteadyStates(bytes)) out.push_back(std::move(s));
  if (out.size() != winds.size())
    throw ComputeError("trim schedule: " + std::to_string(out.size()) + " points gathered for " +
                       std::to_string(winds.size()) + " wind speeds");
  return out;
}

std::vector<SweepPoint> trimmedPoints(const Model& m, const std::string& spec, const TrimOptions& opt) {
  std::vector<SweepPoint> points;
  for (const SteadyState& s : trimSchedule(m, parseRange(spec, "--wind"), opt)) points.push_back(sweepPointOf(s));
  return points;
}

}  // namespace whirl

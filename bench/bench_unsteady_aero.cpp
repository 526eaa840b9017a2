// Speed with the blade elements' unsteady-airfoil states (issue 47, "Numbers"): the NREL 5MW
// (cases/nrel5mw/Main_Aero.fst with its airfoil files' UA data, UA_Mod 4: 180 states on 45 elements) —
// one aeroelastic linearization with the states at rated (11.4 m/s, 12.1 rpm), and its Campbell diagram
// along 23 trimmed wind speeds (3–25 m/s, 36 azimuths); the same with DBEMT_Mod 3 dynamic inflow (408 states).
// Targets: 200 µs and 1 s.
// Run: build/bench/whirl_bench --benchmark_filter=Ua
#include <benchmark/benchmark.h>

#include <numbers>

#include "linearize/linearize.hpp"
#include "linearize/trim.hpp"
#include "modal/campbell_sweep.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

Model uaModel() {
  return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst", {"AFAeroMod=2", "UAMod=4"});
}

// The same with DBEMT_Mod 3 dynamic inflow (WakeMod 2): 228 more states, 4 on each of the 57 elements.
Model uaDbemtModel() {
  return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst",
                            {"AFAeroMod=2", "UAMod=4", "WakeMod=2", "DBEMT_Mod=3"});
}

void uaLinearization(benchmark::State& state, const Model& m) {
  OperatingCondition c;
  c.rotor_speed = 12.1 * std::numbers::pi / 30;
  c.wind_speed = 11.4;
  c.collective_pitch = 0;
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m, c));
  LinearizeWorkspace lw(m);
  LinearizeOptions opt;
  opt.unsteady_aero = true;
  for (auto _ : state) {
    LinearModel l = linearize(m, op, lw, opt);
    benchmark::DoNotOptimize(l.A.data());
  }
  state.counters["ua_states"] = uaStateCount(m.aero);
  state.counters["aero_states"] = aeroStateCount(m.aero);
}

void nrel5mwUaLinearization(benchmark::State& state) { uaLinearization(state, uaModel()); }
BENCHMARK(nrel5mwUaLinearization)->Unit(benchmark::kMicrosecond);

void nrel5mwUaDbemtLinearization(benchmark::State& state) { uaLinearization(state, uaDbemtModel()); }
BENCHMARK(nrel5mwUaDbemtLinearization)->Unit(benchmark::kMicrosecond);

void uaCampbell(benchmark::State& state, const Model& m) {
  SweepOptions opt;
  opt.azimuths = 36;
  opt.unsteady_aero = true;
  for (auto _ : state) {
    auto points = campbellSweep(m, trimmedPoints(m, "3:1:25"), opt);
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["linearizations"] = 23 * 36;
}

void nrel5mwUaCampbell(benchmark::State& state) { uaCampbell(state, uaModel()); }
BENCHMARK(nrel5mwUaCampbell)->Unit(benchmark::kMillisecond);

void nrel5mwUaDbemtCampbell(benchmark::State& state) { uaCampbell(state, uaDbemtModel()); }
BENCHMARK(nrel5mwUaDbemtCampbell)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace whirl

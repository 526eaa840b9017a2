// `simulate` on the NREL 5MW structural model (cases/nrel5mw/Main_Onshore.fst, rotor free at
// 12.1 rpm, tower top and blade tips displaced): 600 s simulated, wall time and the ratio to real
// time as counters. Run: build/bench/whirl_bench --benchmark_filter=nrel5mwSimulate
#include <benchmark/benchmark.h>

#include <numbers>

#include "linearize/simulate.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

void nrel5mwSimulate600s(benchmark::State& state) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Onshore.fst");
  OperatingCondition c;
  c.rotor_speed = 12.1 * std::numbers::pi / 30;
  OperatingPoint start = solveOperatingPoint(m, c);
  for (int i : m.activeDofs())
    if (m.dofs[i].kind == DofKind::Elastic) start.q(i) += 0.1;  // a free decay of every elastic coordinate
  SimulationOptions o;
  o.t_end = 600;
  o.dt_out = 0.05;
  Simulation sim;
  for (auto _ : state) {
    sim = simulate(m, start, o);
    benchmark::DoNotOptimize(sim.q.data());
  }
  state.counters["states"] = static_cast<double>(2 * sim.states.size());
  state.counters["steps"] = static_cast<double>(sim.steps);
  state.counters["jacobians"] = static_cast<double>(sim.jacobian_evaluations);
  state.counters["x_real_time"] = benchmark::Counter(o.t_end * static_cast<double>(state.iterations()),
                                                     benchmark::Counter::kIsRate);
}
BENCHMARK(nrel5mwSimulate600s)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace whirl

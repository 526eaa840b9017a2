// `simulate` (SUNDIALS IDA, linearize/simulate.hpp), 600 s simulated at the default tolerances
// (1e-6 / 1e-8), the ratio to real time and IDA's counters as counters:
//  - nrel5mwSimulate600s: the NREL 5MW structural model (cases/nrel5mw/Main_Onshore.fst, 16 DOFs),
//    rotor free at 12.1 rpm from its equilibrium, every elastic coordinate displaced 0.1 (a violent
//    transient: the blades leave the small-slope range in the first second, whirl simulate warns);
//  - nrel5mwAeroStartup: the 10-minute start-up of [Branlard2019, §5.6] (no controller, no turbulence):
//    cases/nrel5mw/Main_Aero.fst (8 m/s steady wind, pitch 0, ServoDyn's simple torque law, AeroDyn's
//    BEMT re-solved at every residual), the rotor released from rest at the parked static equilibrium;
//    it settles at 9.13 rpm (tests/validation/test_simulate_aero.cpp checks it against `whirl steady`);
//    at the default tolerances and with the absolute one loosened to 1e-7 and 1e-6; nrel5mwAeroStartupNoSkew
//    without AeroDyn's skewed-wake correction.
// Run: build/bench/whirl_bench --benchmark_filter='nrel5mwSimulate|nrel5mwAeroStartup'
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "linearize/simulate.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

// IDA's work and the ratio to real time, as counters.
void idaCounters(benchmark::State& state, const Simulation& sim, double t_end) {
  state.counters["steps"] = static_cast<double>(sim.steps);
  state.counters["residuals"] = static_cast<double>(sim.residual_evaluations);
  state.counters["jacobians"] = static_cast<double>(sim.jacobian_evaluations);
  state.counters["mass"] = static_cast<double>(sim.mass_matrix_evaluations);
  state.counters["x_real_time"] = benchmark::Counter(t_end * static_cast<double>(state.iterations()),
                                                     benchmark::Counter::kIsRate);
}

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
  state.counters["error_fails"] = static_cast<double>(sim.error_test_failures);
  state.counters["newton_fails"] = static_cast<double>(sim.convergence_failures);
  idaCounters(state, sim, o.t_end);
}
BENCHMARK(nrel5mwSimulate600s)->Unit(benchmark::kMillisecond)->Iterations(1);

void aeroStartup(benchmark::State& state, const std::vector<std::string>& overrides) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst", overrides);
  OperatingCondition parked;
  parked.rotor_speed = 0;
  const OperatingPoint start = solveOperatingPoint(m, parked);
  SimulationOptions o;
  o.t_end = 600;
  o.dt_out = 0.1;  // the deck's DT_Out
  o.atol = std::pow(10.0, -static_cast<double>(state.range(0)));
  Simulation sim;
  for (auto _ : state) {
    sim = simulate(m, start, o);
    benchmark::DoNotOptimize(sim.q.data());
  }
  state.counters["error_fails"] = static_cast<double>(sim.error_test_failures);
  state.counters["newton_fails"] = static_cast<double>(sim.convergence_failures);
  state.counters["newton_iters"] = static_cast<double>(sim.nonlinear_iterations);
  const int az = m.roles.azimuth.front();
  state.counters["final_rpm"] = sim.qd(sim.qd.rows() - 1, az) * 30 / std::numbers::pi;
  idaCounters(state, sim, o.t_end);
}
void nrel5mwAeroStartup(benchmark::State& state) { aeroStartup(state, {}); }
// The same without AeroDyn's skewed-wake correction (the deck's SkewMod 2 set to 0): its 1P induction
// costs IDA more steps and each residual a second flow and polar evaluation per element.
void nrel5mwAeroStartupNoSkew(benchmark::State& state) { aeroStartup(state, {"SkewMod=0"}); }
// The argument k: IDA's absolute tolerance 10^-k (8: the default). The looser ones show the price of
// the default's accuracy; what each costs in accuracy is in README *Speed* (work and precision).
BENCHMARK(nrel5mwAeroStartup)->Arg(8)->Arg(7)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(nrel5mwAeroStartupNoSkew)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace whirl

// Issue 43 "Numbers": the closed-loop aeroelastic Campbell along 23 wind speeds and `whirl tune`.
#include <benchmark/benchmark.h>

#include <string>

#include "linearize/controller_tuning.hpp"
#include "linearize/controller_tuning_whirl.hpp"
#include "linearize/sweep.hpp"
#include "linearize/trim.hpp"
#include "modal/closed_loop_campbell.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/openfast/servodyn/rotor_performance_input.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kRoot = WHIRL_SOURCE_DIR;

TuningTurbine nrel5mwTuning() {
  TuningTurbine t;  // tests/data/rosco/NREL5MW.yaml and the deck (tests/unit/test_controller_tuning.cpp)
  t.inertia = 38677040.613 + 534.116 * 97 * 97;
  t.rotor_radius = 63;
  t.air_density = 1.225;
  t.gearbox_ratio = 97;
  t.rated_rotor_speed = 1.26711;
  t.rated_power = 5e6;
  t.v_min = 3;
  t.v_rated = 11.4;
  t.v_max = 25;
  return t;
}

TuningGoals nrel5mwGoals() {
  TuningGoals g;
  g.pc_omega = 0.6;
  g.pc_zeta = 0.7;
  g.vs_omega = 0.15;
  g.vs_zeta = 0.7;
  return g;
}

// ROSCO's tuning from its Cp surface: reading the surface, the schedule and the placement.
void tuneCpSurface(benchmark::State& state) {
  for (auto _ : state) {
    const aero::RotorPerformance p = io::readRotorPerformance(kRoot + "/tests/data/rosco/Cp_Ct_Cq.NREL5MW.txt");
    const GainSchedule g = placePoles(roscoTuningSchedule(p, nrel5mwTuning(), nrel5mwGoals()), nrel5mwTuning(),
                                      nrel5mwGoals());
    benchmark::DoNotOptimize(g.kp.data());
  }
}
BENCHMARK(tuneCpSurface)->Unit(benchmark::kMillisecond);

// `whirl tune` with whirl's sensitivities: 32 trimmed points (the last below rated and 31 from rated),
// each linearized at 3 × 3 azimuths.
void tuneWhirl(benchmark::State& state) {
  const Model m = readElastoDynModel(kRoot + "/cases/nrel5mw/Main_Aero.fst");
  const std::vector<double> all = roscoWindSpeeds(nrel5mwTuning(), nrel5mwGoals());
  const std::vector<double> winds(all.begin() + 28, all.end());
  for (auto _ : state) {
    const std::vector<TuningPoint> s = whirlTuningSchedule(m, trimSchedule(m, winds));
    benchmark::DoNotOptimize(s.data());
  }
}
BENCHMARK(tuneWhirl)->Unit(benchmark::kMillisecond);

// The closed-loop Campbell of `whirl campbell cases/nrel5mw/Main_ROSCO.fst --wind 3:1:25 --closed-loop`: the
// 23 wind speeds trimmed with ROSCO's controller, each plant linearized at 36 azimuths, closed by the
// controller linearized there, eigen, naming, margins of both loops, tracking (no files).
void nrel5mwClosedLoopCampbell(benchmark::State& state) {
  const std::string deck = kRoot + "/cases/nrel5mw/Main_ROSCO.fst";
  const Model m = readElastoDynModel(deck);
  const RoscoController c = *io::readDeckController(deck, {});
  TrimOptions trim;
  trim.controller = &c;
  for (auto _ : state) {
    const ClosedLoopCampbell d = closedLoopCampbell(m, c, trimSchedule(m, parseRange("3:1:25", "--wind"), trim));
    benchmark::DoNotOptimize(d.closed.lines.data());
  }
}
BENCHMARK(nrel5mwClosedLoopCampbell)->Unit(benchmark::kMillisecond);

// The same without the trim: the closed loop along an already trimmed schedule.
void nrel5mwClosedLoopFromSchedule(benchmark::State& state) {
  const std::string deck = kRoot + "/cases/nrel5mw/Main_ROSCO.fst";
  const Model m = readElastoDynModel(deck);
  const RoscoController c = *io::readDeckController(deck, {});
  TrimOptions trim;
  trim.controller = &c;
  const std::vector<SteadyState> schedule = trimSchedule(m, parseRange("3:1:25", "--wind"), trim);
  for (auto _ : state) {
    const ClosedLoopCampbell d = closedLoopCampbell(m, c, schedule);
    benchmark::DoNotOptimize(d.closed.lines.data());
  }
}
BENCHMARK(nrel5mwClosedLoopFromSchedule)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace whirl

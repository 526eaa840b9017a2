// Speed of the core: one residual evaluation in double, and one full linearization (K, C, Q by
// chunked AD, M assembled in double, A and B) at the operating point, for each validation case and
// a 29-DOF floating turbine with every term of the residual. Run: build/bench/whirl_bench
#include <benchmark/benchmark.h>

#include <numbers>

#include "linearize/jacobian.hpp"
#include "linearize/linearize.hpp"
#include "linearize/periodic.hpp"
#include "linearize/trim.hpp"
#include "modal/campbell_sweep.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"
#include "src/io/case/case_file.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/rich_model.hpp"

namespace whirl {
namespace {

Model load(const std::string& name) {
  if (name == "rich_29dof") return test::richModel();
  if (name == "nrel5mw") return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Onshore.fst");
  if (name == "nrel5mw_aero") return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst");
  // BeamDyn blades (issue 46): Test26's structure with 8 fixed-root modes per blade (60 elements), and
  // the aeroelastic deck with them (Main_Aero_BD.fst: 10 rpm, 8 m/s).
  const std::string test26 = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw_beamdyn/Test26.fst";
  if (name == "nrel5mw_beamdyn") return readElastoDynModel(test26, {"CompAero=0", "CompInflow=0"});
  if (name == "nrel5mw_beamdyn_aero")
    return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw_beamdyn/Main_Aero_BD.fst");
  return readCase(std::string(WHIRL_SOURCE_DIR) + "/cases/" + name + "/" + name + ".yaml");
}

void residualDouble(benchmark::State& state, const std::string& name) {
  const Model m = load(name);
  Workspace<double> ws(m);
  const OperatingPoint op = initialPoint(m);
  VecX e(m.ndof());
  for (auto _ : state) {
    residual(m, ws, op.q, op.qd, op.qdd, op.u, e);
    benchmark::DoNotOptimize(e.data());
  }
  state.counters["dofs"] = m.ndof();
}

void linearization(benchmark::State& state, const std::string& name) {
  const Model m = load(name);
  // The rich model's loads are arbitrary (no equilibrium near zero): time it at its initial point.
  const OperatingPoint op = name == "rich_29dof" ? initialPoint(m) : solveOperatingPoint(m, initialPoint(m));
  LinearizeWorkspace lw(m);  // as in a sweep: buffers allocated once per model
  for (auto _ : state) {
    LinearModel l = linearize(m, op, lw);
    benchmark::DoNotOptimize(l.A.data());
  }
  state.counters["dofs"] = static_cast<double>(m.activeDofs().size());
}

#define WHIRL_CASE_BENCH(name)                                                   \
  BENCHMARK_CAPTURE(residualDouble, name, #name)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_CAPTURE(linearization, name, #name)->Unit(benchmark::kMicrosecond);

WHIRL_CASE_BENCH(landbased_2dof)
WHIRL_CASE_BENCH(landbased_3dof)
WHIRL_CASE_BENCH(flex_4dof)
WHIRL_CASE_BENCH(floating_3dof)
WHIRL_CASE_BENCH(rotating_blade)
WHIRL_CASE_BENCH(rich_29dof)
WHIRL_CASE_BENCH(nrel5mw)
// The 5MW with AeroDyn (19 elements × 3 blades, frozen wake), 10 rpm, 8 m/s; the residual is the
// quasi-steady one (BEM solved at each of the 57 elements).
WHIRL_CASE_BENCH(nrel5mw_aero)
WHIRL_CASE_BENCH(nrel5mw_beamdyn)
WHIRL_CASE_BENCH(nrel5mw_beamdyn_aero)

// The parts of one aeroelastic 5MW linearization: the AD passes of K (∂e/∂q), C (∂e/∂q̇) and Q (∂e/∂u),
// and the double mass-matrix assembly, each timed alone at the operating point.
void linearizationParts(benchmark::State& state, int part) {
  const Model m = load("nrel5mw_aero");
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  LinearizeWorkspace lw(m);
  const std::vector<int> dofs = m.activeDofs();
  std::vector<int> inputs(m.ninput());
  for (int i = 0; i < m.ninput(); ++i) inputs[i] = i;
  const AeroInflow* frozen = &op.inflow;
  MatX M;
  for (auto _ : state) {
    if (part == 3) {
      massMatrix(m, lw.ws, op.q, M);
      benchmark::DoNotOptimize(M.data());
      continue;
    }
    const Wrt wrt = part == 0 ? Wrt::Q : part == 1 ? Wrt::Qd : Wrt::U;
    MatX J = residualJacobian(m, lw.jw, op.q, op.qd, op.qdd, op.u, wrt, part == 2 ? inputs : dofs, nullptr, frozen);
    benchmark::DoNotOptimize(J.data());
  }
}
BENCHMARK_CAPTURE(linearizationParts, K, 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(linearizationParts, C, 1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(linearizationParts, Q, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(linearizationParts, M, 3)->Unit(benchmark::kMicrosecond);

// One linearization per azimuth of the 5MW turning at 12 rpm (36 azimuths, each its own equilibrium),
// as in a Campbell sweep: every call sees a new point, so nothing cached per point is reused.
// Reported: time per linearization (per_linearization).
void azimuthLinearizations(benchmark::State& state, const std::string& name) {
  const Model m = load(name);
  OperatingPoint start = initialPoint(m);
  start.qd(findAzimuthDof(m)) = 12.0 * 2 * std::numbers::pi / 60;
  PeriodicOptions opt;
  opt.azimuths = 36;
  const std::vector<OperatingPoint> points = linearizePeriodic(m, start, opt).points;
  LinearizeWorkspace lw(m);
  for (auto _ : state)
    for (const OperatingPoint& op : points) {
      LinearModel l = linearize(m, op, lw);
      benchmark::DoNotOptimize(l.A.data());
    }
  state.counters["per_linearization"] = benchmark::Counter(static_cast<double>(points.size()),
                                                           benchmark::Counter::kIsIterationInvariantRate |
                                                               benchmark::Counter::kInvert);
}
void nrel5mwAzimuths(benchmark::State& state) { azimuthLinearizations(state, "nrel5mw"); }
BENCHMARK(nrel5mwAzimuths)->Unit(benchmark::kMicrosecond);
// The same with Test26's BeamDyn blades, 8 modes each (31 DOFs; issue 46: ≤ 100 µs).
void nrel5mwBeamDynAzimuths(benchmark::State& state) { azimuthLinearizations(state, "nrel5mw_beamdyn"); }
BENCHMARK(nrel5mwBeamDynAzimuths)->Unit(benchmark::kMicrosecond);

// The NREL 5MW Campbell diagram of the main command: 31 rotor speeds (0–15 rpm) × 36 azimuths, each
// an equilibrium solve and a linearization, multiblade average and eigenanalysis (no output files).
void nrel5mwCampbell(benchmark::State& state) {
  const Model m = load("nrel5mw");
  const std::vector<SweepPoint> pts = rpmRange("0:0.5:15");
  SweepOptions opt;
  opt.azimuths = 36;
  for (auto _ : state) {
    auto points = campbellSweep(m, pts, opt);
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["linearizations"] = 30 * 36 + 1;  // 0 rpm: one azimuth (parked)
}
BENCHMARK(nrel5mwCampbell)->Unit(benchmark::kMillisecond);

// OC3-Hywind (cases/oc3_hywind, OpenFAST Test24) structure, platform, HydroDyn's linear terms and the
// three catenary lines, 0 to 12 rpm by 1 × 36 azimuths (issue 17: ≤ 1 s on one core); no AeroDyn.
void oc3HywindCampbell(benchmark::State& state) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/oc3_hywind/Test24.fst",
                                     {"CompAero=0", "RdtnMod=0"});
  const std::vector<SweepPoint> pts = rpmRange("0:1:12");
  SweepOptions opt;
  opt.azimuths = 36;
  for (auto _ : state) {
    auto points = campbellSweep(m, pts, opt);
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["linearizations"] = 12 * 36 + 1;
}
BENCHMARK(oc3HywindCampbell)->Unit(benchmark::kMillisecond);

// The aeroelastic Campbell diagram of the main command: 23 wind speeds (3–25 m/s), each trimmed (rotor
// speed or pitch for the torque balance), then 36 azimuths of equilibrium (induction solved on the
// deflected geometry) and frozen-wake linearization, multiblade average and eigenanalysis.
void nrel5mwAeroCampbell(benchmark::State& state) {
  const Model m = load("nrel5mw_aero");
  SweepOptions opt;
  opt.azimuths = 36;
  for (auto _ : state) {
    auto points = campbellSweep(m, trimmedPoints(m, "3:1:25"), opt);
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["linearizations"] = 23 * 36;
}
BENCHMARK(nrel5mwAeroCampbell)->Unit(benchmark::kMillisecond);

// The trim alone (23 wind speeds).
void nrel5mwAeroTrim(benchmark::State& state) {
  const Model m = load("nrel5mw_aero");
  int evaluations = 0;
  for (auto _ : state) {
    evaluations = 0;
    for (const SteadyState& s : trimSchedule(m, parseRange("3:1:25", "--wind"))) evaluations += s.evaluations;
  }
  state.counters["torque_evaluations"] = evaluations;
}
BENCHMARK(nrel5mwAeroTrim)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace whirl

BENCHMARK_MAIN();

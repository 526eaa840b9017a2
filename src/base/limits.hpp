#pragma once
// clang-format off
/// \file
/// Upper bounds on every count whirl reads from an input file or the command line, in one place.
///
/// A count larger than its bound is an InputError naming where it came from (`file:line: key: …` or
/// the option), raised before anything of that size is allocated. Readers whose size follows from a
/// header (the `.lin` reader) allocate as rows are read and compare with the header at the end, so a
/// header's claim alone never allocates. The bounds are far above any model whirl is meant for (the
/// dense eigen solver is O(n³): 20 000 states take minutes) and low enough that reaching one cannot
/// exhaust memory on a workstation.
///
/// | bound | value | where it is read |
/// |---|---|---|
/// | kMaxElastoDynNodes | 1000 | ElastoDyn `TwrNodes`, `BldNodes` |
/// | kMaxFemElements | 500 | `fem_beam` `elements:` of a YAML case |
/// | kMaxFemBodyCoordinates | 1200 | the coordinates one FE body (`fem_beam`, SubDyn) brings: every free DOF unreduced |
/// | kMaxFemShapeElements | 200 | `shapes: {from: fem, elements:}` (a 2D beam for mode shapes) |
/// | kMaxFemShapeMesh | 300 | the elements of that beam once every property station is a node |
/// | kMaxReducedModes | 1000 | Craig–Bampton `modes:` of a `fem_beam`; SubDyn `Nmodes` |
/// | kMaxIntegrationPoints | 10000 | beam `integration: {method: trapezoid or midpoint, n:}` |
/// | kMaxGaussPoints | 500 | beam `integration: {method: gauss, n:}` |
/// | kMaxFemShapeMode | 50 | mode numbers of FE shapes (`shapes: {from: fem, modes: [{mode:}]}`) |
/// | kMaxAnalyticShapeMode | 1000 | mode numbers of analytic shapes (`clamped_topmass`, `torsion_sine`) |
/// | kMaxLinDimension | 100000 | `.lin` header counts (states, inputs, outputs) and matrix sizes `A: n x m` |
/// | kMaxSweepPoints | 100000 | `--rpm START:STEP:STOP` points, `--schedule` rows, `flutter`'s rotor speeds |
/// | kMaxAzimuths | 3600 | `--azimuths N` (CLI::Range in src/cli/cmd_*.cpp) |
/// | kMaxRadiationStates | 1000 | HydroDyn's radiation states N, line 3 of the WAMIT `.ss` file |
/// | kMaxHydroDynJoints, kMaxHydroDynPropSets, kMaxHydroDynMembers | 10000 | HydroDyn `NJoints`, `NPropSets`, `NMembers` (`NFillGroups` lists members) |
/// | kMaxSubDynJoints | 2000 | SubDyn `NJoints` (and `NReact`, `NInterf`, `NCmass`, which list joints) |
/// | kMaxSubDynMembers | 2000 | SubDyn `NMembers`; with `NDiv` at most kMaxFemElements elements in all |
/// | kMaxSubDynNDiv | 100 | SubDyn `NDiv` |
/// | kMaxSubDynPropSets | 2000 | SubDyn property-set counts (`NPropSets`, `NXPropSets`) |
/// | kMaxInputFileBytes | 128 MB | every input file, from its size before reading (src/io/text/input_file.hpp) |
/// | kMaxTableRows | 1000000 | rows of a CSV table (readCsv, readTextCsv) and of an OpenFAST table |
/// | kMaxStudySets | 10000 | rows of `study --params` |
/// | kMaxSimulationRecords | 1000000 | `simulate` recorded instants, tmax / dt-out + 1 |
/// | kMaxSimulationValues | 50000000 | `simulate` recorded values, instants × (2 coordinates + inputs + outputs) |
/// | kMaxSimulationRevolutions | 100000 | `simulate` rotor revolutions, tmax × start rotor speed / 2π |
/// | kMaxSimulationSteps | 5000000 | `simulate` integrator steps in all (IDA) |
/// | kMaxMooringCount | 10000 | MoorDyn v1 counts `NTypes`, `NConnects`, `NLines` |
/// | kMaxGravity | 1000 m/s² | YAML `gravity`, `.fst`/ElastoDyn `Gravity`, `--set gravity` |
/// | kMaxWindSpeed | 100 m/s | InflowWind `HWindSpeed`, YAML `wind.speed`, every operating point's wind |
/// | kMaxVerifyAmplitude | 1 m or rad | `verify --amplitude`, Python `Model.verify(amplitude=)` |
// clang-format on
namespace whirl::limits {

inline constexpr int kMaxElastoDynNodes = 1000;
// The FE bodies' reductions solve dense eigenproblems of the free DOFs (6 per node): 500 elements are
// about 3000 DOFs, 72 MB per dense matrix; at 2000 elements each was 1.15 GB (a fuzz finding ran out of
// its 2 GB under the sanitizers). Cases use 50–100 elements, the SubDyn jacket 224.
inline constexpr int kMaxFemElements = 500;
// A body's Ritz integrals are dense: 9 (n + 1)² doubles for n coordinates (1200: 100 MB). An unreduced
// FE body has one coordinate per free DOF: 671 elements without a reduction took 3 GB (a fuzz finding).
inline constexpr int kMaxFemBodyCoordinates = 1200;
// The FE shapes solve the dense generalized eigenproblem of the whole beam (LAPACK dsygvd, O(n³) in
// its 4–5 DOFs per node): 300 elements are about 1500 DOFs, a few seconds with Debian's reference
// LAPACK (measured: 1000 DOFs 2.4 s, 2000 DOFs 24 s on a loaded 2-core machine). The shapes are the
// lowest ≤ 50 modes of a beam, for which tens of elements suffice (cases/ use 60–100).
inline constexpr int kMaxFemShapeElements = 200;
inline constexpr int kMaxFemShapeMesh = 300;
inline constexpr int kMaxReducedModes = 1000;
// A beam's integrals cost O(n) in its points (each adds its sections' inertia and stiffness and one
// interval of the slope-product integral); the trapezoid rule's relative error at 10 000 points is
// ~1e-8, below which more points only cost time.
inline constexpr int kMaxIntegrationPoints = 10000;
// n Gauss points integrate polynomials of degree 2n − 1 exactly; the cases use 16–200, and more than
// 500 only cost time (their nodes by Newton's method are O(n²); from the dense Jacobi eigenproblem they
// were O(n³), and 3210 points took over two minutes under the sanitizers, a fuzz finding).
inline constexpr int kMaxGaussPoints = 500;
inline constexpr int kMaxFemShapeMode = 50;
inline constexpr int kMaxAnalyticShapeMode = 1000;
inline constexpr int kMaxLinDimension = 100000;
inline constexpr int kMaxSweepPoints = 100000;
inline constexpr int kMaxAzimuths = 3600;
/// HydroDyn's state-space radiation (`<PotFile>.ss`): states N (A is N × N, dense).
inline constexpr int kMaxRadiationStates = 1000;
/// HydroDyn's member tables: `NJoints`, `NPropSets`, `NMembers` (and `NFillGroups`, which lists members).
inline constexpr int kMaxHydroDynJoints = 10000;
inline constexpr int kMaxHydroDynPropSets = 10000;
inline constexpr int kMaxHydroDynMembers = 10000;
// SubDyn substructures: the FE model has NJoints + (NDiv − 1) NMembers nodes; its elements are bounded
// as a `fem_beam`'s (kMaxFemElements), since the Craig–Bampton fixed-interface eigenproblem is dense.
inline constexpr int kMaxSubDynJoints = 2000;
inline constexpr int kMaxSubDynMembers = 2000;
inline constexpr int kMaxSubDynNDiv = 100;
inline constexpr int kMaxSubDynPropSets = 2000;
// Every reader holds its whole file in memory, some several times over (text, lines, tokens: a 1 GB
// ElastoDyn file took 4.2 GB). The largest input of the reference decks is a 2 MB WAMIT `.3` file;
// a `.lin` of 1000 states and 1000 outputs is about 60 MB.
inline constexpr long long kMaxInputFileBytes = 128LL * 1000 * 1000;
// Rows of a table (a CSV file, an OpenFAST property or member table): beyond a million a table is
// not an input whirl reads (ElastoDyn stations are interpolated to at most kMaxElastoDynNodes).
inline constexpr int kMaxTableRows = 1000000;
// Each parameter set is a model kept for the sweep and a Campbell diagram (100 001 sets grew past
// 2.4 GB before producing anything).
inline constexpr int kMaxStudySets = 10000;
// `simulate` keeps every recorded instant (q, q̇, u, y) in memory and writes them as text, ~20 bytes a
// value: 5e7 values are 400 MB in memory and about 1 GB of CSV.
inline constexpr long kMaxSimulationRecords = 1000000;
inline constexpr double kMaxSimulationValues = 5e7;
// The integrator resolves each revolution of the rotor with tens of steps at least, so the step count
// grows with the revolutions whatever the tolerance: 10⁵ revolutions are 14 h at 120 rpm. A guard on
// counts, not on wall-clock time (runs stay reproducible); kMaxSimulationSteps is the backstop for a
// motion the start speed does not announce (a spin-up, a diverging rotor).
inline constexpr double kMaxSimulationRevolutions = 1e5;
inline constexpr long kMaxSimulationSteps = 5000000;
// Gravity's magnitude [m/s²]: 100 g. Beyond it a model is not a structure on a planet but an input
// error, and the integrator follows its collapse step by step (1e9 m/s² took 93,707 steps before the
// validity check could stop it).
inline constexpr double kMaxGravity = 1000.0;
// Wind speed [m/s]: the blade-element aerodynamics are incompressible, which holds to about Mach 0.3
// (100 m/s at sea level); IEC 61400-1 class I's 50-year 3-s gust is 70 m/s. A larger wind is an input
// error (1e6 m/s gave loads of 3e21 N that no Newton matrix resolves, reported as a DOF without stiffness).
inline constexpr double kMaxWindSpeed = 100.0;
// `verify`'s perturbation [m or rad]: a check of a linearization lives in its linear range, a
// fraction of the structure's size (a tip deflection of 1 m is 1.6 % of the NREL 5MW blade). Beyond
// it the decays are large nonlinear motions the integrator follows step by step (16 m along every
// blade coordinate took 30 s under the sanitizers) and whose difference from the linear model says
// nothing about the Jacobian.
inline constexpr double kMaxVerifyAmplitude = 1.0;
/// MoorDyn v1's section counts: far above any mooring (the reference floaters have 3–9 lines).
inline constexpr int kMaxMooringCount = 10000;

}  // namespace whirl::limits

#pragma once
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
/// | kMaxFemElements | 2000 | `fem_beam` `elements:` of a YAML case |
/// | kMaxFemShapeElements | 5000 | `shapes: {from: fem, elements:}` (a 2D beam for mode shapes) |
/// | kMaxReducedModes | 1000 | Craig–Bampton `modes:` of a `fem_beam` |
/// | kMaxIntegrationPoints | 100000 | beam `integration: {n:}` |
/// | kMaxFemShapeMode | 50 | mode numbers of FE shapes (`shapes: {from: fem, modes: [{mode:}]}`) |
/// | kMaxAnalyticShapeMode | 1000 | mode numbers of analytic shapes (`clamped_topmass`, `torsion_sine`) |
/// | kMaxLinDimension | 100000 | `.lin` header counts (states, inputs, outputs) and matrix sizes `A: n x m` |
/// | kMaxSweepPoints | 100000 | `--rpm START:STEP:STOP` points, `--schedule` rows |
/// | kMaxAzimuths | 3600 | `--azimuths N` (CLI::Range in src/cli/cmd_*.cpp) |
namespace whirl::limits {

inline constexpr int kMaxElastoDynNodes = 1000;
inline constexpr int kMaxFemElements = 2000;
inline constexpr int kMaxFemShapeElements = 5000;
inline constexpr int kMaxReducedModes = 1000;
inline constexpr int kMaxIntegrationPoints = 100000;
inline constexpr int kMaxFemShapeMode = 50;
inline constexpr int kMaxAnalyticShapeMode = 1000;
inline constexpr int kMaxLinDimension = 100000;
inline constexpr int kMaxSweepPoints = 100000;
inline constexpr int kMaxAzimuths = 3600;

}  // namespace whirl::limits

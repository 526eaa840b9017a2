// libFuzzer harness: the output writers on small models built from the input, as `whirl export` and
// `whirl campbell` call them: the state-space files (.mat, OpenFAST .lin, JSON) of 1–2 operating
// points with 0–3 azimuths, and the Campbell files (CSV, JSON, Gnuplot data and script, HAWCStab2,
// HTML report) of 1–3 points. Names and units are raw bytes from the input (control characters,
// invalid UTF-8, quotes, Gnuplot's and HTML's special characters), numbers are any double (NaN,
// inf, subnormal), line indices may point past a point's modes. Models are consistent in shape
// (A is nx × nx, rates follow their displacements), as whirl's own models always are: a writer's
// precondition is not what is fuzzed, its handling of values and names is.
// Expected: success or InputError/ComputeError (fuzz_support.hpp); the files go to the sandbox.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "modal/campbell.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/state_space_files.hpp"

namespace {

using namespace whirl;

double anyDouble(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: return in.ConsumeFloatingPoint<double>();  // the whole range, ±inf/NaN included by the bytes
    case 1: return in.PickValueInArray({0.0, -0.0, 1e-320, std::nan(""), HUGE_VAL, -HUGE_VAL, 1e308});
    default: return in.ConsumeFloatingPointInRange<double>(-100.0, 100.0);
  }
}

std::string name(FuzzedDataProvider& in) {
  if (in.ConsumeBool()) return in.ConsumeRandomLengthString(16);
  return in.PickValueInArray<const char*>({"tower FA 1", "blade 1 flap 1", "azimuth", "GenSpeed", "wind speed",
                                           "collective pitch", "a,b", "\"q\"", "x'y", "<b>&", "", " "});
}

MatX matrix(FuzzedDataProvider& in, int rows, int cols) {
  MatX m(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) m(i, j) = in.ConsumeBool() ? 0.0 : anyDouble(in);
  return m;
}

StateSpaceVariable variable(FuzzedDataProvider& in, int blades) {
  StateSpaceVariable v;
  v.name = name(in);
  v.unit = in.PickValueInArray<const char*>({"m", "rad", "rad/s", "m/s", "N m", "W", "", "\xff"});
  v.op = anyDouble(in);
  v.blade = blades > 0 ? in.ConsumeIntegralInRange<int>(-1, blades - 1) : -1;
  return v;
}

/// A model with nq displacements and their rates (x = [q; q̇]), nu inputs, ny outputs.
StateSpaceModel model(FuzzedDataProvider& in, int nq, int nu, int ny, int blades) {
  StateSpaceModel s;
  for (int k = 0; k < nq; ++k) s.x.push_back(variable(in, blades));
  if (nq > 0 && in.ConsumeBool()) {
    s.x[0].azimuth = true;
    s.x[0].blade = -1;
  }
  for (int k = 0; k < nq; ++k) {
    StateSpaceVariable r = s.x[k];
    r.name = "d(" + r.name + ")/dt";
    r.azimuth = false;
    r.rate_of = k;
    r.op = anyDouble(in);
    s.x.push_back(r);
  }
  for (int k = 0; k < nu; ++k) s.u.push_back(variable(in, blades));
  for (int k = 0; k < ny; ++k) s.y.push_back(variable(in, blades));
  const int nx = 2 * nq;
  s.xdot_op = VecX::Zero(nx);
  for (int k = 0; k < nx; ++k) s.xdot_op(k) = anyDouble(in);
  s.A = matrix(in, nx, nx);
  s.B = matrix(in, nx, nu);
  s.C = matrix(in, ny, nx);
  s.D = matrix(in, ny, nu);
  s.azimuth = anyDouble(in);
  s.rotor_speed = anyDouble(in);
  if (in.ConsumeBool()) s.wind_speed = anyDouble(in);
  return s;
}

void stateSpaceFiles(FuzzedDataProvider& in) {
  StateSpaceExport e;
  e.source = name(in);
  e.model_name = name(in);
  const int points = in.ConsumeIntegralInRange<int>(1, 2);
  const int nq = in.ConsumeIntegralInRange<int>(0, 3), nu = in.ConsumeIntegralInRange<int>(0, 2),
            ny = in.ConsumeIntegralInRange<int>(0, 2), blades = in.ConsumeIntegralInRange<int>(0, 3);
  for (int p = 0; p < points; ++p) {
    ExportPoint pt;
    pt.rpm = anyDouble(in);
    if (in.ConsumeBool()) pt.wind_speed = anyDouble(in);
    if (in.ConsumeBool()) pt.pitch_deg = anyDouble(in);
    pt.model = model(in, nq, nu, ny, blades);
    const int azimuths = in.ConsumeIntegralInRange<int>(0, 3);
    for (int k = 0; k < azimuths; ++k) pt.azimuths.push_back(model(in, nq, nu, ny, blades));
    pt.model.multiblade = azimuths > 0;
    e.points.push_back(std::move(pt));
  }
  const std::string format = in.PickValueInArray<const char*>({"mat", "lin", "json"});
  const std::string dir = (fuzz::sandbox() / "writers_ss").string();
  prepareOutputFolder(dir);
  OutputSet files(dir);
  writeStateSpaceFiles(e, format, name(in), files);
  files.commit();
}

void campbellFiles(FuzzedDataProvider& in) {
  CampbellDiagram d;
  d.title = name(in);
  const int points = in.ConsumeIntegralInRange<int>(1, 3), ncoord = in.ConsumeIntegralInRange<int>(0, 3);
  std::vector<std::string> coordinates;
  for (int c = 0; c < ncoord; ++c) coordinates.push_back(name(in));
  for (int p = 0; p < points; ++p) {
    CampbellPoint pt;
    pt.rpm = anyDouble(in);
    if (in.ConsumeBool()) pt.wind_speed = anyDouble(in);
    if (in.ConsumeBool()) pt.pitch_deg = anyDouble(in);
    pt.coordinates = coordinates;
    const int nmodes = in.ConsumeIntegralInRange<int>(0, 3);
    for (int m = 0; m < nmodes; ++m) {
      Mode mode;
      mode.freq_hz = anyDouble(in);
      mode.damped_freq_hz = anyDouble(in);
      mode.damping_ratio = anyDouble(in);
      mode.rigid_body = in.ConsumeBool();
      mode.first_order = in.ConsumeBool();
      mode.name = name(in);
      mode.shape = Eigen::VectorXcd::Zero(ncoord);
      mode.participation = VecX::Zero(ncoord);
      for (int c = 0; c < ncoord; ++c) {
        mode.shape(c) = {anyDouble(in), anyDouble(in)};
        mode.participation(c) = anyDouble(in);
      }
      pt.modes.push_back(std::move(mode));
    }
    if (in.ConsumeBool()) pt.validity_problems.push_back(name(in));
    d.points.push_back(std::move(pt));
  }
  const int lines = in.ConsumeIntegralInRange<int>(0, 3);
  for (int l = 0; l < lines; ++l) {
    CampbellLine line;
    line.name = name(in);
    const int entries = in.ConsumeBool() ? points : in.ConsumeIntegralInRange<int>(0, 4);
    for (int p = 0; p < entries; ++p) line.mode.push_back(in.ConsumeIntegralInRange<int>(-2, 3));
    d.lines.push_back(std::move(line));
  }
  CampbellPlotOptions opt;
  opt.render = false;
  if (in.ConsumeBool()) opt.harmonics = {in.ConsumeIntegralInRange<int>(-1, 1000)};
  opt.versus_wind_speed = in.ConsumeBool();
  opt.max_freq_hz = in.ConsumeBool() ? 0.0 : anyDouble(in);
  opt.max_damping_percent = in.ConsumeBool() ? 0.0 : anyDouble(in);
  opt.first_order_lines = in.ConsumeBool();
  if (in.ConsumeBool()) opt.formats = {"hawcstab2"};
  opt.html = in.ConsumeBool();
  if (opt.html) opt.summary = {{name(in), name(in)}};
  writeCampbell(d, (fuzz::sandbox() / "writers_campbell").string(), opt);
}

}  // namespace

static int fuzzOne(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const bool campbell = in.ConsumeBool();
  fuzz::expectOnlyInputErrors([&] { campbell ? campbellFiles(in) : stateSpaceFiles(in); });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_writers", fuzzOne);

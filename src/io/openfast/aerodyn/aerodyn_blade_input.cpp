#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"

#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/io/openfast/distributed_table.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// d/dx at x of the parabola through (x1, f1), (x2, f2), (x3, f3) (AeroDyn's dfdxOfLagrangeInterpolant).
double parabolaSlope(double x, double x1, double f1, double x2, double f2, double x3, double f3) {
  return f1 * ((x - x2) + (x - x3)) / ((x1 - x2) * (x1 - x3)) + f2 * ((x - x1) + (x - x3)) / ((x2 - x1) * (x2 - x3)) +
         f3 * ((x - x1) + (x - x2)) / ((x3 - x1) * (x3 - x2));
}

}  // namespace

std::vector<double> aeroDynCurveAngles(const AeroDynBladeInput& b) {
  // AeroDyn's setCantAngle (AeroDyn_IO.f90): the slope of the mid-chord line x = BlCrvAC + ¼ c sin(twist)
  // over the span, by the parabola through each node and its neighbours (the first and last three at
  // the ends); two nodes have the line's slope.
  const std::size_t n = b.BlSpn.size();
  std::vector<double> x(n), ang(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = b.BlCrvAC[i] + 0.25 * b.BlChord[i] * std::sin(b.BlTwist[i] * kDeg);
  const std::vector<double>& z = b.BlSpn;
  for (std::size_t i = 0; i < n; ++i) {
    double slope = 0;
    if (n == 2) slope = (x[1] - x[0]) / (z[1] - z[0]);
    else {
      const std::size_t k = i == 0 ? 0 : (i + 1 == n ? n - 3 : i - 1);
      slope = parabolaSlope(z[i], z[k], x[k], z[k + 1], x[k + 1], z[k + 2], x[k + 2]);
    }
    ang[i] = std::atan2(slope, 1.0) / kDeg;
  }
  return ang;
}

AeroDynBladeInput readAeroDynBlade(const std::filesystem::path& file, OverrideSet* overrides) {
  AeroDynBladeInput b;
  b.source = OpenFastFile::read(file);
  b.source.checkLayout(aeroDynBladeLayout());
  if (overrides) overrides->applyTo(b.source);
  const OpenFastFile& f = b.source;

  b.NumBlNds = f.getInt("NumBlNds");
  if (b.NumBlNds < 2)
    throw InputError(f.where("NumBlNds", "must be at least 2 (is " + std::to_string(b.NumBlNds) + ")"));
  const DistributedTable t = readDistributedTable(f, "NumBlNds", "BlSpn",
                                                  {"BlSpn", "BlCrvAC", "BlSwpAC", "BlTwist", "BlChord", "BlAFID"});
  b.row_lines = t.row_lines;
  b.BlSpn = t.column("BlSpn");
  b.BlCrvAC = t.column("BlCrvAC");
  b.BlSwpAC = t.column("BlSwpAC");
  b.BlTwist = t.column("BlTwist");
  b.BlChord = t.column("BlChord");
  b.has_BlCrvAng = t.has("BlCrvAng");
  if (b.has_BlCrvAng) b.BlCrvAng = t.column("BlCrvAng");

  const std::string name = f.path().string();
  if (b.BlSpn.front() != 0.0)
    throw InputError(
        where(name, t.row_lines.front(), "BlSpn", "must start at 0 (is " + numberText(b.BlSpn.front()) + ")"));
  for (std::size_t r = 1; r < t.rows(); ++r)
    if (!(b.BlSpn[r] > b.BlSpn[r - 1]))
      throw InputError(where(name, t.row_lines[r], "BlSpn",
                             "must increase from node to node (" + numberText(b.BlSpn[r]) + " after " +
                                 numberText(b.BlSpn[r - 1]) + ")"));
  requirePositiveColumn(t, "BlChord");
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double id = t.column("BlAFID")[r];
    if (id != std::floor(id) || id < 1.0 || id > 1.0e6)
      throw InputError(where(name, t.row_lines[r], "BlAFID",
                             "must be a whole number >= 1 (an index into AFNames), is " + numberText(id)));
    b.BlAFID.push_back(static_cast<int>(id));
  }
  // Without the column AeroDyn computes the angle from the prebend (AeroDyn_IO.f90: ReadBladeInputs,
  // calcCrvAngle), once BlSpn is known to increase.
  if (!b.has_BlCrvAng) b.BlCrvAng = aeroDynCurveAngles(b);
  return b;
}

}  // namespace whirl::io

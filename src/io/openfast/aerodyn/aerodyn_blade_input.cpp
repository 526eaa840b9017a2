#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"

#include <cmath>

#include "src/base/error.hpp"
#include "src/io/openfast/distributed_table.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {

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
  b.BlCrvAng = b.has_BlCrvAng ? t.column("BlCrvAng") : std::vector<double>(t.rows(), 0.0);

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
  return b;
}

}  // namespace whirl::io

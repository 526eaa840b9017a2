#include "src/io/openfast/aerodyn/inflowwind_input.hpp"

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {

InflowWindInput readInflowWind(const std::filesystem::path& file, OverrideSet* overrides) {
  InflowWindInput w;
  w.source = OpenFastFile::read(file);
  w.source.checkLayout(inflowWindLayout());
  if (overrides) overrides->applyTo(w.source);
  const OpenFastFile& f = w.source;

  w.WindType = f.getInt("WindType");
  w.PropagationDir = f.getDouble("PropagationDir");
  w.has_VFlowAng = f.has("VFlowAng");
  // `default` is 0 (InflowWind_Subs.f90, InflowWind_ParseInputFileInfo: ParseVarWDefault "VFlowAng", 0.0).
  w.VFlowAng = f.findDoubleOr("VFlowAng", 0.0).value_or(0.0);
  w.HWindSpeed = f.getDouble("HWindSpeed");
  w.RefHt = f.getDouble("RefHt");
  w.PLExp = f.getDouble("PLExp");
  requireNonnegative(f, "HWindSpeed", w.HWindSpeed);
  if (w.HWindSpeed > limits::kMaxWindSpeed)
    throw InputError(f.where("HWindSpeed", "is " + numberText(w.HWindSpeed) + " m/s, above the limit of " +
                                               numberText(limits::kMaxWindSpeed) +
                                               " m/s (the aerodynamics are incompressible)"));
  requirePositive(f, "RefHt", w.RefHt);
  return w;
}

}  // namespace whirl::io

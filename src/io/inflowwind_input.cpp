#include "src/io/inflowwind_input.hpp"

#include "src/io/elastodyn_common.hpp"
#include "src/io/openfast_overrides.hpp"

namespace whirl::io {

InflowWindInput read_inflowwind(const std::filesystem::path& file, OverrideSet* overrides) {
  InflowWindInput w;
  w.source = OpenFastFile::read(file);
  if (overrides) overrides->apply_to(w.source);
  const OpenFastFile& f = w.source;

  w.WindType = f.get_int("WindType");
  w.PropagationDir = f.get_double("PropagationDir");
  w.has_VFlowAng = f.has("VFlowAng");
  w.VFlowAng = f.find_double("VFlowAng").value_or(0.0);
  w.HWindSpeed = f.get_double("HWindSpeed");
  w.RefHt = f.get_double("RefHt");
  w.PLExp = f.get_double("PLExp");
  require_nonnegative(f, "HWindSpeed", w.HWindSpeed);
  require_positive(f, "RefHt", w.RefHt);
  return w;
}

}  // namespace whirl::io

#include "src/io/openfast/offshore/seastate_input.hpp"

#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// A water property: nullopt when absent or `default` (SeaState_Input.f90, SeaSt_ParseInput:
/// ParseVarWDefault with the glue code's value, i.e. the .fst's).
std::optional<double> waterProperty(const OpenFastFile& f, const char* key) {
  return f.isDefault(key) ? std::nullopt : f.findDouble(key);
}

}  // namespace

SeaStateInput readSeaState(const std::filesystem::path& file, OverrideSet* overrides) {
  SeaStateInput s;
  s.source = OpenFastFile::read(file);
  s.source.checkLayout(seaStateLayout());
  if (overrides) overrides->applyTo(s.source);
  const OpenFastFile& f = s.source;
  s.WtrDens = waterProperty(f, "WtrDens");
  s.WtrDpth = waterProperty(f, "WtrDpth");
  s.MSL2SWL = waterProperty(f, "MSL2SWL");
  if (s.WtrDens) requirePositive(f, "WtrDens", *s.WtrDens);
  if (s.WtrDpth) requirePositive(f, "WtrDpth", *s.WtrDpth);
  // WaveMod may carry a phase ("1P0.0"): any value but 0 means waves.
  if (const OpenFastEntry* e = f.find("WaveMod"); e && e->raw != "0")
    s.notes.push_back(f.where("WaveMod", "incident waves ignored: the linearization is about still water"));
  if (f.findInt("CurrMod").value_or(0) != 0)
    s.notes.push_back(f.where("CurrMod", "current ignored: the linearization is about still water"));
  return s;
}

}  // namespace whirl::io

#include "src/io/openfast/openfast_turbine.hpp"

#include <algorithm>

#include "src/base/error.hpp"
#include "src/io/openfast/offshore/moordyn_input.hpp"
#include "src/io/openfast/openfast_support.hpp"

namespace whirl::io {

namespace {

/// HydroDyn and, in OpenFAST v4+ decks, the SeaState file that holds the water properties and waves.
void readHydro(OpenFastTurbine& t, OverrideSet* overrides) {
  if (t.fst.CompHydro != 1) return;
  if (t.fst.CompSeaSt == 1) t.seastate = readSeaState(t.fst.source.getExistingPath("SeaStFile"), overrides);
  t.hydrodyn = readHydroDyn(t.fst.source.getExistingPath("HydroFile"), overrides);
}

}  // namespace

OpenFastTurbine readOpenFastTurbine(const std::filesystem::path& fst, OverrideSet* overrides) {
  OpenFastTurbine t;
  t.fst = readFst(fst, overrides);
  t.elastodyn = readElastoDyn(t.fst.source.getExistingPath("EDFile"), overrides);
  if (t.fst.CompElast == 2)
    for (int k = 1; k <= t.elastodyn.config.NumBl; ++k) {
      const std::filesystem::path p = t.fst.source.getExistingPath("BDBldFile(" + std::to_string(k) + ")");
      // Blades sharing a file (the usual deck) read it once.
      const auto same = std::find_if(t.beamdyn.begin(), t.beamdyn.end(),
                                     [&](const BeamDynInput& b) { return b.source.path() == p; });
      t.beamdyn.push_back(same != t.beamdyn.end() ? *same : readBeamDyn(p, overrides));
    }
  if (t.fst.CompSub == 1) {
    // A mooring on a SubDyn substructure is refused by requireSupported, unread.
    t.subdyn = readSubDyn(t.fst.source.getExistingPath("SubFile"), overrides);
    readHydro(t, overrides);
  } else if (hasPlatformDofs(t.elastodyn)) {
    readHydro(t, overrides);
    if (t.fst.CompMooring == 1) t.mooring = readMap(t.fst.source.getExistingPath("MooringFile"));
    if (t.fst.CompMooring == 3) t.mooring = readMoorDyn(t.fst.source.getExistingPath("MooringFile"));
  }
  return t;
}

std::optional<ServoDynInput> readServoDynIfEnabled(const FstInput& fst, OverrideSet* overrides) {
  if (fst.CompServo == 0) return std::nullopt;
  const OpenFastFile& f = fst.source;
  const char* key = f.has("ServoFile") || !f.has("SrvDFile") ? "ServoFile" : "SrvDFile";
  return readServoDyn(f.getExistingPath(key), overrides);
}

double gravity(const OpenFastTurbine& turbine) {
  if (turbine.fst.Gravity) return *turbine.fst.Gravity;
  if (turbine.elastodyn.Gravity) return *turbine.elastodyn.Gravity;
  throw InputError(where(turbine.fst.source.path().string(), 0, "Gravity",
                         "not in this file nor in " + turbine.elastodyn.source.path().string()));
}

}  // namespace whirl::io

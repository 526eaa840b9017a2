#include "src/io/openfast_turbine.hpp"

#include "src/io/openfast_support.hpp"
#include "src/model/error.hpp"

namespace whirl::io {

OpenFastTurbine read_openfast_turbine(const std::filesystem::path& fst, OverrideSet* overrides) {
  OpenFastTurbine t;
  t.fst = read_fst(fst, overrides);
  t.elastodyn = read_elastodyn(t.fst.source.get_existing_path("EDFile"), overrides);
  if (t.fst.CompSub == 1) {
    // HydroDyn and moorings on a SubDyn substructure are refused by require_supported, unread.
    t.subdyn = read_subdyn(t.fst.source.get_existing_path("SubFile"), overrides);
  } else if (has_platform_dofs(t.elastodyn)) {
    if (t.fst.CompHydro == 1) t.hydrodyn = read_hydrodyn(t.fst.source.get_existing_path("HydroFile"), overrides);
    if (t.fst.CompMooring == 1) t.mooring = read_map(t.fst.source.get_existing_path("MooringFile"));
  }
  return t;
}

std::optional<ServoDynInput> read_servodyn_if_enabled(const FstInput& fst, OverrideSet* overrides) {
  if (fst.CompServo == 0) return std::nullopt;
  const OpenFastFile& f = fst.source;
  const char* key = f.has("ServoFile") || !f.has("SrvDFile") ? "ServoFile" : "SrvDFile";
  return read_servodyn(f.get_existing_path(key), overrides);
}

double gravity(const OpenFastTurbine& turbine) {
  if (turbine.fst.Gravity) return *turbine.fst.Gravity;
  if (turbine.elastodyn.Gravity) return *turbine.elastodyn.Gravity;
  throw InputError(where(turbine.fst.source.path().string(), 0, "Gravity",
                         "not in this file nor in " + turbine.elastodyn.source.path().string()));
}

}  // namespace whirl::io

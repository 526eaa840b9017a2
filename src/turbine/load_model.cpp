// loadCaseModel: the YAML case reader or the OpenFAST deck, by the file's extension.
#include "src/turbine/load_model.hpp"

#include <filesystem>

#include "src/base/error.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {

bool isYamlCasePath(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

Model loadCaseModel(const std::string& path, const std::vector<std::string>& sets, bool allow_outside_files,
                    std::vector<std::string>* notes) {
  Model m;
  if (isYamlCasePath(path)) {
    std::vector<CaseOverride> overrides;
    for (const auto& s : sets) overrides.push_back(parseOverride(s));
    m = readCase(path, overrides, nullptr, allow_outside_files);
  } else {
    ElastoDynModelOptions eo;
    const io::OpenFastTurbine t = readElastoDynTurbine(path, sets, eo);
    m = buildElastoDynModel(t, eo);
    // Inputs read and left out or replaced (HydroDyn or SeaState waves and currents, AeroDyn's time-domain
    // options, SubDyn's SSIfile on a locked joint): the caller says them, one line each.
    if (notes) {
      if (t.hydrodyn) notes->insert(notes->end(), t.hydrodyn->notes.begin(), t.hydrodyn->notes.end());
      if (t.seastate) notes->insert(notes->end(), t.seastate->notes.begin(), t.seastate->notes.end());
      if (eo.aero) notes->insert(notes->end(), eo.aero->notes.begin(), eo.aero->notes.end());
      if (t.subdyn) notes->insert(notes->end(), t.subdyn->notes.begin(), t.subdyn->notes.end());
    }
  }
  // Every caller linearizes the model: refuse an empty state before any work or output.
  requireActiveDof(m, path);
  return m;
}

void applyUnsteadyAeroChoice(Model& m, UnsteadyAeroChoice choice, const std::string& path,
                             std::vector<std::string>* notes, bool linear_model) {
  if (choice == UnsteadyAeroChoice::required && uaStateCount(m.aero) == 0)
    throw InputError(path +
                     ": --unsteady-aero: the deck's AeroDyn has no unsteady-airfoil states to add (UA_Mod 4 or 6 "
                     "on an element inside UAStartRad…UAEndRad; an older AeroDyn file: --set AFAeroMod=2 --set "
                     "UAMod=4)");
  if (choice == UnsteadyAeroChoice::off) {
    removeUnsteadyAirfoils(m.aero);
    removeDynamicInflow(m.aero);
  }
  // The states are in the linear model only where the model has some (UA_Mod 4 or 6 on some element;
  // DBEMT_Mod 3 with the BEM induction).
  if (!notes || !linear_model) return;
  if (uaStateCount(m.aero) > 0) std::erase_if(*notes, io::isUnsteadyAirfoilNote);
  if (inflowStateCount(m.aero) > 0) std::erase_if(*notes, io::isDynamicInflowNote);
}

}  // namespace whirl

// loadCaseModel: the YAML case reader or the OpenFAST deck, by the file's extension.
#include "src/turbine/load_model.hpp"

#include <filesystem>

#include "src/io/case/case_file.hpp"
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

}  // namespace whirl

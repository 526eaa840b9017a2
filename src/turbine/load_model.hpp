#pragma once
/// \file
/// A model from a case path, as every model-taking command loads it: a YAML case file (.yaml, .yml)
/// or an OpenFAST .fst / ElastoDyn .dat deck, with `--set KEY=VALUE` overrides applied before the
/// model is built. Shared by the command line (src/cli/common.cpp) and the Python module
/// (python/src/), so both build the same model from the same inputs.
#include <string>
#include <vector>

#include "src/model/model.hpp"

namespace whirl {

/// True for a YAML case path (.yaml, .yml), false for OpenFAST / ElastoDyn files.
bool isYamlCasePath(const std::string& path);

/// Loads the case at `path` with the overrides `sets` ("key=value": a dotted path of the YAML case, or
/// an OpenFAST key; gravity=G for both).
/// \param[in]  allow_outside_files  a YAML case's `file:` entries may name files outside its folder
/// \param[out] notes  when given, the informational lines of the OpenFAST readers (HydroDyn inputs
///                    left out, AeroDyn options replaced, SubDyn inputs ignored), without prefix
/// \throws InputError "file:line: key: reason" for bad input, and for a model without an active DOF
///         (every caller linearizes it).
Model loadCaseModel(const std::string& path, const std::vector<std::string>& sets, bool allow_outside_files = false,
                    std::vector<std::string>* notes = nullptr);

}  // namespace whirl

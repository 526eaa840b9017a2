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

/// Which aerodynamic states (unsteady airfoil: AeroDyn's UA_Mod 4 or 6; dynamic inflow: DBEMT_Mod 3;
/// docs/theory/unsteady-aero.md) a model's linearizations carry: the command line's --unsteady-aero /
/// --quasi-steady-aero, the Python module's `unsteady_aero=True/False`.
enum class UnsteadyAeroChoice {
  as_deck,   ///< the states where the deck's AeroDyn asks for them (default)
  required,  ///< as the deck asks, and a model without any such state is refused
  off,       ///< quasi-steady: the elements' UA and DBEMT data removed (static polar, frozen wake)
};

/// Applies `choice` to a model loaded from `path`. With `linear_model` (the caller builds linear models)
/// and states left in the model, the reader's notes that they are left out are dropped from `notes`.
/// \throws InputError "PATH: --unsteady-aero: the deck's AeroDyn has no unsteady-airfoil states to add …"
///   for `required` on a model without an element with states.
void applyUnsteadyAeroChoice(Model& m, UnsteadyAeroChoice choice, const std::string& path,
                             std::vector<std::string>* notes, bool linear_model);

}  // namespace whirl

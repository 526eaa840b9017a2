#pragma once
/// \file
/// The YAML case-file reader: a case (schema: cases/README.md) → a finalized whirl::Model.
///
/// Every problem in the file is reported as an InputError with one line
/// "file:line: key: reason", where key is the dotted path of the value (list entries by their
/// `name`, e.g. `bodies.tower.uniform.EIy`) and line is 1-based.
#include <string>
#include <vector>

#include "src/fem/shape_comparison.hpp"
#include "src/model/model.hpp"

namespace whirl {

/// One `--set key=value`: key is a dotted path into the case, value the new text.
struct CaseOverride {
  std::string key, value;
};

/// Splits "key=value" at the first '='.
/// \throws InputError when there is no '=', the key or the value is empty, or a path segment is empty.
CaseOverride parseOverride(const std::string& text);

/// Reads the YAML case at `path`, applies the overrides, builds the bodies (rigid:
/// rigidBodyInertia; beam: buildBeamBody + beamPoint), joints, DOFs (names from joint `dof`/`dofs`
/// and shape names, settings from `dofs:`), inputs and loads, then calls finalize().
///
/// \param[in] path       the case file; relative files inside it (property and shape CSV files) are
///                       relative to its folder.
/// \param[in] overrides  applied in order before anything is read. Keys are dotted paths; list
///                       entries are addressed by their `name` (or, without a name, their index
///                       from 0). A missing map key is added and then checked like any key written
///                       in the file; a list entry that does not exist is an error.
/// \return the finalized model.
/// \throws InputError "file:line: key: reason" for anything wrong in the file or the overrides.
/// \param[out] beams    when given, the case's `beam` bodies as FE inputs with their shapes (`whirl shapes`).
/// \param[in] allow_outside_files  false (default): a `file:` entry must name a file under the case
///                       folder (no absolute path, no `..` or symbolic link leading out of it).
Model readCase(const std::string& path, const std::vector<CaseOverride>& overrides = {},
               std::vector<fem::FlexibleBeam>* beams = nullptr, bool allow_outside_files = false);

/// The same from the YAML text of a case (the Python module's `whirl.from_dict`: no file written).
/// \param[in] label   names the text in messages instead of a file ("<dict>")
/// \param[in] folder  where the case's `file:` entries are looked up, as a case file's own folder
Model readCaseText(const std::string& text, const std::string& label, const std::string& folder,
                   const std::vector<CaseOverride>& overrides = {}, bool allow_outside_files = false);

}  // namespace whirl

#pragma once
/// \file
/// State-space models written for controller design tools (exact layouts and the tools that read
/// them: docs/user/export-formats.md):
/// - MATLAB .mat (matio, level 5): ROSCO's linear-model layout for one or many operating points
///   (1 × n cell arrays A, B, C, D, x_ops, u_ops, y_ops, the index vectors indInps/indOuts, the
///   operating-point rows, names, units and OpenFAST's channel texts).
/// - OpenFAST `.lin` text, one file per azimuth, in OpenFAST's layout (FAST_Lin.f90): its header,
///   input order, descriptions and output units (src/writers/lin_channels.hpp); readable by
///   readOpenFastLin, openfast_toolbox's FASTLinearizationFile and MBC3, ROSCO's readFASTMatrix.
/// - JSON with the same content.
#include <optional>
#include <string>
#include <vector>

#include "linearize/export_point.hpp"
#include "src/writers/output_set.hpp"

namespace whirl {

/// Writes the .mat file at `path` (the caller stages it; see staged_files.hpp). InputError on failure.
void writeStateSpaceMat(const StateSpaceExport& e, const std::string& path);

/// Text of one `.lin` file for model `m` (its variables must carry rotating-frame blades, i.e. not
/// a multiblade model); `title` goes to the description line.
std::string linFileText(const StateSpaceModel& m, const std::string& title);

/// JSON text of the whole export.
std::string stateSpaceJson(const StateSpaceExport& e);

/// True when every displacement state is an ElastoDyn-equivalent DOF ("tower FA 1", "blade 2 flap 1",
/// "generator azimuth", "drivetrain", "yaw", …).
bool elastoDynStates(const std::vector<StateSpaceVariable>& states);

/// OpenFAST description of state `x` of `all`: ElastoDyn's wording ("ED 1st tower fore-aft bending-mode
/// DOF (internal DOF index = DOF_TFA1), m") when `elastodyn`, so OpenFAST tools (ROSCO, MBC3) recognize
/// them; "whirl <name>, <unit>" otherwise (the azimuth marked "DOF_GeAz" as OpenFAST does). One prefix
/// for all states keeps them one module, which is how readers pair displacements with rates.
std::string linStateDescription(const StateSpaceVariable& x, const std::vector<StateSpaceVariable>& all,
                                bool elastodyn);

/// The files of `whirl export` into `files`: `statespace.mat` (format "mat"), `statespace.json`
/// ("json"), or one OpenFAST-style `.lin` file per azimuth ("lin"; `statespace.<k>.lin` for one
/// operating point, `statespace_<jj>.<k>.lin` for several; a time-invariant model is azimuth 1).
/// `title` goes in the `.lin` headers.
void writeStateSpaceFiles(const StateSpaceExport& e, const std::string& format, const std::string& title,
                          OutputSet& files);

}  // namespace whirl

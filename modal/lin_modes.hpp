#pragma once
/// \file
/// Modes of OpenFAST `.lin` files, the library half of `whirl lin`: the files grouped by operating
/// point (rotor speed, wind speed), the multiblade transform over each group's azimuths [Bir2008],
/// the modes named as for a whirl model (modal/rotor_modes.hpp). Reading the files and writing the
/// results stay with the caller.
#include <string>
#include <vector>

#include "modal/campbell.hpp"
#include "modal/mbc_lin.hpp"
#include "modal/rotor_modes.hpp"
#include "src/io/lin/openfast_lin.hpp"

namespace whirl {

/// The coordinates of a `.lin` file: its displacement states (a rate state, wherever it sits, joins
/// its displacement: MbcLayout::velocity_of) and its first-order states, in state order, named from
/// their descriptions (src/io/lin/openfast_lin_names.hpp). A `.lin` file has no mass matrix: the modes
/// are named from participation factors (modal/participation.hpp).
RotorCoordinates linRotorCoordinates(const OpenFastLin& lin, const MbcLayout& layout);

/// The root name of a file named by OpenFAST's convention `<root>.<k>.lin` (path included:
/// "out/ws03.0.12.lin" → "out/ws03.0"), empty for any other name.
std::string linRootName(const std::string& path);

/// Files grouped by operating point: files of one root name (linRootName; the files without one form
/// a root of their own) whose rotor speeds agree within `tolerance` relative to the larger one (floor
/// 1e-3 rad/s) and wind speeds likewise (floor 1e-2 m/s). Groups in order of rotor speed then wind
/// speed, files of a group in the order given.
/// \throws InputError for a file without an A matrix, or one with the operating point and azimuth
///         (within 1e-6 rad) of an earlier file of its group: a repeated azimuth would bias the
///         multiblade average.
std::vector<std::vector<OpenFastLin>> groupLinByOperatingPoint(std::vector<OpenFastLin> files, double tolerance = 1e-3);

/// The warning for a group of a turning rotor with fewer than 3 azimuths (the multiblade transform
/// needs 3 [Bir2008]); empty when there are enough, or the rotor is parked (one file is exact).
std::string fewAzimuthsWarning(const std::vector<OpenFastLin>& group);

/// The named modes of one operating point's files (its azimuths): rpm and wind speed from the first
/// file's header. Rotating outputs that do not pair across blades are left out of the transform
/// (mbcLayoutFromLin) and named in one line appended to `notes` (when given).
/// \throws InputError when a file's states differ in number from the first file's.
CampbellPoint linCampbellPoint(const std::vector<OpenFastLin>& group, std::vector<std::string>* notes = nullptr);

}  // namespace whirl

#pragma once
/// \file
/// The keys each OpenFAST module's input file can hold, over the versions whirl reads (FAST v8.16,
/// OpenFAST v2.x to v5), for OpenFastFile::checkLayout: a key given twice or a key no version writes in
/// that file is refused with `file:line: key: reason` (OpenFAST reads these files by position, so an
/// extra or repeated line shifts every later value; whirl reads by key and would silently disagree).
///
/// The lists are the labels of OpenFAST's own readers (the `ParseVar`/`ReadVar` calls of the files named
/// at each function, at the tags v2.6.0, v3.0.0, v3.5.5, v4.0.5, v4.2.1, v5.0.0 of OpenFAST/openfast)
/// and the changes listed in OpenFAST's docs/source/user/api_change.rst. A key in a list is not
/// necessarily read by whirl: docs/user/openfast-modules.md says, per module, which keys whirl reads,
/// which it ignores and which values it refuses.
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

/// AeroDyn v15 primary file (modules/aerodyn/src/AeroDyn_IO.f90, ParsePrimaryFileInfo).
const OpenFastLayout& aeroDynLayout();
/// AeroDyn v15 blade file (AeroDyn_IO.f90, ReadBladeInputs): `NumBlNds` and the node table.
const OpenFastLayout& aeroDynBladeLayout();
/// AeroDyn airfoil file (modules/aerodyn/src/AirfoilInfo.f90, ParseAFFile): `Re` … `NumAlf` repeat per table.
const OpenFastLayout& airfoilLayout();
/// InflowWind primary file (modules/inflowwind/src/InflowWind_Subs.f90, InflowWind_ParseInputFileInfo).
const OpenFastLayout& inflowWindLayout();
/// HydroDyn primary file, v2 (FAST v8) to v5 (modules/hydrodyn/src/HydroDyn_Input.f90, HydroDyn_ParseInput).
const OpenFastLayout& hydroDynLayout();
/// SeaState primary file, OpenFAST v4+ (modules/seastate/src/SeaState_Input.f90, SeaSt_ParseInput).
const OpenFastLayout& seaStateLayout();
/// ServoDyn primary file (modules/servodyn/src/ServoDyn_IO.f90, ParseInputFileInfo; FAST v8's ServoDyn v1).
const OpenFastLayout& servoDynLayout();
/// The `.fst` primary file (modules/openfast-library/src/FAST_Subs.f90, FAST_ReadPrimaryFile).
const OpenFastLayout& fstLayout();

}  // namespace whirl::io

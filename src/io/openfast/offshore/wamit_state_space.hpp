#pragma once
/// \file
/// HydroDyn's state-space wave-radiation model (`RdtnMod = 2`): the `<PotFile>.ss` file SS_Fitting
/// writes (Duarte, Sarmento & Alves 2013), as HydroDyn's SS_Rad_Init reads it:
///   line 1   title
///   line 2   6 flags: the DOFs (surge … yaw) the fit covers; HydroDyn needs all six
///   line 3   N, the number of states
///   line 4   6 counts: states per DOF, summing to N
///   then     A (N rows of N), B (N rows of 6), C (6 rows of N), dimensional (SI), nothing after,
/// so that ż = A z + B ẋ and the radiation load on the platform is C z (no sign or scaling added).
#include <array>

#include "src/base/types.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"

namespace whirl::io {

struct RadiationStateSpace {
  MatX A, B, C;                     ///< N × N, N × 6, 6 × N
  std::array<int, 6> per_dof = {};  ///< states per DOF, in state order
};

/// \throws InputError "file:line: reason" for a missing file, a flag that is not 1, N above
///         limits::kMaxRadiationStates or not the sum of the counts, a row with the wrong count of
///         numbers or a number that is not finite, rows missing or left over.
RadiationStateSpace readRadiationStateSpace(const HydroDynInput& hd);

}  // namespace whirl::io

#pragma once
/// \file
/// ServoDyn input file: only the nacelle-yaw spring and damper matter to a structural model.
#include <filesystem>

#include "src/io/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// Yaw spring/damper of a ServoDyn file, in the file's units (YawNeut in degrees).
struct ServoDynInput {
  OpenFastFile source;   ///< the parsed file (path, line of every key: source.where(key, reason))
  int YCMode = 0;        ///< yaw control mode {0 none, 3 user routine, 4 Simulink, 5 DLL} (switch)
  double YawNeut = 0.0;  ///< neutral yaw position: the yaw spring moment is zero there (deg)
  double YawSpr = 0.0;   ///< nacelle-yaw spring constant (N·m/rad)
  double YawDamp = 0.0;  ///< nacelle-yaw damping constant (N·m/(rad/s))
};

/// Reads the yaw keys of a ServoDyn file (YawSpr and YawDamp must not be negative).
/// Throws InputError naming file, line and key.
ServoDynInput read_servodyn(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io

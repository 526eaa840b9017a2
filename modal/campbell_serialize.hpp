#pragma once
/// \file
/// A Campbell point as bytes (CBOR through nlohmann::json), so a point computed on one MPI rank
/// arrives on rank 0 exactly as computed: doubles travel as their 8 bytes, never as text.
#include <string>

#include "modal/campbell.hpp"

namespace whirl {

std::string encodeCampbellPoint(const CampbellPoint& point);

/// Throws ComputeError on bytes that are not an encoded CampbellPoint.
CampbellPoint decodeCampbellPoint(const std::string& bytes);

}  // namespace whirl

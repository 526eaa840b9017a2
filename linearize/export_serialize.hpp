#pragma once
/// \file
/// An exported operating point as bytes (CBOR through nlohmann::json), so a point computed on one
/// MPI rank arrives on rank 0 exactly as computed. Every double (matrices, operating-point values,
/// scalars) travels as its 8 bytes in a CBOR byte string, little-endian: nlohmann's own float
/// encoding would keep the value but not a NaN's payload, and byte strings are compact and fast.
#include <string>

#include "linearize/export_point.hpp"

namespace whirl {

std::string encodeExportPoint(const ExportPoint& point);

/// Throws ComputeError ("export point: corrupt result bytes (…)") on bytes that are not an encoded
/// ExportPoint (truncated, altered, another type).
ExportPoint decodeExportPoint(const std::string& bytes);

}  // namespace whirl

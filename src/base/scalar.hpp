#pragma once
/// \file
/// Scalar types the equations are instantiated for: double, and forward-mode AD with a fixed-size
/// chunk of derivative directions: no heap allocation per operation, 8 directions a pass (AD
/// performance recipe, docs/dev/architecture.md).
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace whirl {

inline constexpr int kChunk = 8;
using ADChunk = Eigen::AutoDiffScalar<Eigen::Matrix<double, kChunk, 1>>;

/// Value of a scalar, whatever its type.
inline double valueOf(double x) { return x; }
inline double valueOf(const ADChunk& x) { return x.value(); }

}  // namespace whirl

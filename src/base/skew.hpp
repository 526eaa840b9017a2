#pragma once
/// \file
/// The cross-product matrix, used by the equations (any scalar) and the finite elements (double).
#include "src/base/types.hpp"

namespace whirl {

/// Skew matrix: skew(a) b = a × b (3 × 3, same frame as a).
template <class T>
Mat3T<T> skew(const Vec3T<T>& a) {
  Mat3T<T> s;
  s << T(0), -a(2), a(1), a(2), T(0), -a(0), -a(1), a(0), T(0);
  return s;
}

}  // namespace whirl

#pragma once
/// \file
/// Gauss–Legendre quadrature: ∫₋₁¹ f dx ≈ Σ w_i f(x_i), exact for polynomials of degree 2n − 1.
#include "src/base/types.hpp"

namespace whirl {

/// \param[in]  n  number of points, n ≥ 1
/// \param[out] x  the n nodes on [−1, 1], ascending
/// \param[out] w  their weights (n), summing to 2
void gaussLegendre(int n, VecX& x, VecX& w);

}  // namespace whirl

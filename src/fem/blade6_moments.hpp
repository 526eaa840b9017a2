#pragma once
/// \file
/// Bending moments of an FE blade (blade6_body.hpp) per modal coordinate, from the FE model's own
/// stress resultants rather than from the tabulated shapes' second differences: the modes are known at
/// the nodes only, and the second difference of the displacements at a clamped root gives about half
/// the moment (measured: a uniform cantilever's first mode, 20 elements, 4.09e6 against the exact
/// 8.79e6 N m per metre of tip deflection).
#include "src/fem/blade6_body.hpp"

namespace whirl::fem {

/// The elastic bending moment at the station x [m] along the body's x (0 ≤ x ≤ length) per modal
/// coordinate (2 × modes, body frame, the convention of beamMomentGains, src/shapes/beam_moment.hpp):
/// row 0 the moment that bends the blade towards +y (about body z), row 1 towards +z (about −y).
/// The element holding x gives its section resultant at its middle, σ = C B v_e (reduced integration,
/// element6.hpp), carried to x by the element's equilibrium, M(s) = M_mid − (s − s_mid) t × F (no
/// distributed load within an element): exact for the FE model, converging as the mesh does.
MatX blade6MomentGains(const Blade6Body& blade, double x);

}  // namespace whirl::fem

#pragma once
/// \file
/// Bending moments of a Rayleigh–Ritz beam from its elastic curvature (Euler–Bernoulli), consistent
/// with the stiffness of [Branlard2019, eq. 20]: at station x, with the curvatures rotated into the
/// principal axes by the structural twist θ,
///   κ1 = cos θ u_y'' + sin θ u_z'',  κ2 = −sin θ u_y'' + cos θ u_z'',  m1 = EIy κ1,  m2 = EIz κ2,
/// and back to body axes: m_y = cos θ m1 − sin θ m2, m_z = sin θ m1 + cos θ m2, u'' = Σ_j φ_j''(x) q_j.
/// m_y [N m] is the moment that bends the beam towards +y (the moment vector about body +z), m_z the
/// one towards +z (about body −y). These are the elastic (internal) moments of the truncated Ritz
/// series, not reaction loads: a few shapes reproduce them less well than the deflections, and
/// stiffness tuners applied to the generalized stiffness afterwards do not enter them.
#include <vector>

#include "src/shapes/beam.hpp"

namespace whirl {

/// Gains G (2 × ne): (m_y, m_z) = G q_e at station x.
MatX beamMomentGains(const BeamProperties& props, const std::vector<ShapePtr>& shapes, double x);

}  // namespace whirl

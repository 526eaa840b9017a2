#pragma once
/// \file
/// A point of a beam moved off its axis on a rigid arm that turns with the section.
#include "src/model/body.hpp"

namespace whirl {

/// Moves the beam point `pt` (src/shapes/beam.hpp: beamPoint) by the arm `d` [m, body frame] that turns
/// with the section: P's position column gains d, each shape column θ_k × d — OpenFAST's line2-to-line2
/// mesh mapping from AeroDyn's nodes to BeamDyn's axis. A force at the arm's end then loads the torsion
/// shapes, and the section's twist moves the point. The shortening columns stay those of the axis
/// (second order in q and d).
void offsetOnRigidArm(BodyPoint& pt, const Vec3& d);

}  // namespace whirl

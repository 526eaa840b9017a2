#pragma once
/// \file
/// The fluid in HydroDyn's filled members (fill groups: flooding or water ballast) as the HydroDyn of
/// the OpenFAST certification decks (v2.03) carries it into a linearization: a translational mass
/// ρ_f π (R − t)² per unit length along each member's axis, from its lower end up to the group's free
/// surface FillFSLoc, moving with the platform (its loads −m a at the member nodes); and its weight, a
/// constant load that does not turn with the platform. HydroDyn leaves the ballast's gravity
/// restoring −m_f g z_f out of its loads: the decks carry it in AddCLin (HydroDyn manual, "hydrostatic
/// restoring for strip-theory members"; Jonkman on the OC4 semi's AddCLin(4,4) and (5,5)), so whirl
/// must not add it a second time.
#include <Eigen/Core>

#include "src/base/types.hpp"
#include "src/io/openfast/offshore/hydrodyn_members.hpp"

namespace whirl::elastodyn {

struct Ballast {
  double mass = 0.0;           ///< fluid mass (kg)
  Vec3 centre = Vec3::Zero();  ///< its centre of mass (m, HydroDyn global frame)
  /// Rigid-body mass matrix about `origin`, [translation; rotation] (kg, kg m, kg m²).
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  /// The weight as a load about `origin`: (0, 0, −m g, −m g y, m g x, 0) with (x, y) the centre from it.
  Eigen::Matrix<double, 6, 1> weight = Eigen::Matrix<double, 6, 1>::Zero();
};

/// The fluid of every fill group; FillDens = DEFAULT takes `water_density` (kg/m³); g (m/s²) > 0;
/// M and weight about `origin` (the platform reference point, HydroDyn global frame). Integrated
/// exactly over each member (inner radius linear between its two property sets).
Ballast ballastOf(const io::HydroDynMembers& m, double water_density, double g, const Vec3& origin);

}  // namespace whirl::elastodyn

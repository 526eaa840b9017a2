#pragma once
/// \file
/// A beam cross-section described by full 6 × 6 matrices (BeamDyn, VABS, BECAS, ANBA): stiffness C,
/// relating the sectional strains [γ; κ] to the stress resultants [F; M], and mass 𝓜, relating the
/// section's velocities [u̇; θ̇] to its momenta [p; h] [Hodges2006, ch. 4; Wang2017, eqs. 9, 13].
///
/// Ordering and frame: three translational/force components, then three rotational/moment
/// components, all along the same three axes. In a section frame (BeamDyn's) axes 1, 2 lie in the
/// section and 3 along the beam axis, so index 2 (0-based) is extension and 5 torsion; in whirl's
/// body frame of a blade (x along the span) index 0 is extension and 3 torsion. Changing axes by
/// a rotation R (columns: the old axes in the new frame) is C' = T C Tᵀ, T = blockdiag(R, R).
///
/// The mass matrix of a rigid section is 𝓜 = [m 1, −m c̃; m c̃, J]: m the mass per length [kg/m],
/// c the mass centre from the reference axis [m] (c̃ its skew matrix), J the inertia per length about
/// the reference axis [kg m] (BeamDyn's i_Edge, i_Flap, i_plr and i_cp).
#include <Eigen/Dense>

#include "src/base/types.hpp"

namespace whirl::fem {

using Mat6s = Eigen::Matrix<double, 6, 6>;

struct Section6 {
  Mat6s C = Mat6s::Zero();  ///< stiffness [N (shear, axial), N m (couplings), N m² (bending, torsion)]
  Mat6s M = Mat6s::Zero();  ///< mass [kg/m, kg, kg m]
  /// Damping: resultants per strain rate [N s, …] (BeamDyn's stiffness-proportional μ: diag(μ) C in
  /// the section frame, Wang2017 §2.3; zero = none).
  Mat6s D = Mat6s::Zero();
};

/// The section in other axes: R has the section's axes as columns, in the new frame.
Section6 rotated(const Section6& s, const Mat3& R);

/// (1 − t) a + t b, entry by entry (BeamDyn interpolates its stations linearly along η).
Section6 lerp6(const Section6& a, const Section6& b, double t);

/// Mass, mass-centre offset and inertia about the mass centre of a mass matrix 𝓜 = [m 1, −m c̃; m c̃, J].
struct SectionMass {
  double m = 0;              ///< [kg/m]
  Vec3 c = Vec3::Zero();     ///< mass centre from the reference axis [m]
  Mat3 J_cm = Mat3::Zero();  ///< inertia about the mass centre [kg m]: J − m (|c|² 1 − c cᵀ)
};
SectionMass sectionMass(const Mat6s& M);

/// A section from isotropic engineering properties in its own axes (x along the beam, principal y, z),
/// mass centre and shear centre on the axis: diag(EA, κGA_y, κGA_z, GJ, EI_y, EI_z) and
/// diag(m, m, m, j_G, i_y, i_z). EI_y = bending of the deflection along z (curvature about y).
Section6 isotropicSection(double EA, double GAy, double GAz, double GJ, double EIy, double EIz, double m, double jx,
                          double iy, double iz);

}  // namespace whirl::fem

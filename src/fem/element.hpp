#pragma once
/// \file
/// One 3D two-node beam element (Euler–Bernoulli, or Timoshenko through the shear parameter Φ),
/// 6 DOF per node in the element frame: [u_x, u_y, u_z, θ_x, θ_y, θ_z] at node 1, then node 2.
///
/// Element frame: x from node 1 to node 2 (length L), y and z principal axes of the section.
/// Sign conventions follow whirl's beams (src/shapes/beam.hpp): θ_z = v' and θ_y = −w' for the
/// deflections v (along y) and w (along z) of an Euler–Bernoulli beam; EIy is the bending
/// stiffness of the deflection along y (curvature v''), EIz of the deflection along z.
/// Interpolation: linear for u_x and θ_x; for each bending plane the shear-deformable cubic of
/// Friedman & Kosmatka (Comput. Struct. 47(3), 1993), which is the Hermite cubic when Φ = 0, with
/// its own section-rotation field. The consistent mass, the Winkler (distributed spring) matrix and
/// the geometric stiffness are integrals of these fields (4-point Gauss, exact for properties linear
/// along the element).
#include <Eigen/Dense>

#include "src/base/types.hpp"

namespace whirl::fem {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat3x12 = Eigen::Matrix<double, 3, 12>;

/// Section properties at one end of an element (element frame), linear along the element.
struct Section {
  double m = 0;     ///< mass per length [kg/m]
  double EA = 0;    ///< axial stiffness [N]
  double EIy = 0;   ///< bending stiffness of the deflection along y [N m²]
  double EIz = 0;   ///< bending stiffness of the deflection along z [N m²]
  double GJ = 0;    ///< torsional stiffness [N m²]
  double iy2 = 0;   ///< ∫ y² dm per length [kg m]: rotary inertia of θ_z (bending along y)
  double iz2 = 0;   ///< ∫ z² dm per length [kg m]: rotary inertia of θ_y; iy2 + iz2 = polar j_G
  double kGAy = 0;  ///< shear stiffness along y [N] (Timoshenko; 0 = rigid in shear)
  double kGAz = 0;  ///< shear stiffness along z [N]
};

/// Shear parameters Φ = 12 EI / (κGA L²) of the two bending planes (0 for Euler–Bernoulli).
struct ShearParameters {
  double y = 0, z = 0;
};

/// Fields at one point ξ = x/L ∈ [0, 1] of the element, per element DOF (element frame).
struct ElementFields {
  Mat3x12 u;   ///< displacement [m per DOF unit]
  Mat3x12 du;  ///< d(displacement)/dx
  Mat3x12 th;  ///< small section rotations θ_x, θ_y, θ_z
};

ElementFields elementFields(double L, const ShearParameters& phi, double xi);

/// Shear parameters from the mean section (zero when timoshenko is false or κGA = 0).
ShearParameters shearParameters(double L, const Section& a, const Section& b, bool timoshenko);

/// Elastic stiffness, element frame (12 × 12), mean section properties (exact for uniform ones).
Mat12 elementStiffness(double L, const Section& a, const Section& b, const ShearParameters& phi);

/// Geometric stiffness per unit axial force (tension positive) [1/m]: ∫ (v'ᵀv' + w'ᵀw') dx.
/// The element's contribution to K is N × this ([Branlard2019, eq. 26] in finite-element form).
Mat12 elementGeometricStiffness(double L, const ShearParameters& phi);

/// Distributed (Winkler) springs per unit length k = (k_x, k_y, k_z) [N/m²] at both ends, linear
/// between: ∫ uᵀ diag(k) u dx (element frame).
Mat12 elementWinkler(double L, const ShearParameters& phi, const Vec3& k1, const Vec3& k2);

/// 4-point Gauss–Legendre on [0, 1].
struct Gauss4 {
  static constexpr double x[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
  static constexpr double w[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};
};

/// Linear interpolation of the section between the element ends.
Section lerp(const Section& a, const Section& b, double xi);

}  // namespace whirl::fem

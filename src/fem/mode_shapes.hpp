#pragma once
/// \file
/// Shape functions for Rayleigh–Ritz beams from distributed properties, by the beam FE of this folder
/// (what BModes does for ElastoDyn users): the lowest bending modes of a cantilever with a tip body,
/// optionally pre-stressed by the centrifugal load of a rotor or by gravity, returned as the project's
/// tabulated shapes (values, slopes, curvatures at the FE nodes), plus the least-squares fit to
/// ElastoDyn's mode-shape polynomial Σ_{k=2..6} a_k ξ^k with Σ a_k = 1.
///
/// Frame: the body frame of src/shapes/beam.hpp — x along the mean line from the root (clamped, x = 0)
/// to the tip (x = L), bending along body y and z. The FE model keeps [u_y, u_z, θ_y, θ_z] per node
/// (and θ_x when the section has GKt and jG), Euler–Bernoulli, structural twist turns each element's
/// principal axes about x (BeamProperties::twist), so twisted blades give coupled flap/edge modes.
#include <array>
#include <string>
#include <vector>

#include "src/shapes/beam.hpp"

namespace whirl::fem {

/// A rigid body at the tip (a tower-top nacelle and rotor, a blade tip mass).
struct TipBody {
  double mass = 0;              ///< [kg]
  Vec3 cm = Vec3::Zero();       ///< centre of mass from the tip node, body frame [m]
  Mat3 inertia = Mat3::Zero();  ///< inertia about the centre of mass, body axes [kg m²]
};

/// Everything the modes depend on besides the mesh.
struct ModeShapeInput {
  BeamProperties props;  ///< stations from 0 to L; m, EIy, EIz required; twist, GKt, jG optional
  TipBody tip;
  /// Rotor speed Ω [rad/s] about `rotation_axis` through the point x = −hub_radius of the body x axis
  /// (a blade on a hub): centrifugal tension N(x) = Ω² ∫ₓᴸ m (r_h + s) ds (+ tip body) stiffens bending
  /// [Branlard2019, eq. 21–27], and the in-plane direction softens by −Ω² m (the centrifugal field grows
  /// with the distance from the axis).
  double rotor_speed = 0;
  double hub_radius = 0;               ///< [m]
  Vec3 rotation_axis = Vec3::UnitY();  ///< body frame (normalized; its x component is ignored)
  /// Gravity along −x [m/s²] (a tower): compression N(x) = −g (∫ₓᴸ m ds + tip mass), softening.
  double axial_gravity = 0;
  int elements = 60;  ///< every property station is a node; intervals split into elements ≤ L/elements
};

/// One FE mode as a whirl shape.
struct BeamMode {
  char direction = 'y';  ///< dominant bending direction: 'y' or 'z'
  int index = 1;         ///< 1-based within its direction
  double freq_hz = 0;    ///< FE natural frequency [Hz]; 0 when ω² < 0 (buckled by the axial load)
  ShapeTable table;      ///< at the FE nodes; scaled to unit tip displacement along `direction`
  ShapePtr shape;        ///< tableShape(table)
};

/// Lowest `count_y` modes dominated by bending along y and `count_z` along z (torsion-dominated
/// modes are skipped), each normalized to +1 tip displacement in its direction.
/// \throws InputError for bad properties (validateBeam), ComputeError when the eigenproblem fails or
///         fewer modes than asked exist in a direction.
std::vector<BeamMode> beamModes(const ModeShapeInput& in, int count_y, int count_z);

/// ElastoDyn's 6th-order mode-shape polynomial u(ξ) = Σ_{k=2..6} a_k ξ^k, Σ a_k = 1, fitted by least
/// squares at equally spaced ξ = x/L (what BModes users paste into ElastoDyn files).
struct PolynomialFit {
  std::array<double, 5> coeffs{};  ///< a_2 … a_6
  double rms = 0;                  ///< RMS of (fit − shape) over the fit points [per unit tip]
  double max_deviation = 0;        ///< max |fit − shape| [per unit tip]
};

/// \param[in] xi stations ξ ∈ [0, 1] (n ≥ 5), \param[in] u values there (unit tip).
PolynomialFit fitElastoDynPolynomial(const VecX& xi, const VecX& u);

/// Fit of one direction of a shape of length L at `points` equally spaced stations.
PolynomialFit fitElastoDynPolynomial(const Shape& shape, double length, char direction, int points = 101);

/// Modal assurance criterion of two shapes over [0, L] (both y and z displacements, `points` equally
/// spaced stations): (a·b)² / (a·a)(b·b) ∈ [0, 1].
double shapeMac(const Shape& a, const Shape& b, double length, int points = 101);

/// max |a − b_scale·b| over the stations of both displacement components [m per unit tip].
double shapeMaxDeviation(const Shape& a, const Shape& b, double length, int points = 101, double b_scale = 1.0);

}  // namespace whirl::fem

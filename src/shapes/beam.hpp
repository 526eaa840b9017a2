#pragma once
/// \file
/// A thin flexible beam [Branlard2019, §4] turned into a whirl body: spanwise properties and shape
/// functions → shape integrals (mass, first moments, S_jl), elastic stiffness (eq. 20), damping,
/// and points (mean-line positions and small rotations) for children and loads.
///
/// Body frame: the mean line runs along +x from the root (x = 0) to the tip (x = L). Shapes
/// displace it along y and z and twist it about x. Mass sits on the COG line (mean line + COG
/// offset); torsion moves the COG by eq. 30 and the section's polar inertia j_G adds eq. 31 (rotary
/// inertia of the sections about the beam axis only, the thin-beam convention), or, when the full
/// section inertia J is given, the section turns as a rigid lamina about all three axes.
/// With axial shortening on, a bent beam's points move along x by −½ Σ q_i q_j ∫₀ˣ ν_i·ν_j dx' and, on a
/// curved mean line (pre-sweep y0, pre-bend z0), by −Σ q_i ∫₀ˣ (y0' u_y,i' + z0' u_z,i') dx' (beam.cpp):
/// the geometric stiffness of any axial load (gravity, masses carried, centrifugal, body
/// acceleration) and the axial-inertia terms of the mass matrix [Branlard2019, eq. 26–29] follow.
#include <string>
#include <vector>

#include "src/model/body.hpp"
#include "src/shapes/shape.hpp"

namespace whirl {

/// Spanwise properties, tabulated at stations x (increasing, from 0 to the length), linear in between.
struct BeamProperties {
  double length = 0;  ///< L [m]
  VecX x;             ///< stations [m]
  VecX m;             ///< mass per length [kg/m]
  VecX EIy;           ///< bending stiffness for deflection along principal y [N m²]
  VecX EIz;           ///< bending stiffness for deflection along principal z [N m²]
  VecX GKt;           ///< torsional stiffness [N m²] (empty = 0)
  VecX jG;            ///< polar mass moment of inertia per length about the COG [kg m] (empty = 0)
  VecX twist;         ///< structural twist of the principal axes about x [rad] (empty = 0)
  VecX y0, z0;        ///< mean line (pre-sweep, pre-bend) [m] (empty = 0)
  VecX cgy, cgz;      ///< COG offset from the mean line, body y and z [m] (empty = 0)
  /// Full inertia tensor per length of the section about its COG, body axes, one per station [kg m]
  /// (empty: the thin-beam convention, jG about x only). Given, it replaces jG in the inertia: the
  /// section turns as a rigid lamina with the mean line's small rotations (t_x, −u_z', u_y'), so its
  /// flap and edge rotary inertia (a Rayleigh beam; BeamDyn's M44, M55, M45) enter too.
  std::vector<Mat3> J;
};

/// Where the integrals are evaluated.
struct BeamIntegration {
  enum Method {
    Stations,   ///< trapezoid over the property stations
    Trapezoid,  ///< trapezoid over n+1 equally spaced points
    Gauss,      ///< n-point Gauss–Legendre
    Midpoint    ///< n equal elements, one node at each centre (ElastoDyn's BldNodes/TwrNodes)
  };
  Method method = Gauss;
  int n = 100;
};

/// Damping of the elastic coordinates.
struct BeamDamping {
  enum Kind { None, ModalRatio, StiffnessProportional, Rayleigh };
  Kind kind = None;
  std::vector<double> ratio;  ///< ModalRatio: ζ per shape; D_jj = 2 ζ_j √(K_jj M_jj)
  double alpha = 0;           ///< Rayleigh: D = α M_ee + β K
  double beta = 0;            ///< StiffnessProportional / Rayleigh
};

struct BeamOptions {
  BeamIntegration integration;
  BeamDamping damping;
  bool axial_shortening = true;
};

/// The body data of a beam: inertia, stiffness and damping.
struct BeamBody {
  BodyInertia inertia;
  ElasticProperties elastic;
};

BeamBody buildBeamBody(const BeamProperties& props, const std::vector<ShapePtr>& shapes, const BeamOptions& opt,
                       const std::string& body_name);

/// The mean-line point at x: position field P (3 × nc) and rotations θ (3 × ne):
/// θ_x = t_x, θ_y = −u_z', θ_z = u_y'.
BodyPoint beamPoint(const BeamProperties& props, const std::vector<ShapePtr>& shapes, bool axial_shortening, double x,
                    std::string name);

/// Evenly spaced mean-line points for showing mode shapes (Body::nodes): `count` ≥ 2 stations from
/// the root (x = 0) to the tip (x = length [m]), named "node 1" … "node <count>".
std::vector<BodyPoint> beamNodes(const BeamProperties& props, const std::vector<ShapePtr>& shapes,
                                 bool axial_shortening, double length, int count = 11);

/// G_ij(x) = ∫₀ˣ (u_y,i' u_y,j' + u_z,i' u_z,j') dx' (ne × ne).
MatX slopeProductIntegral(const std::vector<ShapePtr>& shapes, double x);

/// Checks sizes, finiteness and signs (mass ≥ 0, stiffness > 0); throws InputError naming the field.
void validateBeam(const BeamProperties& props, const std::string& body_name);

}  // namespace whirl

#pragma once
/// \file
/// One ElastoDyn blade file as a whirl beam: spanwise properties in SI units and ElastoDyn's twisted
/// mode shapes (ElastoDyn `Coeff`, arrays `TwistedSF`), with the generalized masses and stiffnesses
/// ElastoDyn prints.
///
/// Blade body frame (x, y, z) = (j3, j1, j2) of ElastoDyn's pitched blade axes:
///   x along the pitch axis, from the root (r = 0) to the tip (r = L = TipRad − HubRad) [m];
///   y = j1, out of the rotor plane (downwind at zero pitch and cone);
///   z = j2, in the plane, towards the trailing edge at zero pitch.
/// ElastoDyn's principal flap axis at r is Lj1 = cos θs j1 − sin θs j2, θs = StrcTwst(r), so whirl's
/// `BeamProperties::twist` (a rotation of the principal axes about +x) is −θs, EIy is the flap
/// stiffness and EIz the edge stiffness.
///
/// The shapes: ElastoDyn takes the polynomial curvature φ''(r) of each mode (BldFl1Sh, BldFl2Sh,
/// BldEdgSh; coefficients of (r/L)², …, (r/L)⁶) as a curvature about the principal axis, rotates it into
/// (j1, j2) with the local twist (flap: (cos θs, −sin θs) φ'', edge: (sin θs, cos θs) φ''), and
/// integrates it twice from the root with its node rule (n equal elements, nodes at the element
/// centres; half an element from the root to node 1, trapezoids between nodes, half an element from
/// node n to the tip). The result, a shape with both out-of-plane and in-plane displacement, is a
/// `tableShape` with displacement, slope and curvature columns at the root, the n nodes and the tip;
/// at the nodes it holds ElastoDyn's values exactly, so a beam built with `BeamIntegration::Midpoint`
/// and n elements has ElastoDyn's mass matrix and, projecting the curvatures back on the principal
/// axes with the same twist, ElastoDyn's stiffness ∫ EI φ''² dr.
#include <vector>

#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/shapes/beam.hpp"

namespace whirl {

/// Shape order of an ElastoDyn blade in whirl: flap 1, edge 1, flap 2 (OpenFAST's state order).
enum ElastoDynBladeShape { kFlap1 = 0, kEdge1 = 1, kFlap2 = 2 };

/// An ElastoDyn blade ready for buildBeamBody.
struct ElastoDynBladeBeam {
  BeamProperties props;  ///< SI: m = BMassDen·AdjBlMs [kg/m], EIy = FlpStff·AdjFlSt, EIz = EdgStff·AdjEdSt [N m²],
                         ///< twist = −StrcTwst [rad]
  std::vector<ShapePtr>
      shapes;           ///< flap 1, edge 1, flap 2: table shapes in body y (j1) and z (j2) [m per unit tip deflection]
  int nodes = 0;        ///< BldNodes: equal elements, one node at each centre
  double tip_mass = 0;  ///< TipMass [kg], a point mass at r = L
  /// ElastoDyn's generalized masses, shape order: TipMass + Σ m ΔR φ² with the UNTWISTED polynomial φ
  /// (MBF, MBE of `Coeff`: r from the blade root, hub radius not included) [kg]. ElastoDyn prints these
  /// and uses them (less TipMass) for the damping; its equations of motion, and whirl's body, use the
  /// twisted shapes, whose Σ m ΔR (Φ² + Ψ²) is slightly larger.
  Eigen::Vector3d generalized_mass = Eigen::Vector3d::Zero();
  /// ElastoDyn's generalized stiffness (KBF, KBE): Σ EI ΔR φ''², flap entries × √(FlStTunr_i FlStTunr_j),
  /// flap 1–flap 2 coupled, edge uncoupled [N/m].
  Eigen::Matrix3d generalized_stiffness = Eigen::Matrix3d::Zero();
  Eigen::Vector3d stiffness_tuner = Eigen::Vector3d::Ones();  ///< FlStTunr(1), 1, FlStTunr(2) [-]
  Eigen::Vector3d damping_ratio = Eigen::Vector3d::Zero();  ///< BldFlDmp(1), BldEdDmp(1), BldFlDmp(2) as fractions [-]
};

/// Builds the blade of `file` with length L = TipRad − HubRad [m] and `nodes` equal elements.
/// Throws InputError naming the blade file when nodes < 1 or the table gives a non-finite property.
ElastoDynBladeBeam elastoDynBladeBeam(const io::ElastoDynBlade& file, double length, int nodes, double tip_mass);

/// ElastoDyn's modal damping (`Coeff`, CTFA/CBF): D(i, l) = 2 ζ_l K(i, l) √(M_l / K(l, l)), i.e. the
/// damping ratio ζ_l at the frequency √(K_ll/M_l) of the structure alone (M_l without tower-top or
/// tip masses). Not symmetric when the ratios differ, as in ElastoDyn.
/// \param[in] K generalized stiffness (n × n) [N/m]
/// \param[in] modal_mass M_l (dim n) [kg]
/// \param[in] zeta ζ_l (dim n) [-]
MatX elastoDynModalDamping(const MatX& K, const VecX& modal_mass, const VecX& zeta);

/// K(i, j) × √(t_i t_j): ElastoDyn's modal stiffness tuners (FAStTunr, SSStTunr, FlStTunr).
MatX applyStiffnessTuners(const MatX& K, const VecX& tuner);

}  // namespace whirl

#pragma once
/// \file
/// A 3D beam finite-element model in one body frame: nodes, two-node elements with their sections,
/// lumped masses, node springs (e.g. a 6×6 foundation matrix), distributed (Winkler) springs and
/// fixed DOFs. Plain data; validate() checks it once.
///
/// DOFs: 6 per node in body axes, [u_x, u_y, u_z, θ_x, θ_y, θ_z], index 6 × node + k.
#include <array>
#include <vector>

#include "src/fem/element.hpp"

namespace whirl::fem {

using Mat6 = Eigen::Matrix<double, 6, 6>;
constexpr int kNodeDofs = 6;
/// Names of the node DOFs, in order: ux, uy, uz, rx, ry, rz.
extern const std::array<const char*, 6> kNodeDofNames;

struct Element {
  int n1 = -1, n2 = -1;
  Section s1, s2;                             ///< sections at node 1 and node 2 (element frame), linear between
  Vec3 y_axis = Vec3::Zero();                 ///< element y axis in body axes; zero = body y projected (or body z)
  Vec3 k1 = Vec3::Zero(), k2 = Vec3::Zero();  ///< Winkler springs per length (element x, y, z) [N/m²]
};

/// A rigid mass at a node: mass and inertia about the node (body axes).
struct NodeMass {
  int node = -1;
  double mass = 0;
  Mat3 inertia = Mat3::Zero();
};

/// A spring to ground on the 6 DOFs of a node (body axes), e.g. a mudline foundation matrix.
struct NodeSpring {
  int node = -1;
  Mat6 K = Mat6::Zero();
};

struct BeamModel {
  std::vector<Vec3> nodes;  ///< positions, body frame [m]
  std::vector<Element> elements;
  std::vector<NodeMass> masses;
  std::vector<NodeSpring> springs;
  std::vector<std::array<bool, 6>> fixed;  ///< per node: DOFs held at zero (empty = none)
  bool timoshenko = false;                 ///< shear deformation from kGAy, kGAz

  int nnodes() const { return static_cast<int>(nodes.size()); }
  int ndof() const { return kNodeDofs * nnodes(); }
};

/// Element frame → body frame rotation (columns: element x, y, z in body axes).
Mat3 elementFrame(const BeamModel& model, const Element& e);

/// Checks indices, lengths, signs (m ≥ 0, EA, EIy, EIz > 0, GJ ≥ 0) and finiteness.
/// \throws InputError "FE model '<name>': element k: <field>: <reason>".
void validate(const BeamModel& model, const std::string& name);

/// Spanwise properties of a straight beam along body x, at increasing stations (linear between).
/// Optional columns may be empty (= 0).
struct BeamStations {
  VecX x;                       ///< stations [m]
  VecX m, EA, EIy, EIz, GJ;     ///< see Section
  VecX iy2, iz2;                ///< section mass second moments [kg m]
  VecX kGAy, kGAz;              ///< shear stiffness [N]
  VecX soil_x, soil_y, soil_z;  ///< Winkler springs per length [N/m²]
};

/// A straight beam along body x with nodes at `node_x` (increasing, inside the stations' range).
BeamModel straightBeam(const BeamStations& props, const std::vector<double>& node_x, bool timoshenko);

/// Node positions for a straight beam of `elements` equal elements on [x0, x1], with the extra
/// stations `extra` inserted (merged with a grid node closer than 1e-6 of an element length).
std::vector<double> meshStations(double x0, double x1, int elements, const std::vector<double>& extra);

}  // namespace whirl::fem

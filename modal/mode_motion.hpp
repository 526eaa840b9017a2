#pragma once
/// \file
/// The physical motion of one mode: complex amplitudes of the nodes of the turbine's bodies (tower,
/// nacelle, hub, blades, platform), plain data filled by modal/mode_shapes.hpp.
///
/// A node moves as Re(u e^{iωt}) about its position at the operating point: |u| is the amplitude, arg u
/// the phase. Components are in the body's own frame at the operating point (docs/architecture.md,
/// *Notation*): an ElastoDyn tower's x is up, y = −ground Y (side-side), z = ground X (fore-aft); a
/// blade's x runs root to tip, y is out of the rotor plane (flap at zero pitch), z in the plane (edge),
/// the frame turning with the rotor and the pitch (the rotating frame). Normalised so that the largest
/// translational amplitude of any node is 1 (real, phase 0); rotations are in rad per that unit.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// Motion of the nodes of one body in one mode.
struct BodyMotion {
  std::string body;  ///< Body::name
  int blade = -1;    ///< rotor blade (0-based) the body is, −1: fixed frame
  /// What the body is for the tables of other tools and the report: "blade", "platform" (a free joint),
  /// "tower", "nacelle", "hub" (the name holds the word, any case), or empty.
  std::string role;
  std::vector<std::string> nodes;  ///< "origin", "node 1", … (Body::nodes, else the origin and Body::points)
  VecX x;                          ///< station of each node along body x, undeformed [m]
  Mat3X position;                  ///< ground position of each node at the operating point [m] (3 × nodes)
  Mat3 R = Mat3::Identity();       ///< body frame → ground at the operating point
  /// nodes × 6: translations u_x, u_y, u_z [m per unit] and small rotations θ_x, θ_y, θ_z [rad per unit]
  /// about the body axes, body-frame components.
  Eigen::MatrixXcd u;
};

/// Motion of every shown body in one mode; empty when not computed (a Floquet analysis, whose shapes are
/// harmonics, not one pattern per mode).
struct ModeMotion {
  std::vector<BodyMotion> bodies;
  /// Multiblade content of the blade motion (rotor with 3 or more blades), per blade node and component,
  /// in the blades' frames: collective u₀ = (1/N) Σ_b u_b, backward and forward whirl
  /// (u_c ∓ i u_s)/2 with u_c = (2/N) Σ_b u_b cos ψ_b, u_s = (2/N) Σ_b u_b sin ψ_b (rotor turning in +ψ).
  /// Rows: blade nodes, columns: the 6 components. Empty without a rotor of 3 or more blades.
  Eigen::MatrixXcd collective, backward, forward;
  std::vector<std::string> blade_nodes;  ///< names of the rows above
  VecX blade_x;                          ///< station of each of those rows along the blade [m]
  bool empty() const { return bodies.empty(); }
};

}  // namespace whirl

#pragma once
/// \file
/// Mode shapes as physical motion: a mode's generalized coordinates (modal/modes.hpp; multiblade
/// coordinates for rotors, modal/rotor_modes.hpp) mapped to the displacements and rotations of body
/// nodes (modal/mode_motion.hpp) through the kinematics at the operating point.
///
/// Linear map. A node at s = P c in body b moves by δp = Jv δq − (R s)~ Jω δq + R P D δq_e and turns
/// by δθ = Jω δq + R Θ δq_e (ground components; Jv, Jω the partial velocities of the body frame,
/// src/dynamics/workspace.hpp; D = ∂c/∂q_e; Θ the point's rotations per elastic coordinate), shown in
/// the body frame: Rᵀ δp, Rᵀ δθ. Exact to first order, so a Rayleigh–Ritz model's node motion is its
/// shapes' values at the node, weighted by the mode.
///
/// Rotors. A mode in multiblade coordinates is turned back to blade coordinates at the first azimuth
/// ψ (blade b at ψ_b = ψ + 2πb/N) by q_b = q₀ + Σ_k (q_kc cos kψ_b + q_ks sin kψ_b) [+ q_d (−1)^b]
/// (linearize/mbc.hpp, [Bir2008]): the motion of the rotor frozen at ψ and vibrating at the mode's
/// frequency. With blades numbered in the direction of rotation, a backward-whirl mode (q_s/q_c = +i)
/// then has blade phases arg u_b stepping by +2π/N from blade to blade, a forward-whirl mode by −2π/N.
#include <vector>

#include "linearize/periodic.hpp"
#include "modal/mode_motion.hpp"
#include "modal/modes.hpp"
#include "src/model/model.hpp"

namespace whirl {

/// The linear map from the active coordinates to the motion of one body's nodes.
struct BodyNodeMap {
  int body = -1;
  BodyMotion shape;     ///< names, stations, positions and R filled; u empty
  std::vector<MatX> J;  ///< per node: 6 × n (body-frame translations then rotations per active coordinate)
};

/// The node maps of the bodies shown: every body with mass or elastic coordinates (massless frames, a
/// yaw bearing, are left out); a body's nodes are Body::nodes, or its origin and Body::points.
/// \param[in] q, qd  all coordinates at the operating point (dim model.ndof())
/// \param[in] active the model coordinate of each mode-shape entry (LinearModel::dofs)
std::vector<BodyNodeMap> bodyNodeMaps(const Model& model, const VecX& q, const VecX& qd,
                                      const std::vector<int>& active);

/// The motion of mode shape `phi` (blade coordinates, dim active) normalised: largest translational
/// amplitude 1 with phase 0. An all-zero motion stays zero.
ModeMotion modeMotion(const std::vector<BodyNodeMap>& maps, const Eigen::VectorXcd& phi);

/// Multiblade coordinates → blade coordinates at azimuth psi of blade 1 (rad), as above. dof_blade:
/// blade of each entry (0-based, −1 fixed); the j-th entries of the blades form a set whose slots hold
/// q₀, q_1c, q_1s, q_2c, … (, q_d) as linearize/mbc.hpp orders them.
Eigen::VectorXcd bladeCoordinates(const Eigen::VectorXcd& phi, const std::vector<int>& dof_blade, int num_blades,
                                  double psi);

/// Collective, backward- and forward-whirl content of the blade motion (ModeMotion::collective …), from
/// the blade bodies' motion; rotor_speed's sign says which way is forward. Needs ≥ 3 blade bodies with
/// the same nodes; otherwise leaves them empty.
void multibladeContent(ModeMotion& motion, int num_blades, double psi, double rotor_speed);

/// Fills Mode::motion of every mode of a rotor (or any model) analysed by rotorModes(model, periodic):
/// multiblade shapes turned back at the first azimuth; fixed-frame or blade coordinates as they are.
/// Leaves the motion empty when the shapes are not in the linear model's coordinates (Floquet).
/// \param[in] num_blades RotorModes::num_blades (0: no transform)
void addModeMotions(const Model& model, const PeriodicLinearization& periodic, int num_blades,
                    const std::vector<std::string>& coordinates, std::vector<Mode>& modes);

/// The same for the modes of one linear model at one operating point (no rotor transform).
void addModeMotions(const Model& model, const OperatingPoint& op, const LinearModel& lin, std::vector<Mode>& modes);

}  // namespace whirl

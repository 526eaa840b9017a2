#pragma once
/// \file
/// Modes of a rotating turbine: the per-azimuth linear models are transformed to multiblade
/// coordinates (linearize/mbc.hpp), averaged over the revolution, and the averaged A is analysed.
/// Blade coordinates become "<shape> collective", "<shape> cos", "<shape> sin" (…); modes are
/// named from their dominant coordinate group, cyclic blade modes as backward (BW) or forward
/// (FW) whirl from the phase between their cosine and sine parts:
///   q_s / q_c = −i → the pattern turns with the rotor (FW), +i → against it (BW).
/// Fewer than 3 blades: no multiblade transform (the transformed system stays periodic). A turning
/// rotor sampled evenly over the revolution is analysed by Floquet (modal/floquet.hpp); otherwise
/// (parked, or uneven azimuths) the modes are those of the first azimuth and the names keep the
/// blade coordinates.
#include <string>
#include <vector>

#include "linearize/mbc.hpp"
#include "linearize/periodic.hpp"
#include "modal/modes.hpp"

namespace whirl {

struct RotorModes {
  std::vector<std::string> coordinates;  ///< names of the mode-shape coordinates (dim n)
  std::vector<Mode> modes;               ///< sorted by frequency
  MatX A;                                ///< the (averaged, multiblade) state matrix, 2n (+ first-order) square
  int num_blades = 0;                    ///< 0 when no transform was applied
};

RotorModes rotorModes(const Model& model, const PeriodicLinearization& periodic);

/// Modes of one linear model by the same path (no transform, one sample): for a model with
/// first-order states (LinearModel::first_order_names), whose modes come from participation factors.
/// \param held unrestrained coordinates the operating point held (OperatingPoint::held)
RotorModes linearModelModes(const Model& model, const LinearModel& lin, const std::vector<int>& held = {});

/// What naming needs of the n displacement coordinates of a linear rotor model.
struct RotorCoordinates {
  std::vector<std::string> names;  ///< DOF names, e.g. "blade 2 flap 1", "tower FA 1" (dim n)
  std::vector<int> blade;          ///< blade of each coordinate (0-based), −1 = fixed frame
  std::vector<bool> azimuth;       ///< the rotor's azimuth coordinates (rigid rotation)
  /// Unrestrained coordinates the operating point held (OperatingPoint::held, a free yaw); empty:
  /// none. A slow mode carried by them is a rigid-body mode, like the azimuth's.
  std::vector<bool> held;
  /// A 2-bladed rotor's teeter (ModelRoles::teeter_dof); empty: none. It turns with the rotor without
  /// being a blade's coordinate: Floquet analysis sees it in the fixed frame as the differential blade
  /// pattern it is (+ on blade 1, − on blade 2), rows "<name> cos" and "<name> sin".
  std::vector<bool> teeter;
  MatX weights;  ///< n × n, weighs participations (a mass matrix or its diagonal)
  /// Empty: the states are [q; q̇; first-order] and `weights` weighs the participations. Otherwise
  /// (a `.lin` file: no mass matrix, states in any order) the coordinate of each state, the
  /// coordinates being the displacements and first-order states in state order, and the modes come
  /// from participation factors (modal/participation.hpp); `weights` is not used.
  std::vector<int> coordinate_of_state;
  /// Naming group of each coordinate (dim n) when several coordinates name one thing (the 14
  /// radiation states of a platform surge); empty: each coordinate is its own group.
  std::vector<std::string> groups;
};

/// Modes of per-azimuth models (states: the n coordinates first, their rates next, then any
/// first-order states, as `layout` says; or any order, RotorCoordinates::coordinate_of_state):
/// multiblade average when ≥ 3 blades, else the first sample.
RotorModes multibladeModes(const RotorCoordinates& coords, const MbcLayout& layout,
                           const std::vector<MbcSample>& samples);

/// A mode-shape coordinate for naming: its group (a fixed coordinate's name, or a blade shape's base
/// name) and what it is of that group (fixed, collective, cos, sin, …).
struct NamingCoordinate {
  std::string group;
  MbcCoordinate kind;
};

/// Names `mode` from the group with the largest energy share (see rotor_modes.cpp); azimuth and held
/// flag rigid-body coordinates (dim of coords).
void nameRotorMode(Mode& mode, const std::vector<NamingCoordinate>& coords, const std::vector<bool>& azimuth,
                   const std::vector<bool>& held, double rotor_speed);

/// "blade 2 flap 1" → "flap 1": drops a leading "blade <k> " from a blade coordinate's name.
std::string bladeBaseName(const std::string& dof_name);

}  // namespace whirl

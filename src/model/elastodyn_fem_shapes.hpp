#pragma once
/// \file
/// FE mode shapes for the ElastoDyn tower and blades (`--set shapes=fem`, `whirl shapes`): the same
/// distributed properties ElastoDyn reads, solved by the beam FE (src/fem/mode_shapes.hpp) with the
/// boundary conditions BModes users give, instead of the polynomials of the input files.
///
/// - Tower (body frame of elastodyn_tower.cpp: x up, y side-to-side = −Y, z fore-aft = X): clamped at
///   the base, the nacelle, hub and rotor as one rigid tip body at the tower top (mass, centre of
///   mass, inertia about it at zero yaw, azimuth-averaged rotor inertia), gravity as an axial load.
/// - Blade (body frame of elastodyn_blade_shapes.hpp: x span, y = j1 out of plane, z = j2 in plane):
///   clamped at the root, structural twist, tip-brake mass, centrifugal stiffening at the rotor speed
///   (hub radius HubRad, rotation axis along y: out of plane at zero pitch and cone) with the in-plane
///   softening.
#include <vector>

#include "src/fem/mode_shapes.hpp"
#include "src/io/elastodyn_input.hpp"
#include "src/model/elastodyn_blade_shapes.hpp"

namespace whirl {

/// The tower's FE input: `props` as built for the tower body (SI, adjusted), rigid top from `ed`.
/// \param[in] gravity [m/s²] (axial compression from the tower's own weight and the top mass)
fem::ModeShapeInput elastoDynTowerModeInput(const io::ElastoDynInput& ed, const BeamProperties& props, double gravity);

/// A blade's FE input at rotor speed `rotor_speed` [rad/s].
fem::ModeShapeInput elastoDynBladeModeInput(const ElastoDynBladeBeam& blade, double hub_radius, double rotor_speed);

/// Tower shapes in ElastoDyn's order: FA 1, SS 1, FA 2, SS 2 (FA along body z, SS along body y).
/// \param[out] freq_hz the FE frequencies of those four modes (may be null)
std::vector<ShapePtr> elastoDynTowerFemShapes(const fem::ModeShapeInput& in, std::vector<double>* freq_hz = nullptr);

/// Blade shapes in ElastoDyn's order: flap 1, edge 1, flap 2 (flap along body y, edge along body z).
std::vector<ShapePtr> elastoDynBladeFemShapes(const fem::ModeShapeInput& in, std::vector<double>* freq_hz = nullptr);

}  // namespace whirl

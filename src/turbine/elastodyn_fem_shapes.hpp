#pragma once
/// \file
/// FE mode shapes for the ElastoDyn tower and blades (`--set shapes=fem`, `whirl shapes`): the same
/// distributed properties ElastoDyn reads, solved by the beam FE (src/fem/mode_shapes.hpp) with the
/// boundary conditions BModes users give, instead of the polynomials of the input files.
///
/// - Tower (body frame of elastodyn_tower.cpp: x up, y side-to-side = −Y, z fore-aft = X): clamped at
///   the base, the nacelle, hub and rotor as one tip body at the tower top (mass, centre of mass at
///   zero yaw; optionally the rigid top's inertia, azimuth-averaged for the rotor), gravity as an axial load.
/// - Blade (body frame of elastodyn_blade_shapes.hpp: x span, y = j1 out of plane, z = j2 in plane):
///   clamped at the root, structural twist, tip-brake mass, centrifugal stiffening at the rotor speed
///   (hub radius HubRad, rotation axis along y: out of plane at zero pitch and cone) with the in-plane
///   softening.
#include <vector>

#include "src/fem/mode_shapes.hpp"
#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"

namespace whirl {

/// The tower's FE input: `props` as built for the tower body (SI, adjusted), the tower-top mass and its
/// centre of mass from `ed` (yaw bearing, nacelle, hub, blades).
/// The top's rotary inertia is left out unless `top_inertia`: in the turbine's coupled modes the rotor
/// is not rigid (blades bend, the drivetrain twists), and a rigid rotor's 2·10⁷–4·10⁷ kg m² at the tower
/// top pulls the second tower modes to 1.95–2.24 Hz instead of the ~2.9 Hz of the coupled turbine.
/// Without it the FE modes match the NREL 5MW file polynomials (BModes) to MAC 0.999 for all four
/// tower modes and give tower-alone second modes of 2.92 Hz (tests/validation/test_nrel5mw_fem_shapes.cpp).
/// \param[in] gravity [m/s²] (axial compression from the tower's own weight and the top mass)
fem::ModeShapeInput elastoDynTowerModeInput(const io::ElastoDynInput& ed, const BeamProperties& props, double gravity,
                                            bool top_inertia = false);

/// A blade's FE input at rotor speed `rotor_speed` [rad/s].
fem::ModeShapeInput elastoDynBladeModeInput(const ElastoDynBladeBeam& blade, double hub_radius, double rotor_speed);

/// Tower shapes in ElastoDyn's order: FA 1, SS 1, FA 2, SS 2 (FA along body z, SS along body y).
/// \param[out] freq_hz the FE frequencies of those four modes (may be null)
std::vector<ShapePtr> elastoDynTowerFemShapes(const fem::ModeShapeInput& in, std::vector<double>* freq_hz = nullptr);

/// Blade shapes in ElastoDyn's order: flap 1, edge 1, flap 2 (flap along body y, edge along body z).
std::vector<ShapePtr> elastoDynBladeFemShapes(const fem::ModeShapeInput& in, std::vector<double>* freq_hz = nullptr);

}  // namespace whirl

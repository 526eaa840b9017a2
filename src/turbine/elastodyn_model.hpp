#pragma once
/// \file
/// The ElastoDyn-equivalent turbine, built from whirl's bodies and joints (no closed-form equations):
/// the same DOFs, shapes, masses and geometry as ElastoDyn, so that linearizing it reproduces
/// ElastoDyn's structural model.
///
/// Frames (all right-handed, SI units, angles in radians inside):
/// - ground = OpenFAST's inertial frame: X downwind, Y to the left looking downwind, Z up; gravity
///   (0, 0, −g); the tower base sits at (0, 0, TowerBsHt).
/// - tower beam body: x up the tower axis, y = −Y (ElastoDyn's a3: side-to-side), z = X (fore-aft);
///   "tower FA k" displaces the top along +X, "tower SS k" along −Y, as ElastoDyn's TFA/TSS DOFs.
/// - yaw bearing (YawBrMass) and nacelle at the tower top; nacelle = ground axes turned by the yaw
///   about Z (ElastoDyn's d1 = x, d2 = z, d3 = −y); NacMass at (NacCMxn, NacCMyn, NacCMzn), inertia
///   NacYIner about the yaw axis only (ElastoDyn's nacelle has no other inertia).
/// - low-speed shaft: at (0, 0, Twr2Shft) of the nacelle, shaft frame x = c1 = (cos ShftTilt, 0,
///   sin ShftTilt) (nacelle axes turned by −ShftTilt about y); turns about x by the generator azimuth.
/// - generator: same place and axes, turns by GBRatio × the generator azimuth (geared), GenIner about x.
/// - hub: at OverHang along x from the generator (the rotor apex, ElastoDyn's point Q), turns about x by
///   the drivetrain twist; HubMass at HubCM along x, HubIner about x.
/// - 2 blades (NumBl = 2): the hub above sits at the teeter pin (OverHang reaches it) and a teetering
///   hub turns about its y (ElastoDyn's teeter axis e2 = f2) by the teeter angle, carrying HubMass; the
///   blades' apex lies UndSling upwind along its x, and they are turned by Delta3 about it
///   (elastodyn_teeter.cpp).
/// - blade k: root at HubRad along the coned axis i3, body x = i3 (ElastoDyn's j3), y = j1 (out of
///   plane), z = j2 (in plane); azimuth offset 2π(k−1)/NumBl about the shaft, PreCone about the hub y,
///   pitch (frozen joint, value BlPitch) about −x. See elastodyn_blade_shapes.hpp for the shapes.
///
/// DOFs (names as the field uses them; a switched-off DOF stays in the model, frozen at its value):
///   "tower FA 1", "tower SS 1", "tower FA 2", "tower SS 2" [m, tower-top deflection];
///   "yaw" [rad, value NacYaw]; "generator azimuth" [rad, LSS side, value Azimuth − AzimB1Up, so
///   0 = blade 1 up; rate RotSpeed; `rotating`]; "drivetrain" [rad, rotor minus generator azimuth];
///   "teeter" [rad, 2 blades only: value TeetDefl, frozen unless TeetDOF; ModelRoles::teeter_dof];
///   "blade k pitch" [rad, always frozen]; "blade k flap 1", "blade k edge 1", "blade k flap 2"
///   [m, tip deflection of the polynomial mode].
/// Inputs (value 0): "generator torque" [N m, high-speed shaft, opposing the rotation: −GBRatio·u on the
/// generator about x, +GBRatio·u on the nacelle]; "rotor thrust" [N, along the shaft on the hub];
/// "rotor torque" [N m, about the shaft on the hub, in the direction of rotation]; "tower-top force"
/// [N, ground X at the tower top]; "tower-top side force" [N, ground Y at the tower top]; "collective
/// pitch" [rad, added to the three frozen "blade k pitch" joints] and "blade k pitch" [rad, one joint,
/// rotating frame]; their operating point is the pitch angle (BlPitch or the schedule's).
/// Outputs (SI units; OpenFAST-like names, whirl definitions): "GenSpeed" [rad/s, GBRatio × generator
/// azimuth rate]; "RotSpeed" [rad/s, generator azimuth + drivetrain rates]; "NacYaw" [rad]; "TTDspFA",
/// "TTDspSS" [m, tower-top (yaw bearing origin) position along ground X, Y]; "YawBrTAxp", "YawBrTAyp"
/// [m/s², its inertial acceleration along the yaw bearing's x, y axes, which tilt with the tower top];
/// "TeetDefl" [rad, 2 blades]; "TwrBsMFA", "TwrBsMSS" [N m, tower-base moments of the loads on the tower and all it
/// carries, bending the top towards +X (ElastoDyn's TwrBsMyt), +Y]; "RootMFlp k", "RootMEdg k" (no space) [N m,
/// ElastoDyn's RootMyb and RootMxb: the moment at the blade root of the loads on the blade (inertia, gravity, the
/// quasi-steady element loads, a tip mass) about the pitched axes j2 and j1 (the blade body's z and y); rotating frame]
/// (OutputKind::SubtreeLoadMoment); with a platform "PtfmSurge", "PtfmSway", "PtfmHeave" [m], "PtfmRoll", "PtfmPitch",
/// "PtfmYaw" [rad], their rates and accelerations "PtfmTVxi" … "PtfmTAzi", and the platform's angular velocity and
/// acceleration about the ground axes "PtfmRVxi" … "PtfmRAzi" (elastodyn_parts.hpp addPlatformOutputs). Springs: yaw
/// (YawSpr, YawDamp about YawNeut, from ServoDyn), drivetrain (DTTorSpr, DTTorDmp), teeter (TeetMod = 1: stops and
/// damper, each linearized on the piece of its law that holds at TeetDefl).
///
/// ElastoDyn conventions kept on purpose: the tower top sits at the tower DOF values themselves (not at
/// the polynomials' tip values, which need not sum to exactly 1); the blades' twisted shapes come from
/// ElastoDyn's node rule; the nacelle has inertia about the yaw axis only; the hub about the shaft only.
///
/// Differences from ElastoDyn:
/// - (none for the generator: it is a body geared to the generator azimuth at GBRatio, so its kinetic
///   energy ½ GenIner (ω_c + GBRatio θ̇)² is ElastoDyn's with GenDOF on or off.)
/// - The axial shortening ∫ ν'·ν' of tower and blades is integrated with fine Gauss quadrature of the
///   shapes' slopes (ElastoDyn: its node rule), a difference of order ΔR².
/// - GBoxEff is not applied to the generator torque.
#include <optional>
#include <string>
#include <vector>

#include "src/fem/shape_comparison.hpp"
#include "src/io/openfast/aerodyn/aero_deck.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "src/model/model.hpp"

namespace whirl {

struct ElastoDynModelOptions {
  /// Yaw spring and damper from ServoDyn (YawSpr, YawDamp, YawNeut) when CompServo = 1 and YawDOF is on.
  bool yaw_spring_from_servodyn = true;
  /// The ServoDyn input (read with the deck, io::readOpenFastDeck); no yaw spring without it.
  std::optional<io::ServoDynInput> servodyn;
  /// Gravity [m/s²]; default: the .fst's (or ElastoDyn v1.0x's) Gravity, 9.80665 for an ElastoDyn file alone.
  std::optional<double> gravity;
  /// Blade nodes when the ElastoDyn file has no BldNodes (v1.00–v1.01 took them from AeroDyn); 0 = required.
  int blade_nodes = 0;
  /// Axial shortening of tower and blades (the geometric stiffness of gravity and centrifugal loads).
  bool axial_shortening = true;
  /// Tower and blade shapes from the beam FE (elastodyn_fem_shapes.hpp) instead of the files' polynomials:
  /// tower with the rotor-nacelle top mass and gravity, blades at the initial rotor speed RotSpeed.
  bool fem_shapes = false;
  /// BeamDyn blades (CompElast = 2, beamdyn_blade.hpp): equal 6 × 6 elements along the axis and the
  /// fixed-root modes kept (`--set blade_elements=N`, `--set blade_modes=N`).
  int blade_elements = 60;
  int blade_modes = 8;
  /// Aerodynamics (AeroDyn, InflowWind) when the .fst has CompAero = 2 (io::OpenFastDeck::aero).
  /// Absent: a structural model. (elastodyn_aero.cpp; frames and conventions in src/model/aero_model.hpp.)
  std::optional<io::AeroDeckInput> aero;
  /// ServoDyn's generator torque law for an aerodynamic model (VSContrl = 1), when ServoDyn is on.
  std::optional<io::ServoDynInput> torque_law;
  /// The deck's ROSCO controller (VSContrl = 5 and a DISCON.IN; io::OpenFastDeck::controller): Model::deck_controller.
  std::optional<RoscoController> controller;
};

/// Builds and finalizes the model of the turbine read from an OpenFAST .fst (or an ElastoDyn .dat alone:
/// then `turbine.fst` is default-constructed, with an empty path and CompServo = 0).
/// Throws InputError naming file, line and key for unsupported options (io::requireSupported), a
/// missing ServoDyn file when the yaw spring is needed, or inconsistent values.
Model buildElastoDynModel(const io::OpenFastTurbine& turbine, const ElastoDynModelOptions& opt = {});

/// Reads `fst_or_dat_path` (a `.fst`, or any other name: an ElastoDyn main file) with KEY=VALUE
/// overrides applied to every file read; `gravity=<m/s²>`, `shapes=polynomial|fem` (any case),
/// `blade_elements=N` and `blade_modes=N` are whirl options instead (ElastoDynModelOptions).
/// Every override must be used by some file read. Throws InputError naming file, line and key.
Model readElastoDynModel(const std::string& fst_or_dat_path, const std::vector<std::string>& overrides = {});

/// The files of readElastoDynModel with the overrides applied; the whirl options go to `opt`.
io::OpenFastTurbine readElastoDynTurbine(const std::string& fst_or_dat_path, const std::vector<std::string>& overrides,
                                         ElastoDynModelOptions& opt);

/// Tower and blades of the turbine as FE inputs (elastodyn_fem_shapes.hpp) with the shapes the model
/// would use (polynomials, or FE with shapes=fem). Blades at `rpm` [rpm] (default: RotSpeed).
std::vector<fem::FlexibleBeam> readElastoDynFlexibleBeams(const std::string& fst_or_dat_path,
                                                          const std::vector<std::string>& overrides,
                                                          std::optional<double> rpm = std::nullopt);

}  // namespace whirl

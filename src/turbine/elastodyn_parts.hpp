#pragma once
/// \file
/// Internal pieces of buildElastoDynModel: each function adds the bodies and DOFs of one part of the
/// turbine to a model under construction (frames and units: see elastodyn_model.hpp). Body and DOF
/// indices are those of the unfinalized model; finalize() renumbers them.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "src/io/openfast/aerodyn/aero_deck.hpp"
#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/io/openfast/offshore/subdyn_input.hpp"
#include "src/io/openfast/openfast_turbine.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
#include "src/model/model_builder.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl::elastodyn {

/// The model under construction (ModelBuilder) and the ElastoDyn deck and options it comes from.
struct Builder {
  const io::ElastoDynInput& ed;
  const ElastoDynModelOptions& opt;
  ModelBuilder builder;
  /// The BeamDyn blades (CompElast = 2), one per blade; null: ElastoDyn's blades.
  const std::vector<io::BeamDynInput>* beamdyn = nullptr;

  Model& model() { return builder.model(); }
  const Model& model() const { return builder.model(); }
  /// Appends a body; returns its index.
  int addBody(Body body) { return builder.addBody(std::move(body)); }
  /// Appends a DOF of `body` (joint coordinate or elastic coordinate `local`); frozen unless `active`.
  /// Returns its index in model().dofs; a repeated name is an error naming the ElastoDyn file.
  int addDof(const std::string& name, int body, DofKind kind, int local, bool active, double value = 0.0,
             double rate = 0.0);
  /// "ElastoDyn file:line: key: reason".
  std::string where(const char* key, const std::string& reason) const { return ed.source.where(key, reason); }
};

struct TowerParts {
  int body = -1;
  int top = -1;               ///< index of the tower-top point
  std::array<int, 4> dofs{};  ///< FA 1, SS 1, FA 2, SS 2
};

/// The platform (elastodyn_platform.cpp): a rigid body at the platform reference point, on a free joint
/// (floating) or tied to a SubDyn substructure's transition piece; body = −1 when there is none (no
/// platform DOF on and no SubDyn: the tower base is then clamped).
struct PlatformParts {
  int body = -1;
  Vec3 reference = Vec3::Zero();  ///< platform reference point, ground frame [m]
  std::array<int, 6> dofs{};      ///< surge, sway, heave, roll, pitch, yaw
};

/// "platform surge", "platform sway", "platform heave", "platform roll", "platform pitch", "platform yaw".
inline constexpr std::array<const char*, 6> kPlatformDofNames = {"platform surge", "platform sway",  "platform heave",
                                                                 "platform roll",  "platform pitch", "platform yaw"};

/// What ElastoDyn says about its platform: reference point (PtfmRefzt, v5's PtfmRefxt/yt), rigid-body
/// inertia (PtfmMass at PtfmCM*, PtfmRIner/PIner/YIner and the v4+ products, about the reference point's
/// body frame), DOF switches (PtfmSgDOF … PtfmYDOF) and initial values (PtfmSurge … PtfmYaw, rad).
struct PlatformDescription {
  Vec3 reference = Vec3::Zero();
  BodyInertia inertia;
  std::array<bool, 6> on{};
  std::array<double, 6> value{};
};
PlatformDescription describePlatform(const Builder& b);

/// The floating platform body on a free joint with its six coordinates `platform surge` … `platform
/// yaw` (switched off: frozen at their initial values); nothing when every platform DOF is off.
PlatformParts addPlatform(Builder& b);

/// The SubDyn substructure (elastodyn_substructure.cpp): its FE body clamped at the reaction joints,
/// reduced to the transition piece at the platform reference point, and the ElastoDyn platform body
/// tied to the TP. The TP's six DOFs are the platform coordinates (`platform surge` … `platform yaw`,
/// switched and initialised as ElastoDyn's), then the Craig–Bampton modes `substructure CB 1` …, as
/// OpenFAST couples ElastoDyn's platform to SubDyn's TP.
/// With HydroDyn (`t.hydrodyn`), its strip-theory added mass on the substructure (hydrodyn_strip.hpp).
PlatformParts addSubstructurePlatform(Builder& b, const io::OpenFastTurbine& t);

/// Water density [kg/m³] and depth [m]: HydroDyn's (v2, v3) or the .fst's (v3.5+); InputError when
/// neither file has it (elastodyn_offshore.cpp).
double waterDensity(const io::OpenFastTurbine& t);
double waterDepth(const io::OpenFastTurbine& t);

/// HydroDyn's linear terms and MAP++'s mooring lines on the platform (elastodyn_offshore.cpp).
void addOffshoreLoads(Builder& b, const PlatformParts& platform, const io::OpenFastTurbine& t);

/// The flexible tower (TwrNodes equal elements, FA/SS polynomial shapes, tuners, modal damping), its
/// base on the platform when there is one, else on the ground.
TowerParts addTower(Builder& b, const PlatformParts& platform);

struct DrivetrainParts {
  int bearing = -1, nacelle = -1, shaft = -1, generator = -1,
      hub = -1;                                           ///< bodies (shaft: low-speed side; generator: HSS)
  int yaw = -1, generator_azimuth = -1, drivetrain = -1;  ///< DOFs
};

/// Yaw bearing, nacelle (yaw joint), generator (generator azimuth) and hub (drivetrain twist).
DrivetrainParts addNacelleAndDrivetrain(Builder& b, const TowerParts& tower);

/// What the blades are attached to: the hub itself (3 blades: its origin is the rotor apex Q) or, for
/// 2 blades, the teetering hub (elastodyn_teeter.cpp), whose origin is the teeter pin P, the apex lying
/// `apex` from it (−UndSling along the shaft) and the blades turned by δ3 about the shaft.
struct RotorHub {
  int body = -1;
  Vec3 apex = Vec3::Zero();   ///< rotor apex in the body frame [m]
  double azimuth_offset = 0;  ///< blade 1's angle about the body x from the body z [rad] (δ3)
  int teeter = -1;            ///< teeter DOF, −1 without one
};

/// The hub of a 2-bladed rotor on its teeter hinge: a body on a revolute joint about the hub's y axis
/// (ElastoDyn's teeter axis e2 = f2) carrying HubMass and the hub inertia, the DOF "teeter" (TeetDOF,
/// value TeetDefl), the teeter springs and damper of TeetMod = 1 linearized on the piece of their law
/// that holds at TeetDefl.
RotorHub addTeeteringHub(Builder& b, const DrivetrainParts& dt);

/// One blade: its body, pitch coordinate and beam (for points added later, e.g. blade elements).
struct BladeParts {
  int body = -1;
  int pitch = -1;
  ElastoDynBladeBeam beam;
  /// A BeamDyn blade (CompElast = 2): its shapes twist the sections, so points off the reference axis
  /// (AeroDyn's aerodynamic centres) move with the section's rotation.
  bool finite_element = false;
};

struct RotorParts {
  std::vector<BladeParts> blades;
  std::vector<int> pitch;  ///< pitch DOF of each blade
  /// Elastic DOFs of each blade: flap 1, edge 1, flap 2 (ElastoDyn) or the kept FE modes (BeamDyn).
  std::vector<std::vector<int>> shape_dofs;
  int teeter = -1;  ///< teeter DOF (2 blades), −1 without one
};

/// The NumBl blades on the hub (pitch joints frozen at BlPitch, twisted ElastoDyn shapes, tip masses).
RotorParts addBlades(Builder& b, const RotorHub& hub);

/// Inputs (generator torque, rotor thrust and torque, tower-top forces, collective and individual
/// pitch) and the default outputs (elastodyn_outputs.cpp; names and definitions in elastodyn_model.hpp).
void addInputsAndOutputs(Builder& b, const TowerParts& tower, const DrivetrainParts& dt, const RotorParts& rotor);

/// An output Σ gain · q^(order) over (DOF, gain) terms.
Output dofOutput(std::string name, std::string unit, int order, std::vector<std::pair<int, double>> terms);

/// ElastoDyn's platform motions in the inertial frame (elastodyn_platform.cpp), SI units (ElastoDyn prints the
/// angles in degrees): PtfmSurge, PtfmSway, PtfmHeave [m] and PtfmRoll, PtfmPitch, PtfmYaw [rad], the
/// coordinates (PtfmTDxi … , PtfmRDxi …); their rates PtfmTVxi, PtfmTVyi, PtfmTVzi [m/s] and accelerations
/// PtfmTAxi … [m/s²]; the platform's angular velocity PtfmRVxi, PtfmRVyi, PtfmRVzi [rad/s] and acceleration
/// PtfmRAxi … [rad/s²] about the ground axes. Nothing without a platform.
void addPlatformOutputs(Builder& b, const PlatformParts& platform);

/// AeroDyn's blade elements and airfoils on the blades, InflowWind's steady wind, and the input
/// "wind speed" (m/s, value HWindSpeed) (elastodyn_aero.cpp).
void addAerodynamics(Builder& b, const DrivetrainParts& dt, const RotorParts& rotor, const io::AeroDeckInput& deck);

/// ServoDyn's simple variable-speed torque law (VSContrl = 1) on the "generator torque" input at the
/// "GenSpeed" output; nothing for VSContrl = 0.
void addGeneratorTorqueLaw(Builder& b, const io::ServoDynInput& servo);

/// Shorthand for an elementary rotation about a body axis (0 = x, 1 = y, 2 = z) by `angle` [rad].
Mat3 axisRotation(int axis, double angle);

}  // namespace whirl::elastodyn

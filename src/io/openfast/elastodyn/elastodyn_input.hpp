#pragma once
/// \file
/// ElastoDyn main input file: the structural description of a turbine (DOF switches, initial
/// conditions, geometry, masses, drivetrain, tower and blade files), as plain typed data.
///
/// Members carry the ElastoDyn key names so that a value can be traced to its line in the file.
/// Units are the file's: lengths m, masses kg, inertias kg·m², but **angles in degrees** (BlPitch,
/// TeetDefl, Azimuth, NacYaw, PtfmRoll/Pitch/Yaw, PreCone, Delta3, AzimB1Up, ShftTilt, TeetDmpP,
/// TeetSStP, TeetHStP), **RotSpeed in rpm** and **GBoxEff in %**. Conversion to SI happens when the
/// model is built, not here.
///
/// Layouts read: ElastoDyn v1.00–v1.03 (FAST 8 / OpenFAST 1–2, Gravity in this file) to OpenFAST v5
/// (PitchDOF, PtfmRefxt/yt, PBrIner, BlPIner, PtfmXYIner…, YawFrctMod). Keys that only some versions
/// have are std::optional. Nothing here says whether whirl can model the turbine: see
/// openfast_support.hpp.
#include <array>
#include <filesystem>
#include <optional>
#include <vector>

#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// DEGREES OF FREEDOM section: true = the DOF is enabled.
struct ElastoDynDofs {
  bool FlapDOF1 = false;         ///< first flapwise blade mode
  bool FlapDOF2 = false;         ///< second flapwise blade mode
  bool EdgeDOF = false;          ///< first edgewise blade mode
  std::optional<bool> PitchDOF;  ///< blade pitch (OpenFAST v5 files only)
  bool TeetDOF = false;          ///< rotor teeter (2 blades only)
  bool DrTrDOF = false;          ///< drivetrain rotational flexibility
  bool GenDOF = false;           ///< generator azimuth (rotor speed free)
  bool YawDOF = false;           ///< nacelle yaw
  bool TwFADOF1 = false;         ///< first fore-aft tower mode
  bool TwFADOF2 = false;         ///< second fore-aft tower mode
  bool TwSSDOF1 = false;         ///< first side-to-side tower mode
  bool TwSSDOF2 = false;         ///< second side-to-side tower mode
  bool PtfmSgDOF = false;        ///< platform surge
  bool PtfmSwDOF = false;        ///< platform sway
  bool PtfmHvDOF = false;        ///< platform heave
  bool PtfmRDOF = false;         ///< platform roll
  bool PtfmPDOF = false;         ///< platform pitch
  bool PtfmYDOF = false;         ///< platform yaw
};

/// INITIAL CONDITIONS section (also the fixed values of disabled DOFs).
struct ElastoDynInitialConditions {
  double OoPDefl = 0.0;             ///< out-of-plane blade-tip displacement (m)
  double IPDefl = 0.0;              ///< in-plane blade-tip displacement (m)
  std::array<double, 3> BlPitch{};  ///< blade pitch angles (deg)
  double TeetDefl = 0.0;            ///< teeter angle (deg)
  double Azimuth = 0.0;             ///< azimuth of blade 1 (deg)
  double RotSpeed = 0.0;            ///< rotor speed (rpm)
  double NacYaw = 0.0;              ///< nacelle yaw angle (deg)
  double TTDspFA = 0.0;             ///< fore-aft tower-top displacement (m)
  double TTDspSS = 0.0;             ///< side-to-side tower-top displacement (m)
  double PtfmSurge = 0.0;           ///< platform surge (m)
  double PtfmSway = 0.0;            ///< platform sway (m)
  double PtfmHeave = 0.0;           ///< platform heave (m)
  double PtfmRoll = 0.0;            ///< platform roll (deg)
  double PtfmPitch = 0.0;           ///< platform pitch (deg)
  double PtfmYaw = 0.0;             ///< platform yaw (deg)
};

/// TURBINE CONFIGURATION section.
struct ElastoDynConfiguration {
  int NumBl = 3;                    ///< number of blades (-)
  double TipRad = 0.0;              ///< rotor apex to blade tip (m)
  double HubRad = 0.0;              ///< rotor apex to blade root (m)
  std::array<double, 3> PreCone{};  ///< blade cone angles (deg)
  double HubCM = 0.0;               ///< rotor apex to hub mass, positive downwind (m)
  double UndSling = 0.0;            ///< undersling, teeter pin to rotor apex (m; 2 blades)
  double Delta3 = 0.0;              ///< delta-3 angle of a teetering rotor (deg)
  double AzimB1Up = 0.0;            ///< azimuth reported when blade 1 points up (deg)
  double OverHang = 0.0;            ///< yaw axis to rotor apex, positive downwind (m)
  double ShftGagL = 0.0;            ///< rotor apex to shaft strain gages (m)
  double ShftTilt = 0.0;            ///< shaft tilt angle (deg)
  double NacCMxn = 0.0;             ///< tower top to nacelle CM, downwind (m)
  double NacCMyn = 0.0;             ///< tower top to nacelle CM, lateral (m)
  double NacCMzn = 0.0;             ///< tower top to nacelle CM, vertical (m)
  double NcIMUxn = 0.0;             ///< tower top to nacelle IMU, downwind (m)
  double NcIMUyn = 0.0;             ///< tower top to nacelle IMU, lateral (m)
  double NcIMUzn = 0.0;             ///< tower top to nacelle IMU, vertical (m)
  double Twr2Shft = 0.0;            ///< tower top to rotor shaft, vertical (m)
  double TowerHt = 0.0;             ///< tower-top height above ground / MSL (m)
  std::optional<double> TowerBsHt;  ///< tower-base height above ground / MSL (m); absent in v1.00
  std::optional<double> PtfmCMxt;   ///< ground/MSL to platform CM, downwind (m); absent in older files
  std::optional<double> PtfmCMyt;   ///< ground/MSL to platform CM, lateral (m); absent in older files
  std::optional<double> PtfmCMzt;   ///< ground/MSL to platform CM, vertical (m)
  std::optional<double> PtfmRefxt;  ///< ground/MSL to platform reference point, downwind (m; v5)
  std::optional<double> PtfmRefyt;  ///< ground/MSL to platform reference point, lateral (m; v5)
  std::optional<double> PtfmRefzt;  ///< ground/MSL to platform reference point, vertical (m)
  std::optional<double> TwrRBHt;    ///< rigid tower-base height (m; v1.00 files only)
  std::optional<double> TwrDraft;   ///< ground/MSL down to the tower base (m; v1.00 files only)
  std::optional<double> PtfmRef;    ///< ground/MSL down to the platform reference (m; v1.00 files only)
};

/// MASS AND INERTIA section.
struct ElastoDynMassInertia {
  std::array<double, 3> TipMass{};               ///< tip-brake masses (kg)
  std::optional<std::array<double, 3>> PBrIner;  ///< pitch bearing/actuator inertias (kg·m²; v5)
  std::optional<std::array<double, 3>> BlPIner;  ///< pitch inertias of the undeflected blades (kg·m²; v5)
  double HubMass = 0.0;                          ///< hub mass (kg)
  double HubIner = 0.0;                          ///< hub inertia about the rotor axis (kg·m²)
  std::optional<double> HubIner_Teeter;          ///< hub inertia about the teeter axis (kg·m²; v4.2+)
  double GenIner = 0.0;                          ///< generator inertia about the high-speed shaft (kg·m²)
  double NacMass = 0.0;                          ///< nacelle mass (kg)
  double NacYIner = 0.0;                         ///< nacelle inertia about the yaw axis (kg·m²)
  double YawBrMass = 0.0;                        ///< yaw-bearing mass (kg)
  double PtfmMass = 0.0;                         ///< platform mass (kg)
  double PtfmRIner = 0.0;                        ///< platform roll inertia about its CM (kg·m²)
  double PtfmPIner = 0.0;                        ///< platform pitch inertia about its CM (kg·m²)
  double PtfmYIner = 0.0;                        ///< platform yaw inertia about its CM (kg·m²)
  std::optional<double> PtfmXYIner;              ///< platform xy product of inertia (kg·m²; v4+)
  std::optional<double> PtfmYZIner;              ///< platform yz product of inertia (kg·m²; v4+)
  std::optional<double> PtfmXZIner;              ///< platform xz product of inertia (kg·m²; v4+)
};

/// ROTOR-TEETER section, read when present (used only for 2-bladed rotors).
struct ElastoDynTeeter {
  std::optional<int> TeetMod;      ///< teeter spring/damper model (switch)
  std::optional<double> TeetDmpP;  ///< damper position (deg)
  std::optional<double> TeetDmp;   ///< damping constant (N·m/(rad/s))
  std::optional<double> TeetCDmp;  ///< Coulomb-damping moment (N·m)
  std::optional<double> TeetSStP;  ///< soft-stop position (deg)
  std::optional<double> TeetHStP;  ///< hard-stop position (deg)
  std::optional<double> TeetSSSp;  ///< soft-stop spring constant (N·m/rad)
  std::optional<double> TeetHSSp;  ///< hard-stop spring constant (N·m/rad)
};

/// DRIVETRAIN section.
struct ElastoDynDrivetrain {
  double GBoxEff = 100.0;  ///< gearbox efficiency (%)
  double GBRatio = 1.0;    ///< gearbox ratio (-)
  double DTTorSpr = 0.0;   ///< drivetrain torsional spring, low-speed side (N·m/rad)
  double DTTorDmp = 0.0;   ///< drivetrain torsional damper, low-speed side (N·m/(rad/s))
};

/// Contents of an ElastoDyn main input file with its tower and blade files.
struct ElastoDynInput {
  OpenFastFile source;  ///< the parsed file (path, line of every key: source.where(key, reason))

  std::optional<double> Gravity;  ///< gravitational acceleration (m/s²); in this file up to v1.03 only
  ElastoDynDofs dof;
  ElastoDynInitialConditions init;
  ElastoDynConfiguration config;
  ElastoDynMassInertia mass;
  std::optional<int> BldNodes;                 ///< blade analysis nodes (-); absent in v1.00–v1.01 files
  std::vector<std::filesystem::path> BldFile;  ///< resolved blade file of each blade (NumBl entries)
  ElastoDynTeeter teeter;
  ElastoDynDrivetrain drivetrain;
  std::optional<int> YawFrctMod;   ///< yaw-friction model (switch; OpenFAST v4+)
  bool Furling = false;            ///< furling turbine (flag)
  std::filesystem::path FurlFile;  ///< resolved furling file name (not read)
  int TwrNodes = 0;                ///< tower analysis nodes (-)
  std::filesystem::path TwrFile;   ///< resolved tower file

  ElastoDynTower tower;                ///< contents of TwrFile
  std::vector<ElastoDynBlade> blades;  ///< contents of BldFile(k), one per blade
};

/// Reads an ElastoDyn main file and the tower and blade files it names (resolved against its folder).
/// `overrides` (may be null) are applied to every file before reading values. Checks values (counts,
/// non-negative masses, TipRad > HubRad, GBRatio > 0 …) but not whether whirl supports the options.
/// Throws InputError naming file, line and key for anything missing, malformed or out of range,
/// including a tower or blade file that does not exist.
ElastoDynInput readElastoDyn(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

}  // namespace whirl::io

#pragma once
/// \file
/// AeroDyn v15 main input file, normalized across layouts into one description: wake/induction model,
/// airfoil aerodynamics, tower influence, environment, BEM options, airfoil and blade file names, tower
/// table. Values stay in the file's units (angles deg; AirDens kg/m³, KinVisc m²/s).
///
/// Layouts read (keys matched case-insensitively, absent keys of a layout take OpenFAST's defaults):
/// - **v15** — AeroDyn v15.02–v15.04 (FAST 8 certification tests, OpenFAST v1–v3.5): `WakeMod`
///   {0 none, 1 BEMT, 2 DBEMT, 3 OLAF}, `AFAeroMod` {1 steady, 2 unsteady}, `SkewMod` {0 orthogonal,
///   1 uncoupled, 2 Pitt/Peters, 3 coupled} with `SkewModFactor` (v2+); `TwrShadow` a True/False flag up
///   to OpenFAST v2.x, a switch {0, 1, 2} from v3.0; `FrozenWake`, `CavitCheck`, `DBEMT_Mod` (v2.2+),
///   `AFTabMod` (v2.3+), `CompAA` (v2.5+), `Buoyancy`, `TFinAero` (v3.4+); absent keys read as off.
/// - **v4** — OpenFAST v4.0–v5.0 (`Wake_Mod` present): `Wake_Mod` {0 none, 1 BEMT, 3 OLAF}, `BEM_Mod`,
///   `Skew_Mod` {−1 orthogonal, 0 none, 1 active} with `SkewMomCorr`, `SkewRedistr_Mod`,
///   `SkewRedistrFactor`, `SectAvg`…, `DBEMT_Mod` {−1 frozen wake, 0 none, 1–3 dynamic}, `UA_Mod`
///   {0 quasi-steady, 2–7 unsteady}, `NacelleDrag`; `Buoyancy` up to v4.x (v5: implied by the .fst `MHK`).
///   Legacy keys in a v4 file (WakeMod, AFAeroMod, FrozenWake, SkewMod, UAMod) are mapped as OpenFAST v5
///   maps them, except that FrozenWake = True always means a frozen wake.
///
/// Nothing here says whether whirl can model the options: see aero_support.hpp.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/distributed_table.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;
struct FstInput;

/// Which generation of keys the file uses.
enum class AeroDynLayout {
  V15,  ///< WakeMod / AFAeroMod / FrozenWake / SkewMod (AeroDyn v15.0x, OpenFAST up to v3.5)
  V4,   ///< Wake_Mod / UA_Mod / DBEMT_Mod = −1 / Skew_Mod (OpenFAST v4.0 to v5)
};

/// Skewed-wake correction, normalized to OpenFAST v4's Skew_Mod.
enum class SkewModel {
  Orthogonal,  ///< Skew_Mod = −1 (legacy SkewMod = 0): remove the non-normal inflow component
  None,        ///< Skew_Mod = 0 (legacy SkewMod = 1, "uncoupled"): no skew model
  Active,      ///< Skew_Mod = 1 (legacy SkewMod = 2, Pitt/Peters): skew model with redistribution
  Coupled,     ///< legacy SkewMod = 3 ("coupled", never implemented; refused by OpenFAST v4+)
};

/// Environment values AeroDyn's "default" stands for: those of the .fst (OpenFAST v3+), else OpenFAST's
/// built-in values.
struct AeroDynEnvironment {
  double AirDens = 1.225;     ///< air density (kg/m³)
  double KinVisc = 1.464e-5;  ///< kinematic viscosity (m²/s)
  double SpdSound = 335.0;    ///< speed of sound (m/s)
  double Patm = 103500.0;     ///< atmospheric pressure (Pa)
  double Pvap = 1700.0;       ///< vapour pressure (Pa)
};

/// The environment of a .fst: its AirDens, KinVisc, SpdSound, Patm, Pvap where it has them (OpenFAST
/// v3+), OpenFAST's defaults otherwise.
AeroDynEnvironment aerodynEnvironment(const FstInput& fst);

/// An AeroDyn v15 main file, normalized.
struct AeroDynInput {
  OpenFastFile source;  ///< the parsed file (path, line of every key: source.where(key, reason))
  AeroDynLayout layout = AeroDynLayout::V15;

  // ---- wake / induction ----
  /// Wake model, as OpenFAST v4's Wake_Mod: {0 none (no induction), 1 BEMT, 3 OLAF}; legacy WakeMod = 2
  /// (DBEMT) reads as 1 with `DBEMT_Mod` > 0; other values are kept as read.
  int Wake_Mod = 1;
  std::string wake_key = "WakeMod";  ///< key the wake model was read from ("WakeMod" or "Wake_Mod")
  /// Dynamic BEMT, as OpenFAST v4's DBEMT_Mod: {−1 frozen wake, 0 quasi-steady, 1–3 dynamic}. From the file
  /// in the v4 layout; in the v15 layout −1 when FrozenWake = True, the file's DBEMT_Mod when WakeMod = 2,
  /// else 0 (DBEMT_Mod is unused there).
  int DBEMT_Mod = 0;
  std::string dbemt_key = "DBEMT_Mod";  ///< key that set DBEMT_Mod ("DBEMT_Mod", "FrozenWake" or "WakeMod")
  bool frozen_wake = false;             ///< induction held at its operating-point value when linearizing
  /// DBEMT's time constant τ1 [s] (`tau1_const`, used with DBEMT_Mod 1 and 3; must then be > 0, AeroDyn's
  /// DBEMT_ValidateInitInp); nullopt when absent.
  std::optional<double> tau1_const;

  // ---- airfoil aerodynamics ----
  /// Unsteady airfoil model, as OpenFAST v4's UA_Mod: 0 quasi-steady; > 0 a dynamic-stall model
  /// (legacy AFAeroMod = 2 reads as the file's UAMod).
  int UA_Mod = 0;
  std::string ua_key = "AFAeroMod";  ///< key that decided it ("AFAeroMod" or "UA_Mod")
  bool unsteadyAero() const { return UA_Mod > 0; }
  /// The span over which UA runs, as fractions of the largest element radius (`UAStartRad`, `UAEndRad`;
  /// AeroDyn: 0 and 1 when the lines are missing; elements below UAStartRad or above UAEndRad have no UA).
  double UAStartRad = 0.0;
  double UAEndRad = 1.0;
  bool AoA34 = true;  ///< angle of attack at 3/4 chord (`AoA34`, OpenFAST v4+; true when absent)

  // ---- other physics switches (0 / false = off) ----
  int TwrPotent = 0;         ///< tower potential flow {0 none, 1 baseline, 2 Bak correction}
  int TwrShadow = 0;         ///< tower shadow {0 none, 1 Powles, 2 Eames}; a v15.0x True reads as 1
  bool TwrAero = false;      ///< tower drag loads
  bool Buoyancy = false;     ///< buoyancy (OpenFAST v3.2–v4.x key)
  bool CavitCheck = false;   ///< cavitation check
  bool CompAA = false;       ///< aeroacoustics
  bool NacelleDrag = false;  ///< nacelle drag (v4+)
  bool SectAvg = false;      ///< sector-averaged inflow (v4+)
  bool TFinAero = false;     ///< tail-fin aerodynamics (v3.2+)
  int BEM_Mod = 1;           ///< BEM formulation {1 legacy (no sweep/pitch/twist), 2 polar}; 1 when absent (v15)

  // ---- environment (resolved: "default" → AeroDynEnvironment) ----
  double AirDens = 1.225;        ///< air density (kg/m³), > 0
  double KinVisc = 1.464e-5;     ///< kinematic viscosity (m²/s), > 0
  double SpdSound = 335.0;       ///< speed of sound (m/s)
  double Patm = 103500.0;        ///< atmospheric pressure (Pa)
  double Pvap = 1700.0;          ///< vapour pressure (Pa)
  bool AirDens_default = false;  ///< AirDens was "default" (or absent)
  bool KinVisc_default = false;  ///< KinVisc was "default" (or absent)

  // ---- BEM options ----
  SkewModel skew = SkewModel::Active;
  std::string skew_key = "SkewMod";  ///< key the skew model was read from ("SkewMod" or "Skew_Mod")
  double SkewModFactor = 15.0 * 3.14159265358979323846 / 32.0;  ///< Pitt/Peters constant (-), "default" = 15π/32
  int SkewRedistr_Mod = 1;   ///< {0 no redistribution, 1 Glauert/Pitt–Peters}; v15: 1 when SkewMod = 2, else 0
  bool SkewMomCorr = false;  ///< skew momentum correction (v4+)
  bool TipLoss = true;       ///< Prandtl tip loss
  bool HubLoss = true;       ///< Prandtl hub loss
  bool TanInd = true;        ///< tangential induction
  bool AIDrag = true;        ///< drag term in the axial induction
  bool TIDrag = true;        ///< drag term in the tangential induction
  std::optional<double>
      IndToler;       ///< BEMT residual tolerance (-), > 0; nullopt = "default" (OpenFAST: 5e-5 single, 5e-10 double)
  int MaxIter = 100;  ///< BEMT iteration limit, >= 1

  // ---- airfoils ----
  int AFTabMod = 1;      ///< {1 first table only, 2 2-D on Re, 3 2-D on UserProp}; 1 when absent
  AirfoilColumns InCol;  ///< InCol_Alfa, InCol_Cl, InCol_Cd, InCol_Cm (0 = no Cm column)
  int InCol_Cpmin = 0;   ///< Cpmin column, 0 = none
  std::vector<std::filesystem::path>
      AFNames;                     ///< airfoil files (resolved against this file's folder), NumAFfiles of them
  std::vector<int> AFNames_lines;  ///< file line of each name
  bool UseBlCm = true;             ///< include the pitching moment

  // ---- blades and tower ----
  std::vector<std::filesystem::path>
      ADBlFile;       ///< blade file of ADBlFile(1), (2), (3) as present (resolved, not checked)
  int NumTwrNds = 0;  ///< tower nodes
  DistributedTable
      tower;  ///< TwrElev, TwrDiam, TwrCd [, TwrTI, TwrCb, TwrCp, TwrCa] as in the file; empty when NumTwrNds = 0
};

/// Reads an AeroDyn v15 main file (any layout above); `env` gives what "default" environment values
/// mean. Checks: AirDens > 0, KinVisc > 0, MaxIter >= 1, IndToler > 0, NumAFfiles >= 1 with that many
/// names, InCol_Alfa/Cl/Cd >= 1 and InCol_Cm/Cpmin >= 0, known Skew_Mod/SkewMod values, not both a key and
/// its legacy spelling, the tower table complete. Files named are not opened (see readAeroDeck).
/// Throws InputError "file:line: key: reason".
AeroDynInput readAeroDyn(const std::filesystem::path& file, const AeroDynEnvironment& env = {},
                         OverrideSet* overrides = nullptr);

}  // namespace whirl::io

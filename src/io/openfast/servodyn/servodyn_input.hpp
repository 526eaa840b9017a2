#pragma once
/// \file
/// ServoDyn input file: the nacelle-yaw spring and damper (structural models need nothing else), the
/// control switches, and the generator-torque law (simple variable-speed controller or generator model)
/// that an aerodynamic operating point needs. Layout unchanged from FAST 8 (ServoDyn v1.05) to OpenFAST v5
/// for these keys.
#include <filesystem>
#include <optional>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class OverrideSet;

/// Yaw spring/damper, control switches and generator keys of a ServoDyn file, in the file's units
/// (YawNeut deg, speeds rpm on the high-speed shaft, torques N·m on the high-speed shaft, GenEff and
/// slips in %). The control and generator keys are optional here so that a file cut down to its yaw
/// section still reads; generatorTorqueLaw() requires them.
struct ServoDynInput {
  OpenFastFile source;   ///< the parsed file (path, line of every key: source.where(key, reason))
  int YCMode = 0;        ///< yaw control mode {0 none, 3 user routine, 4 Simulink, 5 DLL} (switch)
  double YawNeut = 0.0;  ///< neutral yaw position: the yaw spring moment is zero there (deg)
  double YawSpr = 0.0;   ///< nacelle-yaw spring constant (N·m/rad)
  double YawDamp = 0.0;  ///< nacelle-yaw damping constant (N·m/(rad/s))

  std::optional<int> PCMode;  ///< pitch control {0 none, 3 user routine, 4 Simulink, 5 Bladed DLL}
  std::optional<int>
      VSContrl;  ///< variable-speed control {0 none: GenModel, 1 simple VS, 3 routine, 4 Simulink, 5 DLL}
  std::optional<int> GenModel;      ///< generator model when VSContrl = 0 {1 simple induction, 2 Thevenin, 3 user}
  std::optional<double> GenEff;     ///< generator efficiency (%)
  std::optional<double> VS_RtGnSp;  ///< rated generator speed of the simple VS law (rpm, HSS)
  std::optional<double> VS_RtTq;    ///< rated (region 3) generator torque of the simple VS law (N·m, HSS)
  std::optional<double> VS_Rgn2K;   ///< region-2 torque constant, torque = VS_Rgn2K·speed² (N·m/rpm², HSS)
  std::optional<double> VS_SlPc;    ///< rated slip of the region 2½ line of the simple VS law (%)
  std::optional<double> SIG_SlPc;   ///< rated slip of the simple induction generator (%)
  std::optional<double> SIG_SySp;   ///< synchronous (zero-torque) speed of the simple induction generator (rpm, HSS)
  std::optional<double> SIG_RtTq;   ///< rated torque of the simple induction generator (N·m, HSS)
  std::optional<double> SIG_PORt;   ///< pull-out ratio of the simple induction generator, Tpullout/Trated (-)
};

/// Reads the yaw keys of a ServoDyn file (YawSpr and YawDamp must not be negative) and, when present,
/// the control and generator keys. Throws InputError naming file, line and key.
ServoDynInput readServoDyn(const std::filesystem::path& file, OverrideSet* overrides = nullptr);

/// How ServoDyn sets the generator torque.
enum class TorqueControl {
  SimpleVariableSpeed,         ///< VSContrl = 1: ServoDyn's simple variable-speed law (VS_* keys)
  SimpleInductionGenerator,    ///< VSContrl = 0, GenModel = 1: torque from the slip (SIG_* keys)
  TheveninInductionGenerator,  ///< VSContrl = 0, GenModel = 2: Thevenin-equivalent circuit (TEC_* keys)
};

/// The generator-torque law of a ServoDyn file, in the file's units (HSS side).
struct GeneratorTorqueLaw {
  TorqueControl mode = TorqueControl::SimpleVariableSpeed;
  double GenEff = 100.0;   ///< generator efficiency (%), in (0, 100]
  double VS_RtGnSp = 0.0;  ///< [SimpleVariableSpeed] rated generator speed (rpm), > 0
  double VS_RtTq = 0.0;    ///< [SimpleVariableSpeed] rated torque (N·m), >= 0
  double VS_Rgn2K = 0.0;   ///< [SimpleVariableSpeed] region-2 constant (N·m/rpm²), >= 0
  double VS_SlPc = 0.0;    ///< [SimpleVariableSpeed] rated slip (%), > 0
  double SIG_SlPc = 0.0;   ///< [SimpleInductionGenerator] rated slip (%), > 0
  double SIG_SySp = 0.0;   ///< [SimpleInductionGenerator] synchronous speed (rpm), > 0
  double SIG_RtTq = 0.0;   ///< [SimpleInductionGenerator] rated torque (N·m), >= 0
  double SIG_PORt = 0.0;   ///< [SimpleInductionGenerator] pull-out ratio (-), >= 1
  double TEC_Freq = 0.0;   ///< [TheveninInductionGenerator] line frequency (Hz), > 0
  int TEC_NPol = 0;        ///< [TheveninInductionGenerator] number of poles, even, > 0
  double TEC_SRes = 0.0;   ///< [TheveninInductionGenerator] stator resistance (ohms), >= 0
  double TEC_RRes = 0.0;   ///< [TheveninInductionGenerator] rotor resistance (ohms), > 0
  double TEC_VLL = 0.0;    ///< [TheveninInductionGenerator] line-to-line RMS voltage (volts), > 0
  double TEC_SLR = 0.0;    ///< [TheveninInductionGenerator] stator leakage reactance (ohms), >= 0
  double TEC_RLR = 0.0;    ///< [TheveninInductionGenerator] rotor leakage reactance (ohms), >= 0
  double TEC_MR = 0.0;     ///< [TheveninInductionGenerator] magnetizing reactance (ohms), > 0
};

/// The torque law, for callers that need the generator torque (aerodynamic operating points).
/// Refuses, with "file:line: key: value not supported by whirl (…; whirl supports only …)", a
/// controller in user code (VSContrl = 3 routine, 4 Simulink/LabVIEW, 5 Bladed-style DLL) and, with
/// VSContrl = 0, a generator in a user routine (GenModel = 3). Throws InputError when a key the law
/// needs is missing or out of range.
GeneratorTorqueLaw generatorTorqueLaw(const ServoDynInput& servo);

/// A generator torque from a controller in user code (VSContrl = 3 routine, 4 Simulink/LabVIEW, 5
/// Bladed-style DLL), which whirl cannot run: "file:line: VSContrl: value: what it is: the linear model
/// is open loop …", the note under which an aerodynamic model is built without a torque law (generator
/// torque an input, as a controller designer's plant model has it). Nothing for the laws whirl models.
std::optional<std::string> externalTorqueController(const ServoDynInput& servo);

}  // namespace whirl::io

#include "src/io/openfast/servodyn/servodyn_input.hpp"

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// "file:line: key: <value> not supported by whirl (<what>; whirl supports only <supported>)".
InputError refusal(const OpenFastFile& f, const char* key, const std::string& what, const std::string& supported) {
  const OpenFastEntry* e = f.find(key);
  return InputError(f.where(key, (e ? e->raw : std::string("?")) + " not supported by whirl (" + what +
                                     "; whirl supports only " + supported + ")"));
}

}  // namespace

ServoDynInput readServoDyn(const std::filesystem::path& file, OverrideSet* overrides) {
  ServoDynInput s;
  s.source = OpenFastFile::read(file);
  s.source.checkLayout(servoDynLayout());
  if (overrides) overrides->applyTo(s.source);
  const OpenFastFile& f = s.source;
  s.YCMode = f.getInt("YCMode");
  s.YawNeut = f.getDouble("YawNeut");
  s.YawSpr = f.getDouble("YawSpr");
  s.YawDamp = f.getDouble("YawDamp");
  requireNonnegative(f, "YawSpr", s.YawSpr);
  requireNonnegative(f, "YawDamp", s.YawDamp);

  s.PCMode = f.findInt("PCMode");
  s.VSContrl = f.findInt("VSContrl");
  s.GenModel = f.findInt("GenModel");
  s.GenEff = f.findDouble("GenEff");
  s.VS_RtGnSp = f.findDouble("VS_RtGnSp");
  s.VS_RtTq = f.findDouble("VS_RtTq");
  s.VS_Rgn2K = f.findDouble("VS_Rgn2K");
  s.VS_SlPc = f.findDouble("VS_SlPc");
  s.SIG_SlPc = f.findDouble("SIG_SlPc");
  s.SIG_SySp = f.findDouble("SIG_SySp");
  s.SIG_RtTq = f.findDouble("SIG_RtTq");
  s.SIG_PORt = f.findDouble("SIG_PORt");
  return s;
}

GeneratorTorqueLaw generatorTorqueLaw(const ServoDynInput& servo) {
  const OpenFastFile& f = servo.source;
  GeneratorTorqueLaw law;
  const int vs = f.getInt("VSContrl");
  const char* supported = "VSContrl = 1 (simple variable-speed law) or 0 with GenModel = 1 or 2 (induction generator)";
  if (vs == 3) throw refusal(f, "VSContrl", "torque from the user routine UserVSCont", supported);
  if (vs == 4) throw refusal(f, "VSContrl", "torque from Simulink/LabVIEW", supported);
  if (vs == 5) throw refusal(f, "VSContrl", "torque from a Bladed-style controller DLL", supported);
  if (vs != 0 && vs != 1)
    throw InputError(f.where("VSContrl", "must be 0, 1, 3, 4 or 5 (is " + std::to_string(vs) + ")"));
  law.GenEff = f.getDouble("GenEff");
  if (!(law.GenEff > 0.0 && law.GenEff <= 100.0))
    throw InputError(f.where("GenEff", "must be in (0, 100] % (is " + numberText(law.GenEff) + ")"));
  if (vs == 1) {
    law.mode = TorqueControl::SimpleVariableSpeed;
    law.VS_RtGnSp = f.getDouble("VS_RtGnSp");
    law.VS_RtTq = f.getDouble("VS_RtTq");
    law.VS_Rgn2K = f.getDouble("VS_Rgn2K");
    law.VS_SlPc = f.getDouble("VS_SlPc");
    requirePositive(f, "VS_RtGnSp", law.VS_RtGnSp);
    requireNonnegative(f, "VS_RtTq", law.VS_RtTq);
    requireNonnegative(f, "VS_Rgn2K", law.VS_Rgn2K);
    requirePositive(f, "VS_SlPc", law.VS_SlPc);
    return law;
  }
  const int gen = f.getInt("GenModel");
  const char* gen_supported = "GenModel = 1 (simple induction generator) or 2 (Thevenin) when VSContrl = 0";
  if (gen == 3) throw refusal(f, "GenModel", "generator from the user routine UserGen", gen_supported);
  if (gen != 1 && gen != 2) throw InputError(f.where("GenModel", "must be 1, 2 or 3 (is " + std::to_string(gen) + ")"));
  if (gen == 2) {
    law.mode = TorqueControl::TheveninInductionGenerator;
    law.TEC_Freq = f.getDouble("TEC_Freq");
    law.TEC_NPol = f.getInt("TEC_NPol");
    law.TEC_SRes = f.getDouble("TEC_SRes");
    law.TEC_RRes = f.getDouble("TEC_RRes");
    law.TEC_VLL = f.getDouble("TEC_VLL");
    law.TEC_SLR = f.getDouble("TEC_SLR");
    law.TEC_RLR = f.getDouble("TEC_RLR");
    law.TEC_MR = f.getDouble("TEC_MR");
    requirePositive(f, "TEC_Freq", law.TEC_Freq);
    if (!(law.TEC_NPol > 0 && law.TEC_NPol % 2 == 0))
      throw InputError(
          f.where("TEC_NPol", "must be a positive even number of poles (is " + std::to_string(law.TEC_NPol) + ")"));
    requireNonnegative(f, "TEC_SRes", law.TEC_SRes);
    requirePositive(f, "TEC_RRes", law.TEC_RRes);
    requirePositive(f, "TEC_VLL", law.TEC_VLL);
    requireNonnegative(f, "TEC_SLR", law.TEC_SLR);
    requireNonnegative(f, "TEC_RLR", law.TEC_RLR);
    requirePositive(f, "TEC_MR", law.TEC_MR);
    return law;
  }
  law.mode = TorqueControl::SimpleInductionGenerator;
  law.SIG_SlPc = f.getDouble("SIG_SlPc");
  law.SIG_SySp = f.getDouble("SIG_SySp");
  law.SIG_RtTq = f.getDouble("SIG_RtTq");
  law.SIG_PORt = f.getDouble("SIG_PORt");
  requirePositive(f, "SIG_SlPc", law.SIG_SlPc);
  requirePositive(f, "SIG_SySp", law.SIG_SySp);
  requireNonnegative(f, "SIG_RtTq", law.SIG_RtTq);
  if (!(law.SIG_PORt >= 1.0))
    throw InputError(
        f.where("SIG_PORt", "must be at least 1 (pull-out over rated torque, is " + numberText(law.SIG_PORt) + ")"));
  return law;
}

std::optional<std::string> externalTorqueController(const ServoDynInput& servo) {
  const int vs = servo.VSContrl.value_or(0);
  const char* what = vs == 3   ? "torque from the user routine UserVSCont"
                     : vs == 4 ? "torque from Simulink/LabVIEW"
                     : vs == 5 ? "torque from a Bladed-style controller DLL"
                               : nullptr;
  if (!what) return std::nullopt;
  const OpenFastFile& f = servo.source;
  std::error_code ec;
  if (vs == 5 && f.has("DLL_InFile") && std::filesystem::is_regular_file(f.getPath("DLL_InFile"), ec))
    return f.where("VSContrl", f.find("VSContrl")->raw +
                                   ": torque (and pitch) from ROSCO, whose DISCON.IN whirl reads (io::readDiscon): the "
                                   "trim along the wind settles where that controller does; the linear model is open "
                                   "loop (generator torque and pitch are inputs)");
  return f.where("VSContrl", f.find("VSContrl")->raw + ": " + what +
                                 ", which whirl does not run: the linear model is open loop (the generator torque "
                                 "is an input, its speed feedback left out); trimming along the wind needs a torque "
                                 "law (VSContrl = 1)");
}

}  // namespace whirl::io

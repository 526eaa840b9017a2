#include "src/io/servodyn_input.hpp"

#include "src/io/elastodyn_common.hpp"
#include "src/io/openfast_overrides.hpp"
#include "src/model/error.hpp"

namespace whirl::io {
namespace {

/// "file:line: key: <value> not supported by whirl (<what>; whirl supports only <supported>)".
InputError refusal(const OpenFastFile& f, const char* key, const std::string& what, const std::string& supported) {
  const OpenFastEntry* e = f.find(key);
  return InputError(f.where(key, (e ? e->raw : std::string("?")) + " not supported by whirl (" + what +
                                     "; whirl supports only " + supported + ")"));
}

}  // namespace

ServoDynInput read_servodyn(const std::filesystem::path& file, OverrideSet* overrides) {
  ServoDynInput s;
  s.source = OpenFastFile::read(file);
  s.source.check_layout(OpenFastLayout{"ServoDyn", {}, {}});  // duplicates only: many keys across versions
  if (overrides) overrides->apply_to(s.source);
  const OpenFastFile& f = s.source;
  s.YCMode = f.get_int("YCMode");
  s.YawNeut = f.get_double("YawNeut");
  s.YawSpr = f.get_double("YawSpr");
  s.YawDamp = f.get_double("YawDamp");
  require_nonnegative(f, "YawSpr", s.YawSpr);
  require_nonnegative(f, "YawDamp", s.YawDamp);

  s.PCMode = f.find_int("PCMode");
  s.VSContrl = f.find_int("VSContrl");
  s.GenModel = f.find_int("GenModel");
  s.GenEff = f.find_double("GenEff");
  s.VS_RtGnSp = f.find_double("VS_RtGnSp");
  s.VS_RtTq = f.find_double("VS_RtTq");
  s.VS_Rgn2K = f.find_double("VS_Rgn2K");
  s.VS_SlPc = f.find_double("VS_SlPc");
  s.SIG_SlPc = f.find_double("SIG_SlPc");
  s.SIG_SySp = f.find_double("SIG_SySp");
  s.SIG_RtTq = f.find_double("SIG_RtTq");
  s.SIG_PORt = f.find_double("SIG_PORt");
  return s;
}

GeneratorTorqueLaw generator_torque_law(const ServoDynInput& servo) {
  const OpenFastFile& f = servo.source;
  GeneratorTorqueLaw law;
  const int vs = f.get_int("VSContrl");
  const char* supported = "VSContrl = 1 (simple variable-speed law) or 0 with GenModel = 1 (simple induction generator)";
  if (vs == 3) throw refusal(f, "VSContrl", "torque from the user routine UserVSCont", supported);
  if (vs == 4) throw refusal(f, "VSContrl", "torque from Simulink/LabVIEW", supported);
  if (vs == 5) throw refusal(f, "VSContrl", "torque from a Bladed-style controller DLL", supported);
  if (vs != 0 && vs != 1) throw InputError(f.where("VSContrl", "must be 0, 1, 3, 4 or 5 (is " + std::to_string(vs) + ")"));
  law.GenEff = f.get_double("GenEff");
  if (!(law.GenEff > 0.0 && law.GenEff <= 100.0))
    throw InputError(f.where("GenEff", "must be in (0, 100] % (is " + number_text(law.GenEff) + ")"));
  if (vs == 1) {
    law.mode = TorqueControl::SimpleVariableSpeed;
    law.VS_RtGnSp = f.get_double("VS_RtGnSp");
    law.VS_RtTq = f.get_double("VS_RtTq");
    law.VS_Rgn2K = f.get_double("VS_Rgn2K");
    law.VS_SlPc = f.get_double("VS_SlPc");
    require_positive(f, "VS_RtGnSp", law.VS_RtGnSp);
    require_nonnegative(f, "VS_RtTq", law.VS_RtTq);
    require_nonnegative(f, "VS_Rgn2K", law.VS_Rgn2K);
    require_positive(f, "VS_SlPc", law.VS_SlPc);
    return law;
  }
  const int gen = f.get_int("GenModel");
  const char* gen_supported = "GenModel = 1 (simple induction generator) when VSContrl = 0";
  if (gen == 2) throw refusal(f, "GenModel", "Thevenin-equivalent induction generator", gen_supported);
  if (gen == 3) throw refusal(f, "GenModel", "generator from the user routine UserGen", gen_supported);
  if (gen != 1) throw InputError(f.where("GenModel", "must be 1, 2 or 3 (is " + std::to_string(gen) + ")"));
  law.mode = TorqueControl::SimpleInductionGenerator;
  law.SIG_SlPc = f.get_double("SIG_SlPc");
  law.SIG_SySp = f.get_double("SIG_SySp");
  law.SIG_RtTq = f.get_double("SIG_RtTq");
  law.SIG_PORt = f.get_double("SIG_PORt");
  require_positive(f, "SIG_SlPc", law.SIG_SlPc);
  require_positive(f, "SIG_SySp", law.SIG_SySp);
  require_nonnegative(f, "SIG_RtTq", law.SIG_RtTq);
  if (!(law.SIG_PORt >= 1.0))
    throw InputError(f.where("SIG_PORt", "must be at least 1 (pull-out over rated torque, is " + number_text(law.SIG_PORt) + ")"));
  return law;
}

}  // namespace whirl::io

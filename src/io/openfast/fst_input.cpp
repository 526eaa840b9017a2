#include "src/io/openfast/fst_input.hpp"

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// An integer switch, or a FAST 8.0x True/False flag (1/0); `fallback` when the key is absent.
int switchOr(const OpenFastFile& f, std::string_view key, int fallback) {
  const OpenFastEntry* e = f.find(key);
  if (!e) return fallback;
  if (e->tokens.size() == 1 && !parseFortranDouble(e->tokens.front())) return f.getBool(key) ? 1 : 0;
  return f.getInt(key);
}

/// The path of the first of `keys` present in the file, or nullopt.
std::optional<std::filesystem::path> pathOfFirst(const OpenFastFile& f, std::initializer_list<const char*> keys) {
  for (const char* k : keys)
    if (f.has(k)) return f.getPath(k);
  return std::nullopt;
}

/// A FAST v7 (or v6) primary file has the whole structural model inline and no EDFile; its keys
/// ADAMSPrep/AnalMode and the turbine's TwrFile left the .fst in FAST v8, which moved the structure into
/// ElastoDyn [JonkmanJonkman2016]. Say so instead of "EDFile: key not found".
void requireNotFast7(const OpenFastFile& f) {
  if (f.has("EDFile")) return;
  for (const char* key : {"ADAMSPrep", "AnalMode", "TwrFile"}) {
    if (!f.has(key)) continue;
    throw InputError(f.where(key,
                             "this is a FAST v7 primary input file (the turbine is inline, there is no "
                             "EDFile): whirl reads FAST v8 and OpenFAST decks, whose .fst names an "
                             "ElastoDyn file; convert it with ConvertFAST7to8.m (OpenFAST "
                             "matlab-toolbox, ConvertFASTversions) or use the FAST v8 deck of the same turbine"));
  }
}

}  // namespace

FstInput readFst(const std::filesystem::path& file, OverrideSet* overrides) {
  FstInput in;
  in.source = OpenFastFile::read(file);
  requireNotFast7(in.source);  // before the layout, whose "not a key" would hide the reason
  in.source.checkLayout(fstLayout());
  if (overrides) overrides->applyTo(in.source);
  const OpenFastFile& f = in.source;

  in.Gravity = f.findDouble("Gravity");
  if (in.Gravity) requireGravity(f, *in.Gravity);
  in.CompElast = switchOr(f, "CompElast", 1);
  in.CompInflow = switchOr(f, "CompInflow", 0);
  in.CompAero = switchOr(f, "CompAero", 0);
  in.CompServo = switchOr(f, "CompServo", 0);
  in.CompSeaSt = switchOr(f, "CompSeaSt", 0);
  in.CompHydro = switchOr(f, "CompHydro", 0);
  in.CompSub = switchOr(f, "CompSub", 0);
  in.CompMooring = switchOr(f, "CompMooring", 0);
  in.MHK = f.findInt("MHK");
  in.NRotors = f.findInt("NRotors");
  in.AirDens = f.findDouble("AirDens");
  in.KinVisc = f.findDouble("KinVisc");
  in.SpdSound = f.findDouble("SpdSound");
  in.Patm = f.findDouble("Patm");
  in.Pvap = f.findDouble("Pvap");
  if (in.AirDens) requirePositive(f, "AirDens", *in.AirDens);
  if (in.KinVisc) requirePositive(f, "KinVisc", *in.KinVisc);
  in.EDFile = f.getPath("EDFile");
  in.ServoFile = pathOfFirst(f, {"ServoFile", "SrvDFile"});
  in.AeroFile = pathOfFirst(f, {"AeroFile", "ADFile"});
  in.InflowFile = pathOfFirst(f, {"InflowFile"});
  in.SeaStFile = pathOfFirst(f, {"SeaStFile"});
  in.HydroFile = pathOfFirst(f, {"HydroFile"});
  in.MooringFile = pathOfFirst(f, {"MooringFile"});
  in.WtrDens = f.findDouble("WtrDens");
  in.WtrDpth = f.findDouble("WtrDpth");
  return in;
}

}  // namespace whirl::io

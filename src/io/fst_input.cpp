#include "src/io/fst_input.hpp"

#include "src/io/elastodyn_common.hpp"
#include "src/io/openfast_overrides.hpp"
#include "src/model/error.hpp"

namespace whirl::io {
namespace {

/// An integer switch, or a FAST 8.0x True/False flag (1/0); `fallback` when the key is absent.
int switch_or(const OpenFastFile& f, std::string_view key, int fallback) {
  const OpenFastEntry* e = f.find(key);
  if (!e) return fallback;
  if (e->tokens.size() == 1 && !parse_fortran_double(e->tokens.front())) return f.get_bool(key) ? 1 : 0;
  return f.get_int(key);
}

/// The path of the first of `keys` present in the file, or nullopt.
std::optional<std::filesystem::path> path_of_first(const OpenFastFile& f, std::initializer_list<const char*> keys) {
  for (const char* k : keys)
    if (f.has(k)) return f.get_path(k);
  return std::nullopt;
}

/// Duplicates only (the .fst has many keys across versions, none of which whirl reads by position):
/// OpenFAST v5 repeats the per-rotor lines for a second rotor.
const OpenFastLayout& layout() {
  static const OpenFastLayout l{".fst", {}, {"EDFile", "BDBldFile(k)", "ServoFile", "SrvDFile"}};
  return l;
}

/// A FAST v7 (or v6) primary file has the whole structural model inline and no EDFile; its keys
/// ADAMSPrep/AnalMode and the turbine's TwrFile left the .fst in FAST v8, which moved the structure into
/// ElastoDyn [JonkmanJonkman2016]. Say so instead of "EDFile: key not found".
void require_not_fast7(const OpenFastFile& f) {
  if (f.has("EDFile")) return;
  for (const char* key : {"ADAMSPrep", "AnalMode", "TwrFile"}) {
    if (!f.has(key)) continue;
    throw InputError(f.where(key, "this is a FAST v7 primary input file (the turbine is inline, there is no "
                                  "EDFile): whirl reads FAST v8 and OpenFAST decks, whose .fst names an "
                                  "ElastoDyn file; convert it with ConvertFAST7to8.m (OpenFAST "
                                  "matlab-toolbox, ConvertFASTversions) or use the FAST v8 deck of the same turbine"));
  }
}

}  // namespace

FstInput read_fst(const std::filesystem::path& file, OverrideSet* overrides) {
  FstInput in;
  in.source = OpenFastFile::read(file);
  in.source.check_layout(layout());
  if (overrides) overrides->apply_to(in.source);
  const OpenFastFile& f = in.source;

  in.Gravity = f.find_double("Gravity");
  if (in.Gravity) require_nonnegative(f, "Gravity", *in.Gravity);
  in.CompElast = switch_or(f, "CompElast", 1);
  in.CompInflow = switch_or(f, "CompInflow", 0);
  in.CompAero = switch_or(f, "CompAero", 0);
  in.CompServo = switch_or(f, "CompServo", 0);
  in.CompHydro = switch_or(f, "CompHydro", 0);
  in.CompSub = switch_or(f, "CompSub", 0);
  in.CompMooring = switch_or(f, "CompMooring", 0);
  in.MHK = f.find_int("MHK");
  in.NRotors = f.find_int("NRotors");
  in.AirDens = f.find_double("AirDens");
  in.KinVisc = f.find_double("KinVisc");
  in.SpdSound = f.find_double("SpdSound");
  in.Patm = f.find_double("Patm");
  in.Pvap = f.find_double("Pvap");
  if (in.AirDens) require_positive(f, "AirDens", *in.AirDens);
  if (in.KinVisc) require_positive(f, "KinVisc", *in.KinVisc);
  require_not_fast7(f);
  in.EDFile = f.get_path("EDFile");
  in.ServoFile = path_of_first(f, {"ServoFile", "SrvDFile"});
  in.AeroFile = path_of_first(f, {"AeroFile", "ADFile"});
  in.InflowFile = path_of_first(f, {"InflowFile"});
  in.HydroFile = path_of_first(f, {"HydroFile"});
  in.MooringFile = path_of_first(f, {"MooringFile"});
  in.WtrDens = f.find_double("WtrDens");
  in.WtrDpth = f.find_double("WtrDpth");
  return in;
}

}  // namespace whirl::io

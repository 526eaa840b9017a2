#include "src/io/aerodyn_input.hpp"

#include <algorithm>
#include <cmath>

#include "src/io/elastodyn_common.hpp"
#include "src/io/fst_input.hpp"
#include "src/io/openfast_lines.hpp"
#include "src/io/openfast_overrides.hpp"
#include "src/model/error.hpp"

namespace whirl::io {
namespace {

/// An integer switch, or a True/False flag read as 1/0 (TwrShadow of AeroDyn v15.0x); `fallback` when absent.
int switch_or_flag(const OpenFastFile& f, std::string_view key, int fallback) {
  const OpenFastEntry* e = f.find(key);
  if (!e) return fallback;
  if (e->tokens.size() == 1 && !parse_fortran_double(e->tokens.front())) return f.get_bool(key) ? 1 : 0;
  return f.get_int(key);
}

/// The key present in the file among a new spelling and its legacy one; InputError when both or neither are.
std::string one_of(const OpenFastFile& f, const char* current, const char* legacy) {
  const bool has_current = f.has(current);
  const bool has_legacy = f.has(legacy);
  if (has_current && has_legacy)
    throw InputError(f.where(current, std::string("cannot have both ") + current + " and its legacy spelling " +
                                          legacy + " (line " + std::to_string(f.find(legacy)->line) + ")"));
  if (!has_current && !has_legacy)
    throw InputError(f.where(current, std::string("key not found in this file (nor its legacy spelling ") + legacy + ")"));
  return has_current ? current : legacy;
}

/// A file name as AeroDyn resolves it: relative to the folder of `from`, backslashes read as '/'.
std::filesystem::path resolve(const std::filesystem::path& from, std::string name) {
  std::replace(name.begin(), name.end(), '\\', '/');
  const std::filesystem::path p(name);
  return (p.is_absolute() ? p : from.parent_path() / p).lexically_normal();
}

double env_value(const OpenFastFile& f, const char* key, double fallback, bool* defaulted = nullptr) {
  const std::optional<double> v = f.has(key) ? f.get_double_or_default(key) : std::nullopt;
  if (defaulted) *defaulted = !v;
  return v.value_or(fallback);
}

void read_wake(const OpenFastFile& f, AeroDynInput& a) {
  a.wake_key = one_of(f, "Wake_Mod", "WakeMod");
  a.layout = f.has("Wake_Mod") ? AeroDynLayout::V4 : AeroDynLayout::V15;
  a.Wake_Mod = f.get_int(a.wake_key);
  const std::optional<bool> frozen = f.find_bool("FrozenWake");
  if (a.layout == AeroDynLayout::V4) {
    a.DBEMT_Mod = f.find_int("DBEMT_Mod").value_or(0);
    a.dbemt_key = "DBEMT_Mod";
  } else if (a.Wake_Mod == 2) {  // legacy DBEMT: BEMT with the file's DBEMT_Mod (> 0)
    a.Wake_Mod = 1;
    a.DBEMT_Mod = std::max(1, f.find_int("DBEMT_Mod").value_or(1));
    a.dbemt_key = "WakeMod";
  } else {
    a.DBEMT_Mod = 0;  // DBEMT_Mod is only used with WakeMod = 2
  }
  if (frozen.value_or(false) && a.DBEMT_Mod <= 0) {
    a.DBEMT_Mod = -1;
    a.dbemt_key = "FrozenWake";
  }
  a.frozen_wake = a.DBEMT_Mod == -1;
}

void read_unsteady_aero(const OpenFastFile& f, AeroDynInput& a) {
  if (f.has("AFAeroMod")) {
    a.ua_key = "AFAeroMod";
    const int mod = f.get_int("AFAeroMod");
    if (mod != 1 && mod != 2)
      throw InputError(f.where("AFAeroMod", "must be 1 (steady) or 2 (unsteady), is " + std::to_string(mod)));
    const std::optional<int> ua = f.has("UA_Mod") ? f.find_int("UA_Mod") : f.find_int("UAMod");
    a.UA_Mod = mod == 1 ? 0 : std::max(1, ua.value_or(1));
    return;
  }
  a.ua_key = one_of(f, "UA_Mod", "UAMod");
  a.UA_Mod = f.get_int(a.ua_key);
}

void read_skew(const OpenFastFile& f, AeroDynInput& a) {
  a.skew_key = one_of(f, "Skew_Mod", "SkewMod");
  const int v = f.get_int(a.skew_key);
  if (a.skew_key == "Skew_Mod") {
    if (v < -1 || v > 1) throw InputError(f.where("Skew_Mod", "must be -1, 0 or 1, is " + std::to_string(v)));
    a.skew = v == -1 ? SkewModel::Orthogonal : v == 0 ? SkewModel::None : SkewModel::Active;
    a.SkewRedistr_Mod = f.find_int("SkewRedistr_Mod").value_or(1);
  } else {
    if (v < 0 || v > 3) throw InputError(f.where("SkewMod", "must be 0, 1, 2 or 3, is " + std::to_string(v)));
    const SkewModel legacy[] = {SkewModel::Orthogonal, SkewModel::None, SkewModel::Active, SkewModel::Coupled};
    a.skew = legacy[v];
    a.SkewRedistr_Mod = v == 2 ? 1 : 0;
  }
  a.SkewMomCorr = f.find_bool("SkewMomCorr").value_or(false);
  const char* factor = f.has("SkewRedistrFactor") ? "SkewRedistrFactor" : "SkewModFactor";
  if (f.has(factor))
    if (const std::optional<double> k = f.get_double_or_default(factor)) a.SkewModFactor = *k;
}

/// The entry on line `line`, or nullptr.
const OpenFastEntry* entry_at(const OpenFastFile& f, int line) {
  for (const OpenFastEntry& e : f.entries())
    if (e.line == line) return &e;
  return nullptr;
}

/// AFNames: the first name on the key's line, the others alone on the next content lines.
void read_airfoil_names(const OpenFastFile& f, const OpenFastLines& lines, AeroDynInput& a) {
  const int n = f.get_int("NumAFfiles");
  if (n < 1) throw InputError(f.where("NumAFfiles", "must be at least 1 (is " + std::to_string(n) + ")"));
  const OpenFastEntry* first = f.find("AFNames");
  if (!first) throw InputError(f.where("AFNames", "key not found in this file"));
  a.AFNames.push_back(resolve(f.path(), f.get_string("AFNames")));
  a.AFNames_lines.push_back(first->line);
  int at = first->line;
  for (int k = 2; k <= n; ++k) {
    const std::optional<int> next = lines.next_content_line(at);
    const std::vector<std::string> words = next ? split_words(lines.line(*next)) : std::vector<std::string>{};
    const OpenFastEntry* keyed = next ? entry_at(f, *next) : nullptr;  // e.g. "True  UseBlCm": the list ended
    if (!next || words.empty() || parse_fortran_double(words.front()) || words.front().rfind("==", 0) == 0 ||
        words.front().rfind("--", 0) == 0 || (keyed && to_lower(keyed->key).rfind("afnames", 0) != 0))
      throw InputError(f.where("NumAFfiles", "announces " + std::to_string(n) + " airfoil files, only " +
                                                 std::to_string(k - 1) + " names follow AFNames (line " +
                                                 std::to_string(first->line) + ")"));
    a.AFNames.push_back(resolve(f.path(), unquoted(words.front())));
    a.AFNames_lines.push_back(*next);
    at = *next;
  }
}

/// The tower table after NumTwrNds: a header row (a trailing '!' comment allowed), a unit row, NumTwrNds rows.
DistributedTable read_tower(const OpenFastFile& f, const OpenFastLines& lines, int count) {
  DistributedTable t;
  t.file = f.path().string();
  if (count < 0) throw InputError(f.where("NumTwrNds", "must not be negative (is " + std::to_string(count) + ")"));
  if (count == 0) return t;
  const int key_line = f.find("NumTwrNds")->line;
  const std::optional<int> header = lines.next_content_line(key_line);
  const std::optional<int> units = header ? lines.next_content_line(*header) : std::nullopt;
  if (!units) throw InputError(f.where("NumTwrNds", "no tower table follows (truncated file?)"));
  t.names = split_words(lines.line(*header));
  for (const std::string& u : split_words(lines.line(*units))) t.units.push_back(u);
  t.values.assign(t.names.size(), {});
  int at = *units;
  for (int r = 0; r < count; ++r) {
    const std::optional<int> next = lines.next_content_line(at);
    const std::optional<std::vector<double>> row = next ? parse_number_row(lines.line(*next)) : std::nullopt;
    if (!row)
      throw InputError(f.where("NumTwrNds", "table has " + std::to_string(r) + " rows, " + std::to_string(count) +
                                                " expected: " +
                                                (next ? "line " + std::to_string(*next) + " is not a row of numbers"
                                                      : std::string("the file ends")) +
                                                " (truncated table?)"));
    if (row->size() < t.names.size())
      throw InputError(where(t.file, *next, "", "row has " + std::to_string(row->size()) + " numbers, the tower table has " +
                                                    std::to_string(t.names.size()) + " columns"));
    for (std::size_t c = 0; c < t.names.size(); ++c) {
      const double v = (*row)[c];
      if (!std::isfinite(v))
        throw InputError(where(t.file, *next, t.names[c], std::isnan(v) ? "value is NaN" : "value is infinite"));
      t.values[c].push_back(v);
    }
    t.row_lines.push_back(*next);
    at = *next;
  }
  return t;
}

void read_columns(const OpenFastFile& f, AeroDynInput& a) {
  a.AFTabMod = f.find_int("AFTabMod").value_or(1);
  a.InCol.alpha = f.get_int("InCol_Alfa");
  a.InCol.cl = f.get_int("InCol_Cl");
  a.InCol.cd = f.get_int("InCol_Cd");
  a.InCol.cm = f.get_int("InCol_Cm");
  a.InCol_Cpmin = f.get_int("InCol_Cpmin");
  for (const char* k : {"InCol_Alfa", "InCol_Cl", "InCol_Cd"}) require_positive(f, k, f.get_int(k));
  for (const char* k : {"InCol_Cm", "InCol_Cpmin"}) require_nonnegative(f, k, f.get_int(k));
}

}  // namespace

AeroDynEnvironment aerodyn_environment(const FstInput& fst) {
  AeroDynEnvironment env;
  env.AirDens = fst.AirDens.value_or(env.AirDens);
  env.KinVisc = fst.KinVisc.value_or(env.KinVisc);
  env.SpdSound = fst.SpdSound.value_or(env.SpdSound);
  env.Patm = fst.Patm.value_or(env.Patm);
  env.Pvap = fst.Pvap.value_or(env.Pvap);
  return env;
}

AeroDynInput read_aerodyn(const std::filesystem::path& file, const AeroDynEnvironment& env, OverrideSet* overrides) {
  const OpenFastLines lines = OpenFastLines::read(file);
  AeroDynInput a;
  a.source = OpenFastFile::parse(lines.text(), file);
  if (overrides) overrides->apply_to(a.source);
  const OpenFastFile& f = a.source;

  read_wake(f, a);
  read_unsteady_aero(f, a);
  a.TwrPotent = f.get_int("TwrPotent");
  a.TwrShadow = switch_or_flag(f, "TwrShadow", 0);
  a.TwrAero = f.get_bool("TwrAero");
  a.Buoyancy = f.find_bool("Buoyancy").value_or(false);
  a.CavitCheck = f.find_bool("CavitCheck").value_or(false);
  a.CompAA = f.find_bool("CompAA").value_or(false);
  a.NacelleDrag = f.find_bool("NacelleDrag").value_or(false);
  a.SectAvg = f.find_bool("SectAvg").value_or(false);
  a.TFinAero = f.find_bool("TFinAero").value_or(false);
  a.BEM_Mod = f.find_int("BEM_Mod").value_or(1);

  a.AirDens = env_value(f, "AirDens", env.AirDens, &a.AirDens_default);
  a.KinVisc = env_value(f, "KinVisc", env.KinVisc, &a.KinVisc_default);
  a.SpdSound = env_value(f, "SpdSound", env.SpdSound);
  a.Patm = env_value(f, "Patm", env.Patm);
  a.Pvap = env_value(f, "Pvap", env.Pvap);
  if (!(a.AirDens > 0.0))
    throw InputError(f.where("AirDens", "must be positive (is " + number_text(a.AirDens) + ")"));
  if (!(a.KinVisc > 0.0))
    throw InputError(f.where("KinVisc", "must be positive (is " + number_text(a.KinVisc) + ")"));

  read_skew(f, a);
  a.TipLoss = f.get_bool("TipLoss");
  a.HubLoss = f.get_bool("HubLoss");
  a.TanInd = f.get_bool("TanInd");
  a.AIDrag = f.get_bool("AIDrag");
  a.TIDrag = f.get_bool("TIDrag");
  a.IndToler = f.get_double_or_default("IndToler");
  if (a.IndToler) require_positive(f, "IndToler", *a.IndToler);
  a.MaxIter = f.get_int("MaxIter");
  if (a.MaxIter < 1) throw InputError(f.where("MaxIter", "must be at least 1 (is " + std::to_string(a.MaxIter) + ")"));

  read_columns(f, a);
  read_airfoil_names(f, lines, a);
  a.UseBlCm = f.get_bool("UseBlCm");
  for (int k = 1; k <= 3 && f.has(indexed_key("ADBlFile", k)); ++k)
    a.ADBlFile.push_back(f.get_path(indexed_key("ADBlFile", k)));
  if (a.ADBlFile.empty()) throw InputError(f.where("ADBlFile(1)", "key not found in this file"));
  a.NumTwrNds = f.get_int("NumTwrNds");
  a.tower = read_tower(f, lines, a.NumTwrNds);
  return a;
}

}  // namespace whirl::io

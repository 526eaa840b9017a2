#include "src/io/openfast/aerodyn/aerodyn_input.hpp"

#include <algorithm>
#include <cmath>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_lines.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

/// An integer switch, or a True/False flag read as 1/0 (TwrShadow of AeroDyn v15.0x); `fallback` when absent.
int switchOrFlag(const OpenFastFile& f, std::string_view key, int fallback) {
  const OpenFastEntry* e = f.find(key);
  if (!e) return fallback;
  if (e->tokens.size() == 1 && !parseFortranDouble(e->tokens.front())) return f.getBool(key) ? 1 : 0;
  return f.getInt(key);
}

/// The key present in the file among a new spelling and its legacy one; InputError when both or neither are.
std::string oneOf(const OpenFastFile& f, const char* current, const char* legacy) {
  const bool has_current = f.has(current);
  const bool has_legacy = f.has(legacy);
  if (has_current && has_legacy)
    throw InputError(f.where(current, std::string("cannot have both ") + current + " and its legacy spelling " +
                                          legacy + " (line " + std::to_string(f.find(legacy)->line) + ")"));
  if (!has_current && !has_legacy)
    throw InputError(
        f.where(current, std::string("key not found in this file (nor its legacy spelling ") + legacy + ")"));
  return has_current ? current : legacy;
}

double envValue(const OpenFastFile& f, const char* key, double fallback, bool* defaulted = nullptr) {
  const std::optional<double> v = f.has(key) ? f.getDoubleOrDefault(key) : std::nullopt;
  if (defaulted) *defaulted = !v;
  return v.value_or(fallback);
}

void readWake(const OpenFastFile& f, AeroDynInput& a) {
  a.wake_key = oneOf(f, "Wake_Mod", "WakeMod");
  a.layout = f.has("Wake_Mod") ? AeroDynLayout::V4 : AeroDynLayout::V15;
  a.Wake_Mod = f.getInt(a.wake_key);
  const std::optional<bool> frozen = f.findBool("FrozenWake");
  if (a.layout == AeroDynLayout::V4) {
    a.DBEMT_Mod = f.findInt("DBEMT_Mod").value_or(0);
    a.dbemt_key = "DBEMT_Mod";
  } else if (a.Wake_Mod == 2) {  // legacy DBEMT: BEMT with the file's DBEMT_Mod (> 0)
    a.Wake_Mod = 1;
    a.DBEMT_Mod = std::max(1, f.findInt("DBEMT_Mod").value_or(1));
    a.dbemt_key = "WakeMod";
  } else {
    a.DBEMT_Mod = 0;  // DBEMT_Mod is only used with WakeMod = 2
  }
  if (frozen.value_or(false) && a.DBEMT_Mod <= 0) {
    a.DBEMT_Mod = -1;
    a.dbemt_key = "FrozenWake";
  }
  a.frozen_wake = a.DBEMT_Mod == -1;
  if (f.has("tau1_const")) a.tau1_const = f.getDoubleOrDefault("tau1_const");
  if ((a.DBEMT_Mod == 1 || a.DBEMT_Mod == 3) && a.Wake_Mod == 1) {
    if (!a.tau1_const)
      throw InputError(
          f.where(f.has("tau1_const") ? "tau1_const" : a.dbemt_key,
                  "DBEMT_Mod " + std::to_string(a.DBEMT_Mod) + " needs tau1_const (a time constant in s)"));
    if (!(*a.tau1_const > 0.0))
      throw InputError(f.where("tau1_const", "must be > 0 with DBEMT_Mod " + std::to_string(a.DBEMT_Mod) + " (is " +
                                                 numberText(*a.tau1_const) + ")"));
  }
}

/// UAStartRad, UAEndRad (fractions of the largest element radius, AeroDyn_IO.f90: 0 and 1 when missing) and
/// AoA34.
void readUaSpan(const OpenFastFile& f, AeroDynInput& a) {
  auto fraction = [&](const char* key, double fallback) {
    const std::optional<double> v = f.has(key) ? f.getDoubleOrDefault(key) : std::nullopt;
    if (v && (*v < 0.0 || *v > 1.0))
      throw InputError(f.where(key, "must be a fraction of the rotor radius in [0, 1] (is " + numberText(*v) + ")"));
    return v.value_or(fallback);
  };
  a.UAStartRad = fraction("UAStartRad", 0.0);
  a.UAEndRad = fraction("UAEndRad", 1.0);
  if (a.UAStartRad > a.UAEndRad)
    throw InputError(f.where("UAEndRad", "must not be below UAStartRad (" + numberText(a.UAEndRad) + " < " +
                                             numberText(a.UAStartRad) + "): no element would have UA"));
  a.AoA34 = f.findBool("AoA34").value_or(true);
}

void readUnsteadyAero(const OpenFastFile& f, AeroDynInput& a) {
  if (f.has("AFAeroMod")) {
    a.ua_key = "AFAeroMod";
    const int mod = f.getInt("AFAeroMod");
    if (mod != 1 && mod != 2)
      throw InputError(f.where("AFAeroMod", "must be 1 (steady) or 2 (unsteady), is " + std::to_string(mod)));
    const std::optional<int> ua = f.has("UA_Mod") ? f.findInt("UA_Mod") : f.findInt("UAMod");
    a.UA_Mod = mod == 1 ? 0 : std::max(1, ua.value_or(1));
    return;
  }
  a.ua_key = oneOf(f, "UA_Mod", "UAMod");
  a.UA_Mod = f.getInt(a.ua_key);
}

void readSkew(const OpenFastFile& f, AeroDynInput& a) {
  a.skew_key = oneOf(f, "Skew_Mod", "SkewMod");
  const int v = f.getInt(a.skew_key);
  if (a.skew_key == "Skew_Mod") {
    if (v < -1 || v > 1) throw InputError(f.where("Skew_Mod", "must be -1, 0 or 1, is " + std::to_string(v)));
    a.skew = v == -1 ? SkewModel::Orthogonal : v == 0 ? SkewModel::None : SkewModel::Active;
    // `default` is 1 (AeroDyn_IO.f90, ParsePrimaryFileInfo: ParseVarWDefault "SkewRedistr_Mod", 1).
    a.SkewRedistr_Mod = f.findIntOr("SkewRedistr_Mod", 1).value_or(1);
  } else {
    if (v < 0 || v > 3) throw InputError(f.where("SkewMod", "must be 0, 1, 2 or 3, is " + std::to_string(v)));
    const SkewModel legacy[] = {SkewModel::Orthogonal, SkewModel::None, SkewModel::Active, SkewModel::Coupled};
    a.skew = legacy[v];
    a.SkewRedistr_Mod = v == 2 ? 1 : 0;
  }
  a.SkewMomCorr = f.findBool("SkewMomCorr").value_or(false);
  const char* factor = f.has("SkewRedistrFactor") ? "SkewRedistrFactor" : "SkewModFactor";
  if (f.has(factor))
    if (const std::optional<double> k = f.getDoubleOrDefault(factor)) a.SkewModFactor = *k;
}

/// AFNames: the first name on the key's line, the others alone on the next content lines.
void readAirfoilNames(const OpenFastFile& f, const OpenFastLines& lines, AeroDynInput& a) {
  const int n = f.getInt("NumAFfiles");
  if (n < 1) throw InputError(f.where("NumAFfiles", "must be at least 1 (is " + std::to_string(n) + ")"));
  AirfoilNameList names = readAirfoilNameList(f, lines, "NumAFfiles", "AFNames", n);
  a.AFNames = std::move(names.paths);
  a.AFNames_lines = std::move(names.lines);
}

/// The tower table after NumTwrNds: a header row (a trailing '!' comment allowed), a unit row, NumTwrNds rows.
DistributedTable readTower(const OpenFastFile& f, const OpenFastLines& lines, int count) {
  DistributedTable t;
  t.file = f.path().string();
  if (count < 0) throw InputError(f.where("NumTwrNds", "must not be negative (is " + std::to_string(count) + ")"));
  if (count == 0) return t;
  const int key_line = f.find("NumTwrNds")->line;
  const std::optional<int> header = lines.nextContentLine(key_line);
  const std::optional<int> units = header ? lines.nextContentLine(*header) : std::nullopt;
  if (!units) throw InputError(f.where("NumTwrNds", "no tower table follows (truncated file?)"));
  t.names = splitWords(lines.line(*header));
  for (const std::string& u : splitWords(lines.line(*units))) t.units.push_back(u);
  t.values.assign(t.names.size(), {});
  int at = *units;
  for (int r = 0; r < count; ++r) {
    const std::optional<int> next = lines.nextContentLine(at);
    const std::optional<std::vector<double>> row = next ? parseNumberRow(lines.line(*next)) : std::nullopt;
    if (!row)
      throw InputError(f.where("NumTwrNds", "table has " + std::to_string(r) + " rows, " + std::to_string(count) +
                                                " expected: " +
                                                (next ? "line " + std::to_string(*next) + " is not a row of numbers"
                                                      : std::string("the file ends")) +
                                                " (truncated table?)"));
    if (row->size() < t.names.size())
      throw InputError(where(t.file, *next, "",
                             "row has " + std::to_string(row->size()) + " numbers, the tower table has " +
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

void readColumns(const OpenFastFile& f, AeroDynInput& a) {
  a.AFTabMod = f.findInt("AFTabMod").value_or(1);
  a.InCol.alpha = f.getInt("InCol_Alfa");
  a.InCol.cl = f.getInt("InCol_Cl");
  a.InCol.cd = f.getInt("InCol_Cd");
  a.InCol.cm = f.getInt("InCol_Cm");
  a.InCol_Cpmin = f.getInt("InCol_Cpmin");
  for (const char* k : {"InCol_Alfa", "InCol_Cl", "InCol_Cd"}) requirePositive(f, k, f.getInt(k));
  for (const char* k : {"InCol_Cm", "InCol_Cpmin"}) requireNonnegative(f, k, f.getInt(k));
}

}  // namespace

AeroDynEnvironment aerodynEnvironment(const FstInput& fst) {
  AeroDynEnvironment env;
  env.AirDens = fst.AirDens.value_or(env.AirDens);
  env.KinVisc = fst.KinVisc.value_or(env.KinVisc);
  env.SpdSound = fst.SpdSound.value_or(env.SpdSound);
  env.Patm = fst.Patm.value_or(env.Patm);
  env.Pvap = fst.Pvap.value_or(env.Pvap);
  return env;
}

AeroDynInput readAeroDyn(const std::filesystem::path& file, const AeroDynEnvironment& env, OverrideSet* overrides) {
  const OpenFastLines lines = OpenFastLines::read(file);
  AeroDynInput a;
  a.source = OpenFastFile::parse(lines.text(), file);
  a.source.checkLayout(aeroDynLayout());
  if (overrides) overrides->applyTo(a.source);
  const OpenFastFile& f = a.source;

  readWake(f, a);
  readUnsteadyAero(f, a);
  readUaSpan(f, a);
  a.TwrPotent = f.getInt("TwrPotent");
  a.TwrShadow = switchOrFlag(f, "TwrShadow", 0);
  a.TwrAero = f.getBool("TwrAero");
  a.Buoyancy = f.findBool("Buoyancy").value_or(false);
  a.CavitCheck = f.findBool("CavitCheck").value_or(false);
  a.CompAA = f.findBool("CompAA").value_or(false);
  a.NacelleDrag = f.findBool("NacelleDrag").value_or(false);
  a.SectAvg = f.findBool("SectAvg").value_or(false);
  a.TFinAero = f.findBool("TFinAero").value_or(false);
  a.BEM_Mod = f.findInt("BEM_Mod").value_or(1);

  a.AirDens = envValue(f, "AirDens", env.AirDens, &a.AirDens_default);
  a.KinVisc = envValue(f, "KinVisc", env.KinVisc, &a.KinVisc_default);
  a.SpdSound = envValue(f, "SpdSound", env.SpdSound);
  a.Patm = envValue(f, "Patm", env.Patm);
  a.Pvap = envValue(f, "Pvap", env.Pvap);
  if (!(a.AirDens > 0.0)) throw InputError(f.where("AirDens", "must be positive (is " + numberText(a.AirDens) + ")"));
  if (!(a.KinVisc > 0.0)) throw InputError(f.where("KinVisc", "must be positive (is " + numberText(a.KinVisc) + ")"));

  readSkew(f, a);
  a.TipLoss = f.getBool("TipLoss");
  a.HubLoss = f.getBool("HubLoss");
  a.TanInd = f.getBool("TanInd");
  a.AIDrag = f.getBool("AIDrag");
  a.TIDrag = f.getBool("TIDrag");
  a.IndToler = f.getDoubleOrDefault("IndToler");
  if (a.IndToler) requirePositive(f, "IndToler", *a.IndToler);
  a.MaxIter = f.getInt("MaxIter");
  if (a.MaxIter < 1) throw InputError(f.where("MaxIter", "must be at least 1 (is " + std::to_string(a.MaxIter) + ")"));

  readColumns(f, a);
  readAirfoilNames(f, lines, a);
  a.UseBlCm = f.getBool("UseBlCm");
  for (int k = 1; k <= 3 && f.has(indexedKey("ADBlFile", k)); ++k)
    a.ADBlFile.push_back(f.getPath(indexedKey("ADBlFile", k)));
  if (a.ADBlFile.empty()) throw InputError(f.where("ADBlFile(1)", "key not found in this file"));
  a.NumTwrNds = f.getInt("NumTwrNds");
  a.tower = readTower(f, lines, a.NumTwrNds);
  return a;
}

}  // namespace whirl::io

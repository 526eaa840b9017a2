#include "src/io/openfast/aerodyn/aerodyn14_input.hpp"

#include <algorithm>
#include <cmath>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_lines.hpp"
#include "src/io/openfast/openfast_overrides.hpp"

namespace whirl::io {
namespace {

const OpenFastLayout& layout() {
  static const OpenFastLayout l{"AeroDyn v14",
                                {"SysUnits", "StallMod", "UseCm", "InfModel", "IndModel", "AToler", "TLModel",
                                 "HLModel", "TwrShad", "ShadHWid", "T_Shad_Refpt", "AirDens", "KinVisc", "DTAero",
                                 "NumFoil", "FoilNm", "BldNodes"},
                                {}};
  return l;
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

/// A switch value, upper case, among `allowed`.
std::string choice(const OpenFastFile& f, const char* key, std::initializer_list<const char*> allowed) {
  const std::string v = upper(f.getString(key));
  std::string list;
  for (const char* a : allowed) {
    if (v == a) return v;
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  throw InputError(f.where(key, "must be one of " + list + " (is " + f.find(key)->raw + ")"));
}

/// The line that holds `key` as its second word (the keys before the element table), or 0.
int keyLine(const OpenFastLines& lines, std::string_view key) {
  for (int n = 1; n <= lines.count(); ++n) {
    const std::vector<std::string> w = splitWords(lines.line(n));
    if (w.size() >= 2 && toLower(w[1]) == toLower(key)) return n;
  }
  return 0;
}

/// The element table after BldNodes: a header row of names, then `count` rows "numbers… PRINT|NOPRINT".
void readElements(const OpenFastFile& f, const OpenFastLines& lines, int count, AeroDyn14Input& a) {
  const std::string file = f.path().string();
  const int key_line = f.find("BldNodes")->line;
  const std::optional<int> header = lines.nextContentLine(key_line);
  const std::vector<std::string> names = header ? splitWords(lines.line(*header)) : std::vector<std::string>{};
  if (names.empty() || toLower(names.front()) != "rnodes")
    throw InputError(f.where("BldNodes",
                             "the element table (header RNodes AeroTwst DRNodes Chord NFoil PrnElm) "
                             "does not follow" +
                                 std::string(header ? "" : ": the file ends")));
  int at = *header;
  for (int r = 0; r < count; ++r) {
    const std::optional<int> next = lines.nextContentLine(at);
    std::vector<std::string> words = next ? splitWords(lines.line(*next)) : std::vector<std::string>{};
    if (!words.empty() && (upper(words.back()) == "PRINT" || upper(words.back()) == "NOPRINT")) words.pop_back();
    std::vector<double> row;
    for (const std::string& w : words)
      if (const std::optional<double> v = parseFortranDouble(w)) row.push_back(*v);
    if (!next || row.size() != words.size() || row.size() < 5)
      throw InputError(f.where("BldNodes", "element table has " + std::to_string(r) + " rows, " +
                                               std::to_string(count) + " expected: " +
                                               (next ? "line " + std::to_string(*next) +
                                                           " is not a row of 5 numbers (RNodes AeroTwst DRNodes "
                                                           "Chord NFoil) and PRINT or NOPRINT"
                                                     : std::string("the file ends")) +
                                               " (truncated table?)"));
    const char* cols[] = {"RNodes", "AeroTwst", "DRNodes", "Chord", "NFoil"};
    for (int c = 0; c < 5; ++c)
      if (!std::isfinite(row[c]))
        throw InputError(where(file, *next, cols[c], std::isnan(row[c]) ? "value is NaN" : "value is infinite"));
    auto bad = [&](const char* col, const std::string& reason) { return InputError(where(file, *next, col, reason)); };
    if (!a.RNodes.empty() && !(row[0] > a.RNodes.back()))
      throw bad("RNodes", "must increase from element to element (" + numberText(row[0]) + " after " +
                              numberText(a.RNodes.back()) + ")");
    if (!(row[0] > 0)) throw bad("RNodes", "must be positive (is " + numberText(row[0]) + ")");
    if (!(row[2] > 0)) throw bad("DRNodes", "must be positive (is " + numberText(row[2]) + ")");
    if (!(row[3] > 0)) throw bad("Chord", "must be positive (is " + numberText(row[3]) + ")");
    const int foils = static_cast<int>(a.FoilNm.size());
    if (row[4] != std::floor(row[4]) || row[4] < 1 || row[4] > foils)
      throw bad("NFoil", "must be an airfoil of FoilNm, a whole number from 1 to NumFoil = " + std::to_string(foils) +
                             " (is " + numberText(row[4]) + ")");
    a.RNodes.push_back(row[0]);
    a.AeroTwst.push_back(row[1]);
    a.DRNodes.push_back(row[2]);
    a.Chord.push_back(row[3]);
    a.NFoil.push_back(static_cast<int>(row[4]));
    a.row_lines.push_back(*next);
    at = *next;
  }
}

}  // namespace

AeroDyn14Input readAeroDyn14(const std::filesystem::path& file, OverrideSet* overrides) {
  const OpenFastLines lines = OpenFastLines::read(file);
  // The keys end at BldNodes; the element table after it has no unit row and ends its rows with a word,
  // which the generic tokenizer would take for keys.
  const int last = keyLine(lines, "BldNodes");
  if (last == 0)
    throw InputError(
        where(file.string(), 0, "BldNodes",
              "key not found in this file (an AeroDyn v14 file ends with BldNodes and the element table)"));
  std::string head;
  for (int n = 1; n <= last; ++n) head += lines.line(n) + "\n";
  AeroDyn14Input a;
  a.source = OpenFastFile::parse(head, file);
  a.source.checkLayout(layout());
  if (overrides) overrides->applyTo(a.source);
  const OpenFastFile& f = a.source;

  if (f.has("SysUnits")) choice(f, "SysUnits", {"SI"});
  a.StallMod = choice(f, "StallMod", {"BEDDOES", "STEADY"});
  a.UseCm = choice(f, "UseCm", {"USE_CM", "NO_CM"}) == "USE_CM";
  a.InfModel = choice(f, "InfModel", {"DYNIN", "EQUIL", "EQUILDA", "EQUILDT", "EQUILDB"});
  a.IndModel = choice(f, "IndModel", {"NONE", "WAKE", "SWIRL"});
  a.AToler = f.getDouble("AToler");
  requirePositive(f, "AToler", a.AToler);
  a.TLModel = choice(f, "TLModel", {"PRANDTL", "GTECH", "NONE"});
  a.HLModel = choice(f, "HLModel", {"PRANDTL", "NONE"});
  a.TwrShad = f.getDouble("TwrShad");
  f.getDouble("ShadHWid");
  f.getDouble("T_Shad_Refpt");
  a.AirDens = f.getDouble("AirDens");
  requirePositive(f, "AirDens", a.AirDens);
  a.KinVisc = f.getDouble("KinVisc");
  requirePositive(f, "KinVisc", a.KinVisc);
  f.getDoubleOrDefault("DTAero");  // the time step ("default": the glue code's), unused by a linear model

  const int foils = f.getInt("NumFoil");
  if (foils < 1) throw InputError(f.where("NumFoil", "must be at least 1 (is " + std::to_string(foils) + ")"));
  AirfoilNameList names = readAirfoilNameList(f, lines, "NumFoil", "FoilNm", foils);
  a.FoilNm = std::move(names.paths);
  a.FoilNm_lines = std::move(names.lines);

  const int nodes = f.getInt("BldNodes");
  if (nodes < 1) throw InputError(f.where("BldNodes", "must be at least 1 (is " + std::to_string(nodes) + ")"));
  if (nodes > lines.count())
    throw InputError(f.where("BldNodes", std::to_string(nodes) + " elements announced, the file has " +
                                             std::to_string(lines.count()) + " lines (truncated table?)"));
  readElements(f, lines, nodes, a);
  if (const std::optional<int> next = lines.nextContentLine(a.row_lines.back())) {
    const std::vector<std::string> words = splitWords(lines.line(*next));
    a.MultiTab = words.empty() ? "" : upper(unquoted(words.front()));
    a.MultiTab_line = *next;
  }
  return a;
}

}  // namespace whirl::io

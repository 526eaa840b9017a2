#include "src/io/openfast/aerodyn/airfoil_input.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_input.hpp"
#include "src/io/openfast/openfast_layouts.hpp"
#include "src/io/openfast/openfast_lines.hpp"

namespace whirl::io {
namespace {

/// The file's text for OpenFastFile::parse: comment lines and lines outside [from, to] blanked (line
/// numbers unchanged). With `title`, line 1 becomes a placeholder title so that the tokenizer does not
/// take the first value line for the file's title.
std::string keepLines(const OpenFastLines& lines, int from, int to, bool title) {
  std::string out;
  for (int n = 1; n <= lines.count(); ++n) {
    const std::string& l = lines.line(n);
    if (n == 1 && title && (isCommentLine(l) || isBlankLine(l))) out += "AirfoilInfo";
    else if (n >= from && n <= to && !isCommentLine(l)) out += l;
    out += '\n';
  }
  return out;
}

/// The keys of one table (Re … NumAlf), none repeated within it (AirfoilInfo.f90, ParseAFFile).
const OpenFastLayout& airfoilTableLayout() {
  static const OpenFastLayout l{"AeroDyn airfoil", airfoilLayout().repeatable, {}};
  return l;
}

/// Entry `key` (case-insensitive) after line `after`, first in file order; nullptr when none.
const OpenFastEntry* entryAfter(const OpenFastFile& f, std::string_view key, int after) {
  const std::string k = toLower(key);
  for (const OpenFastEntry& e : f.entries())
    if (e.line > after && toLower(e.key) == k) return &e;
  return nullptr;
}

/// The UA constants the continuous models divide by or take as angles: time constants positive, the
/// zero-lift angle within ±180° (AeroDyn's UA_ValidateAFI; a zero time constant would divide by zero
/// in UA_CalcContStateDeriv). The first violation, "file:line: key: reason", or empty. Not an error here:
/// AeroDyn validates only the airfoils UA runs on (a cylinder's table may hold zeros: certtest Test10).
std::string uaProblem(const OpenFastFile& t, const AirfoilUAData& ua) {
  const std::pair<const char*, const std::optional<double>*> positive[] = {{"T_f0", &ua.T_f0},
                                                                           {"T_V0", &ua.T_V0},
                                                                           {"T_p", &ua.T_p},
                                                                           {"T_VL", &ua.T_VL}};
  for (const auto& [key, v] : positive)
    if (*v && !(**v > 0.0)) return t.where(key, "must be > 0 (is " + numberText(**v) + ")");
  if (ua.alpha0 && std::abs(*ua.alpha0) > 180.0)
    return t.where("alpha0", "must be within -180 to 180 deg (is " + numberText(*ua.alpha0) + ")");
  return "";
}

void readUa(const OpenFastFile& t, AirfoilUAData& ua) {
  struct Field {
    const char* key;
    std::optional<double> AirfoilUAData::*member;
  };
  static const Field fields[] = {
      {"alpha0", &AirfoilUAData::alpha0},
      {"alpha1", &AirfoilUAData::alpha1},
      {"alpha2", &AirfoilUAData::alpha2},
      {"alphaUpper", &AirfoilUAData::alphaUpper},
      {"alphaLower", &AirfoilUAData::alphaLower},
      {"eta_e", &AirfoilUAData::eta_e},
      {"C_nalpha", &AirfoilUAData::C_nalpha},
      {"C_lalpha", &AirfoilUAData::C_lalpha},
      {"T_f0", &AirfoilUAData::T_f0},
      {"T_V0", &AirfoilUAData::T_V0},
      {"T_p", &AirfoilUAData::T_p},
      {"T_VL", &AirfoilUAData::T_VL},
      {"b1", &AirfoilUAData::b1},
      {"b2", &AirfoilUAData::b2},
      {"b5", &AirfoilUAData::b5},
      {"A1", &AirfoilUAData::A1},
      {"A2", &AirfoilUAData::A2},
      {"A5", &AirfoilUAData::A5},
      {"S1", &AirfoilUAData::S1},
      {"S2", &AirfoilUAData::S2},
      {"S3", &AirfoilUAData::S3},
      {"S4", &AirfoilUAData::S4},
      {"Cn1", &AirfoilUAData::Cn1},
      {"Cn2", &AirfoilUAData::Cn2},
      {"St_sh", &AirfoilUAData::St_sh},
      {"Cd0", &AirfoilUAData::Cd0},
      {"Cm0", &AirfoilUAData::Cm0},
      {"k0", &AirfoilUAData::k0},
      {"k1", &AirfoilUAData::k1},
      {"k2", &AirfoilUAData::k2},
      {"k3", &AirfoilUAData::k3},
      {"k1_hat", &AirfoilUAData::k1_hat},
      {"x_cp_bar", &AirfoilUAData::x_cp_bar},
      {"UACutout", &AirfoilUAData::UACutout},
      {"UACutout_delta", &AirfoilUAData::UACutout_delta},
      {"filtCutOff", &AirfoilUAData::filtCutOff},
  };
  for (const Field& fd : fields)
    if (t.has(fd.key)) ua.*fd.member = t.getDoubleOrDefault(fd.key);
  ua.invalid = uaProblem(t, ua);
}

/// Reads the NumAlf rows after line `num_alf_line` into `tab`.
void readRows(const OpenFastLines& lines, const OpenFastFile& t, int num_alf, int num_alf_line,
              const AirfoilColumns& col, AirfoilTable& tab) {
  const std::string file = lines.path().string();
  const int needed = std::max({col.alpha, col.cl, col.cd, col.cm});
  int at = num_alf_line;
  for (int r = 0; r < num_alf; ++r) {
    const std::optional<int> next = lines.nextContentLine(at);
    const std::string got = "table has " + std::to_string(r) + " rows, " + std::to_string(num_alf) + " expected: ";
    if (!next)
      throw InputError(
          t.where("NumAlf", got + "the file ends at line " + std::to_string(lines.count()) + " (truncated table?)"));
    const std::optional<std::vector<double>> row = parseNumberRow(lines.line(*next));
    if (!row)
      throw InputError(
          t.where("NumAlf", got + "line " + std::to_string(*next) + " is not a row of numbers (truncated table?)"));
    if (static_cast<int>(row->size()) < needed)
      throw InputError(whirl::where(file, *next, "",
                                    "row has " + std::to_string(row->size()) +
                                        " numbers, the columns asked for "
                                        "(InCol_Alfa/Cl/Cd/Cm = " +
                                        std::to_string(col.alpha) + "/" + std::to_string(col.cl) + "/" +
                                        std::to_string(col.cd) + "/" + std::to_string(col.cm) + ") need " +
                                        std::to_string(needed)));
    struct Pick {
      int column;
      const char* name;
      std::vector<double>* into;
    };
    const Pick picks[] = {{col.alpha, "Alpha", &tab.alpha_deg},
                          {col.cl, "Cl", &tab.cl},
                          {col.cd, "Cd", &tab.cd},
                          {col.cm, "Cm", &tab.cm}};
    for (const Pick& p : picks) {
      if (p.column <= 0) continue;
      const double v = (*row)[static_cast<std::size_t>(p.column - 1)];
      if (!std::isfinite(v))
        throw InputError(whirl::where(file, *next, p.name, std::isnan(v) ? "value is NaN" : "value is infinite"));
      p.into->push_back(v);
    }
    const std::size_t n = tab.alpha_deg.size();
    if (n >= 2 && !(tab.alpha_deg[n - 1] > tab.alpha_deg[n - 2]))
      throw InputError(whirl::where(file, *next, "Alpha",
                                    "must increase from row to row (" + numberText(tab.alpha_deg[n - 1]) + " after " +
                                        numberText(tab.alpha_deg[n - 2]) + ")"));
    tab.row_lines.push_back(*next);
    at = *next;
  }
  tab.first_row_line = tab.row_lines.empty() ? 0 : tab.row_lines.front();
}

AirfoilTable readTable(const OpenFastLines& lines, int re_line, int num_alf_line, const AirfoilColumns& col) {
  const OpenFastFile t = OpenFastFile::parse(keepLines(lines, re_line, num_alf_line, false), lines.path());
  t.checkLayout(airfoilTableLayout());
  AirfoilTable tab;
  tab.re_line = re_line;
  tab.num_alf_line = num_alf_line;
  tab.re = t.getDouble("Re");
  requirePositive(t, "Re", tab.re);
  tab.user_prop = t.has("UserProp") || !t.has("Ctrl") ? t.getDouble("UserProp") : t.getDouble("Ctrl");
  tab.ua.included = t.findBool("InclUAdata").value_or(false);
  if (tab.ua.included) readUa(t, tab.ua);
  const int num_alf = t.getInt("NumAlf");
  if (num_alf < 1) throw InputError(t.where("NumAlf", "must be at least 1 (is " + std::to_string(num_alf) + ")"));
  readRows(lines, t, num_alf, num_alf_line, col, tab);
  return tab;
}

void checkColumns(const std::filesystem::path& file, const AirfoilColumns& c) {
  if (c.alpha < 1 || c.cl < 1 || c.cd < 1 || c.cm < 0)
    throw InputError(whirl::where(file.string(), 0, "InCol_*",
                                  "airfoil table columns must be >= 1 (InCol_Cm >= 0), are " + std::to_string(c.alpha) +
                                      "/" + std::to_string(c.cl) + "/" + std::to_string(c.cd) + "/" +
                                      std::to_string(c.cm)));
}

}  // namespace

AirfoilInput readAirfoil(const std::filesystem::path& file, const AirfoilColumns& columns) {
  checkColumns(file, columns);
  const OpenFastLines lines = OpenFastLines::read(file);
  if (lines.count() > 0 && !isCommentLine(lines.line(1)) && !isBlankLine(lines.line(1)))
    throw InputError(
        whirl::where(file.string(), 1, "", "the first line of an airfoil file must be a comment (starting with '!')"));
  const OpenFastFile f = OpenFastFile::parse(keepLines(lines, 1, lines.count(), true), file);
  f.checkLayout(airfoilLayout());

  AirfoilInput a;
  a.path = file;
  a.name = file.stem().string();
  const std::optional<double> order = f.getDoubleOrDefault("InterpOrd");
  a.interp_order_default = !order;
  if (order) {
    if (*order != 1.0 && *order != 3.0)
      throw InputError(f.where("InterpOrd", "must be 1 (linear) or 3 (cubic spline) or \"default\" (is " +
                                                numberText(*order) + ")"));
    a.interp_order = static_cast<int>(*order);
  }
  if (f.has("RelThickness")) a.rel_thickness = f.getDoubleOrDefault("RelThickness");
  a.non_dim_area = f.getDouble("NonDimArea");
  const OpenFastEntry* coords = f.find("NumCoords");
  if (coords && coords->tokens.size() == 1 && coords->tokens.front().rfind('@', 0) == 0) {
    std::string name = unquoted(coords->tokens.front().substr(1));
    std::replace(name.begin(), name.end(), '\\', '/');
    a.coords_file = (file.parent_path() / name).lexically_normal();
  } else {
    a.num_coords = f.getInt("NumCoords");
    requireNonnegative(f, "NumCoords", *a.num_coords);
  }
  if (f.has("BL_file")) a.bl_file = f.getString("BL_file");

  const int num_tabs = f.getInt("NumTabs");
  if (num_tabs < 1) throw InputError(f.where("NumTabs", "must be at least 1 (is " + std::to_string(num_tabs) + ")"));
  int cursor = f.find("NumTabs")->line;
  for (int t = 1; t <= num_tabs; ++t) {
    const OpenFastEntry* re = entryAfter(f, "Re", cursor);
    const std::string announced = std::to_string(num_tabs) + " tables announced, ";
    if (!re)
      throw InputError(f.where("NumTabs", announced + "no 'Re' line for table " + std::to_string(t) + " after line " +
                                              std::to_string(cursor) + " (truncated file?)"));
    const OpenFastEntry* num_alf = entryAfter(f, "NumAlf", re->line);
    if (!num_alf)
      throw InputError(whirl::where(file.string(), re->line, "NumAlf",
                                    "key not found after 'Re' of table " + std::to_string(t) + " (truncated file?)"));
    a.tables.push_back(readTable(lines, re->line, num_alf->line, columns));
    cursor = a.tables.back().row_lines.back();
  }
  return a;
}

aero::Polar airfoilPolar(const AirfoilInput& af, bool use_cm, aero::ReynoldsInterp reynolds) {
  if (af.tables.empty()) throw InputError(af.path.string() + ": no airfoil table");
  constexpr double deg = std::numbers::pi / 180.0;
  const aero::PolarInterp interp = af.interp_order == 3 ? aero::PolarInterp::CubicSpline : aero::PolarInterp::Linear;
  auto polar = [&](const AirfoilTable& t) {
    std::vector<double> alpha(t.alpha_deg.size());
    for (std::size_t k = 0; k < alpha.size(); ++k) alpha[k] = t.alpha_deg[k] * deg;
    std::vector<double> cm = t.cm.empty() || !use_cm ? std::vector<double>(alpha.size(), 0.0) : t.cm;
    return aero::makePolar(af.name, alpha, t.cl, t.cd, cm, interp,
                           af.path.string() + ":" + std::to_string(t.first_row_line));
  };
  if (reynolds == aero::ReynoldsInterp::None || af.tables.size() == 1) return polar(af.tables.front());
  std::vector<aero::Polar> tables;
  std::vector<double> re;  // the files give millions
  std::vector<std::string> sources;
  for (const AirfoilTable& t : af.tables) {
    tables.push_back(polar(t));
    re.push_back(t.re * 1e6);
    sources.push_back(af.path.string() + ":" + std::to_string(t.re_line));
  }
  return aero::reynoldsPolar(std::move(tables), re, reynolds, sources);
}

}  // namespace whirl::io

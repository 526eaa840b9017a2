#include "src/io/openfast/openfast_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

struct Token {
  std::string text;
  std::size_t begin = 0;  ///< offset in the line
  std::size_t end = 0;    ///< one past the last character
};

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool isAlpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }

bool startsWithCi(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && toLower(s.substr(0, prefix.size())) == prefix;
}

/// Splits a line into tokens at blanks and commas; a token opening with a quote runs to the matching quote.
std::vector<Token> tokenize(std::string_view line) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    if (isBlank(line[i]) || line[i] == ',') {
      ++i;
      continue;
    }
    const std::size_t b = i;
    if (line[i] == '"' || line[i] == '\'') {
      const std::size_t close = line.find(line[i], i + 1);
      i = close == std::string_view::npos ? line.size() : close + 1;
    } else {
      while (i < line.size() && !isBlank(line[i]) && line[i] != ',') ++i;
    }
    out.push_back({std::string(line.substr(b, i - b)), b, i});
  }
  return out;
}

bool isQuoted(std::string_view t) { return !t.empty() && (t.front() == '"' || t.front() == '\''); }

std::string unquote(std::string_view t) {
  if (!isQuoted(t)) return std::string(t);
  t.remove_prefix(1);
  if (!t.empty() && (t.back() == '"' || t.back() == '\'')) t.remove_suffix(1);
  return std::string(t);
}

std::optional<bool> parseBool(std::string_view t) {
  const std::string s = toLower(unquote(t));
  if (s == "true" || s == "t" || s == ".true." || s == ".t.") return true;
  if (s == "false" || s == "f" || s == ".false." || s == ".f.") return false;
  return std::nullopt;
}

bool isDefaultToken(std::string_view t) { return toLower(unquote(t)) == "default"; }

/// A token that can be (part of) a value rather than a key.
bool isValueToken(std::string_view t) {
  return isQuoted(t) || parseFortranDouble(t).has_value() || parseBool(t).has_value() || isDefaultToken(t);
}

/// A token that looks like a key or a column name: starts with a letter or '_'.
bool isIdentifier(std::string_view t) { return !t.empty() && isAlpha(t.front()); }

bool isSeparator(std::string_view trimmed) { return trimmed.substr(0, 3) == "---" || trimmed.substr(0, 3) == "==="; }

bool isNumberRow(const std::vector<Token>& toks) {
  return !toks.empty() &&
         std::all_of(toks.begin(), toks.end(), [](const Token& t) { return parseFortranDouble(t.text).has_value(); });
}

bool isTableHeader(const std::vector<Token>& toks) {
  return toks.size() >= 2 && std::all_of(toks.begin(), toks.end(),
                                         [](const Token& t) { return isIdentifier(t.text) && !isValueToken(t.text); });
}

/// "(-)  (kg/m)  (N m^2)" → {"(-)", "(kg/m)", "(N m^2)"}.
std::vector<std::string> splitUnits(std::string_view line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while ((i = line.find('(', i)) != std::string_view::npos) {
    const std::size_t close = line.find(')', i);
    const std::size_t end = close == std::string_view::npos ? line.size() : close + 1;
    out.emplace_back(line.substr(i, end - i));
    i = end;
  }
  return out;
}

/// A comment line of OpenFAST's FileInfo-based readers (NWTC_IO.f90, ProcessComFile: CommChars '!#%').
bool isCommentStart(std::string_view trimmed) {
  return !trimmed.empty() && (trimmed.front() == '!' || trimmed.front() == '#' || trimmed.front() == '%');
}

/// True when the next non-blank line after line `i` is a unit row "(-) (m) …": line i is then a table's
/// column-name row, even when a bracketed note after the names kept it from parsing as a table.
bool unitRowFollows(const std::vector<std::string_view>& lines, std::size_t i) {
  for (std::size_t j = i + 1; j < lines.size(); ++j) {
    const std::string_view t = trimBlanks(lines[j]);
    if (t.empty()) continue;
    return t.front() == '(';
  }
  return false;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t b = 0;
  while (b < text.size()) {
    std::size_t e = text.find('\n', b);
    if (e == std::string_view::npos) e = text.size();
    std::string_view l = text.substr(b, e - b);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines.push_back(l);
    b = e + 1;
  }
  return lines;
}

}  // namespace

std::string toLower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

std::optional<double> parseFortranDouble(std::string_view text) {
  if (text.empty()) return std::nullopt;
  std::string s(text);
  if (s.front() == '+') s.erase(0, 1);
  if (s.empty()) return std::nullopt;
  const char c0 = s.front();
  if ((c0 >= '0' && c0 <= '9') || c0 == '.' || c0 == '-')
    std::replace_if(
        s.begin(), s.end(), [](char c) { return c == 'd' || c == 'D'; }, 'e');
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string canonicalKey(std::string_view key) {
  std::string out;
  for (const char c : key)
    if (c != '(' && c != ')' && !isBlank(c)) out += c;
  return toLower(out);
}

int OpenFastTable::columnIndex(std::string_view name) const {
  const std::string n = toLower(name);
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (toLower(columns[i]) == n) return static_cast<int>(i);
  return -1;
}

OpenFastFile OpenFastFile::read(const std::filesystem::path& file) {
  std::string text;
  if (!readInputFile(file.string(), text)) throw InputError(whirl::where(file.string(), 0, "", "cannot open file"));
  return parse(text, file);
}

OpenFastFile OpenFastFile::parse(std::string_view text, const std::filesystem::path& file) {
  OpenFastFile f;
  f.path_ = file;
  const std::vector<std::string_view> lines = splitLines(text);
  bool in_outlist = false;
  bool title_seen = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int lineno = static_cast<int>(i) + 1;
    const std::string_view t = trimBlanks(lines[i]);
    if (in_outlist) {
      if (startsWithCi(t, "end")) in_outlist = false;
      continue;
    }
    if (t.empty() || isSeparator(t)) continue;
    if (!title_seen) {
      title_seen = true;
      if (lineno <= 3) {
        f.title_ = tabsToSpaces(t);
        f.title_line_ = lineno;
        continue;
      }
    }
    const std::vector<Token> toks = tokenize(lines[i]);
    if (isTableHeader(toks) && i + 1 < lines.size() && trimBlanks(lines[i + 1]).substr(0, 1) == "(") {
      OpenFastTable tab;
      tab.header_line = lineno;
      for (const Token& tk : toks) tab.columns.push_back(tk.text);
      tab.units = splitUnits(lines[i + 1]);
      std::size_t r = i + 2;
      for (; r < lines.size(); ++r) {
        const std::vector<Token> row = tokenize(lines[r]);
        if (!isNumberRow(row)) break;
        if (tab.rows.size() >= static_cast<std::size_t>(limits::kMaxTableRows))
          throw InputError(tooManyRows(file.string(), static_cast<int>(r) + 1));
        std::vector<double> values;
        for (const Token& tk : row) values.push_back(*parseFortranDouble(tk.text));
        tab.rows.push_back(std::move(values));
        tab.row_lines.push_back(static_cast<int>(r) + 1);
      }
      tab.ends_at_eof = r >= lines.size();
      tab.end_line = tab.ends_at_eof ? static_cast<int>(lines.size()) : static_cast<int>(r) + 1;
      f.tables_.push_back(std::move(tab));
      i = r - 1;
      continue;
    }
    if (toks.empty()) continue;
    // A key without a value, e.g. "OutList  - The next line(s) contains a list of output parameters".
    if (isIdentifier(toks[0].text) && (toks.size() == 1 || toks[1].text.front() == '-')) {
      // "OutList", and the nodal "OutListED"/"OutList_Nodes" blocks of OpenFAST v3+, run to "END".
      if (startsWithCi(toks[0].text, "outlist")) in_outlist = true;
      else if (toks.size() == 1 && !isCommentStart(t)) f.keyless_.emplace_back(lineno, toks[0].text);
      continue;
    }
    // value tokens (the first always), then the key.
    std::size_t k = 1;
    while (k < toks.size() && isValueToken(toks[k].text)) ++k;
    if (k >= toks.size() || !isIdentifier(toks[k].text)) {  // no key: not a value line
      if (!isCommentStart(t)) f.keyless_.emplace_back(lineno, toks[0].text);
      continue;
    }
    OpenFastEntry e;
    e.key = toks[k].text;
    // "BldFile( 1 )": the index was split off at the blanks; join it back up to the closing parenthesis.
    if (e.key.find('(') != std::string::npos && e.key.find(')') == std::string::npos)
      for (std::size_t j = k + 1; j < toks.size() && j <= k + 3; ++j) {
        e.key += toks[j].text;
        if (toks[j].text.find(')') != std::string::npos) break;
      }
    while (e.key.size() > 1 && e.key.back() == '-') e.key.pop_back();  // "Key- description"
    e.raw = std::string(lines[i].substr(toks[0].begin, toks[k - 1].end - toks[0].begin));
    for (std::size_t j = 0; j < k; ++j) e.tokens.push_back(toks[j].text);
    e.line = lineno;
    // "END of output channels …" closes a channel list that has no OutList line (HydroDyn's OUTPUT
    // CHANNELS section): not a value line.
    e.informal = isCommentStart(t) || unitRowFollows(lines, i) || toLower(toks[0].text) == "end";
    if (!e.informal) f.index_.emplace(canonicalKey(e.key), f.entries_.size());  // keeps the first of duplicated keys
    f.entries_.push_back(std::move(e));
  }
  return f;
}

const OpenFastEntry* OpenFastFile::find(std::string_view key) const {
  const auto it = index_.find(canonicalKey(key));
  return it == index_.end() ? nullptr : &entries_[it->second];
}

const OpenFastEntry& OpenFastFile::require(std::string_view key) const {
  const OpenFastEntry* e = find(key);
  if (!e) throw InputError(whirl::where(path_.string(), 0, std::string(key), "key not found in this file"));
  return *e;
}

std::string OpenFastFile::where(std::string_view key, const std::string& reason) const {
  if (const OpenFastEntry* e = find(key)) return where(*e, reason);
  return whirl::where(path_.string(), 0, std::string(key), reason);
}

std::string OpenFastFile::where(const OpenFastEntry& e, const std::string& reason) const {
  return whirl::where(path_.string(), e.line, e.key, e.overridden ? reason + " (value set by override)" : reason);
}

std::string OpenFastFile::singleToken(const OpenFastEntry& e, const char* what) const {
  if (e.tokens.empty()) throw InputError(where(e, std::string("no value, expected ") + what));
  if (e.tokens.size() > 1) throw InputError(where(e, "expected one " + std::string(what) + ", found '" + e.raw + "'"));
  return e.tokens.front();
}

namespace {
/// "'x' is not a number"; for the keyword `default` also why: the getters that accept it are those
/// of the keys OpenFAST reads with ParseVarWDefault (or a DEFAULT string test), this one is not.
std::string notA(std::string_view tok, const char* what) {
  std::string reason = "'" + std::string(tok) + "' is not " + what;
  if (isDefaultToken(tok)) reason += " (OpenFAST has no default value for this key)";
  return reason;
}

double finiteOrThrow(const OpenFastFile& f, std::string_view key, std::string_view tok) {
  const std::optional<double> v = parseFortranDouble(tok);
  if (!v) throw InputError(f.where(key, notA(tok, "a number")));
  if (std::isnan(*v)) throw InputError(f.where(key, "value is NaN"));
  if (std::isinf(*v)) throw InputError(f.where(key, "value is infinite"));
  return *v;
}
}  // namespace

double OpenFastFile::getDouble(std::string_view key) const {
  return finiteOrThrow(*this, key, singleToken(require(key), "number"));
}

std::optional<double> OpenFastFile::getDoubleOrDefault(std::string_view key) const {
  const std::string tok = singleToken(require(key), "number or \"default\"");
  if (isDefaultToken(tok)) return std::nullopt;
  return finiteOrThrow(*this, key, tok);
}

int OpenFastFile::getInt(std::string_view key) const {
  std::string tok = singleToken(require(key), "integer");
  const std::string shown = tok;
  if (!tok.empty() && tok.front() == '+') tok.erase(0, 1);
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || ptr != tok.data() + tok.size() || tok.empty())
    throw InputError(where(key, notA(shown, "an integer")));
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    throw InputError(where(key, "'" + shown + "' is out of the integer range"));
  return static_cast<int>(v);
}

bool OpenFastFile::getBool(std::string_view key) const {
  const std::string tok = singleToken(require(key), "True/False flag");
  const std::optional<bool> b = parseBool(tok);
  if (!b) throw InputError(where(key, notA(tok, "True or False")));
  return *b;
}

std::string OpenFastFile::getString(std::string_view key) const { return unquote(singleToken(require(key), "string")); }

std::filesystem::path OpenFastFile::getPath(std::string_view key) const {
  std::string s = getString(key);
  std::replace(s.begin(), s.end(), '\\', '/');
  if (s.empty()) throw InputError(where(key, "empty file name"));
  const std::filesystem::path p(s);
  if (p.is_absolute()) return p.lexically_normal();
  return (path_.parent_path() / p).lexically_normal();
}

std::filesystem::path OpenFastFile::getExistingPath(std::string_view key) const {
  const std::filesystem::path p = getPath(key);
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(p, ec);
  if (std::filesystem::exists(st) && !std::filesystem::is_regular_file(st))
    throw InputError(where(key, "not a regular file (a folder, FIFO or device): " + p.string()));
  if (!std::filesystem::is_regular_file(st)) throw InputError(where(key, "file not found: " + p.string()));
  return p;
}

std::vector<double> OpenFastFile::getDoubles(std::string_view key) const {
  const OpenFastEntry& e = require(key);
  if (e.tokens.empty()) throw InputError(where(e, "no value, expected a list of numbers"));
  std::vector<double> out;
  for (const std::string& tok : e.tokens) out.push_back(finiteOrThrow(*this, key, tok));
  return out;
}

bool OpenFastFile::isDefault(std::string_view key) const {
  const OpenFastEntry* e = find(key);
  return e && e->tokens.size() == 1 && isDefaultToken(e->tokens.front());
}

std::optional<double> OpenFastFile::findDoubleOr(std::string_view key, double fallback) const {
  if (isDefault(key)) return fallback;
  return findDouble(key);
}

std::optional<int> OpenFastFile::findIntOr(std::string_view key, int fallback) const {
  if (isDefault(key)) return fallback;
  return findInt(key);
}

std::optional<double> OpenFastFile::findDouble(std::string_view key) const {
  return has(key) ? std::optional<double>(getDouble(key)) : std::nullopt;
}

std::optional<int> OpenFastFile::findInt(std::string_view key) const {
  return has(key) ? std::optional<int>(getInt(key)) : std::nullopt;
}

std::optional<bool> OpenFastFile::findBool(std::string_view key) const {
  return has(key) ? std::optional<bool>(getBool(key)) : std::nullopt;
}

void OpenFastFile::refuseKeylessLines(const OpenFastLayout& layout) const {
  int last_key_line = 0;
  for (const OpenFastEntry& e : entries_)
    if (!e.informal) last_key_line = std::max(last_key_line, e.line);
  for (const auto& [line, token] : keyless_)
    if (line > 2 && line < last_key_line)  // lines 1-2: header and title; after the last key: not read
      throw InputError(whirl::where(path_.string(), line, shortenedForMessage(token),
                                    std::string("a line without a key in an OpenFAST ") + layout.name +
                                        " file: OpenFAST reads it by position and stops there or takes it for the "
                                        "next key's value; remove it (every value line is VALUE KEY)"));
}

void OpenFastFile::checkLayout(const OpenFastLayout& layout) const {
  // Position in `keys` of the key spelled `key` (any spelling canonicalKey accepts), or npos. A layout
  // key written `Name(k)` is an array: `Name` and an index ("bldfile1" from BldFile(1) or BldFile1).
  auto position = [](const std::vector<std::string_view>& keys, const std::string& key) {
    const std::string c = canonicalKey(key);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const bool array = keys[i].size() > 3 && keys[i].substr(keys[i].size() - 3) == "(k)";
      const std::string k = toLower(array ? keys[i].substr(0, keys[i].size() - 3) : keys[i]);
      if (!array && c == k) return i;
      if (array && c.size() > k.size() && c.compare(0, k.size(), k) == 0 &&
          c.find_first_not_of("0123456789", k.size()) == std::string::npos)
        return i;
    }
    return std::string::npos;
  };
  const std::size_t npos = std::string::npos;
  std::vector<std::size_t> at(entries_.size(), 0);  // layout position of each entry
  std::vector<bool> present(layout.keys.size(), false);
  if (!layout.keys.empty())
    for (std::size_t i = 0; i < entries_.size(); ++i)
      if (!entries_[i].informal && (at[i] = position(layout.keys, entries_[i].key)) != npos) present[at[i]] = true;
  if (!layout.keyless_lines) refuseKeylessLines(layout);
  std::unordered_map<std::string, int> first_line;
  std::size_t previous = npos;  // layout position of the last key read
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const OpenFastEntry& e = entries_[i];
    if (e.informal) continue;
    // Lines 1 and 2 are the header and title OpenFAST skips whatever they hold (a line 1 that is not a
    // separator makes line 2 parse as a value line: "IEA 15 MW offshore …").
    if (at[i] == npos && e.line <= 2) continue;
    if (at[i] == npos) {
      // Name what OpenFAST reads here: the layout keys missing from the file between the known keys
      // before and after this line (several when file versions differ at this place).
      std::size_t next = layout.keys.size();
      for (std::size_t j = i + 1; j < entries_.size() && next == layout.keys.size(); ++j)
        if (!entries_[j].informal && at[j] != npos) next = at[j];
      std::string expected;
      for (std::size_t k = previous == npos ? 0 : previous + 1; k < next; ++k)
        if (!present[k]) expected += (expected.empty() ? "" : " or ") + std::string(layout.keys[k]);
      if (expected.empty() && previous != npos && next <= previous) expected = std::string(layout.keys[previous]);
      // A row of several values with a word among them, where every key of this part of the layout is
      // present, is a table row with a bad value ("3 5 6 7 deep 1025"), not a key line: the table's
      // reader names the column.
      if (expected.empty() && e.tokens.size() >= 3) continue;
      const std::string found = expected.empty() ? "" : " (expected " + expected + " here)";
      throw InputError(whirl::where(path_.string(), e.line, e.key,
                                    std::string("not a key of an OpenFAST ") + layout.name + " file" + found +
                                        ": OpenFAST reads by position, so an extra line shifts every later "
                                        "value; remove it (or check the file type)"));
    }
    previous = at[i];
    const auto [it, inserted] = first_line.emplace(canonicalKey(e.key), e.line);
    if (!inserted && position(layout.repeatable, e.key) == std::string::npos)
      throw InputError(whirl::where(path_.string(), e.line, e.key,
                                    "given twice (first on line " + std::to_string(it->second) +
                                        "): OpenFAST reads by position and would take this line for another "
                                        "value; remove one"));
  }
}

const OpenFastTable* OpenFastFile::findTable(std::string_view column) const {
  for (const OpenFastTable& t : tables_)
    if (t.columnIndex(column) >= 0) return &t;
  return nullptr;
}

void OpenFastFile::setValue(std::string_view key, const std::string& value) {
  const auto it = index_.find(canonicalKey(key));
  if (it == index_.end())
    throw InputError(whirl::where(path_.string(), 0, std::string(key), "unknown key (not in this file)"));
  OpenFastEntry& e = entries_[it->second];
  e.raw = value;
  e.tokens.clear();
  for (const Token& t : tokenize(value)) e.tokens.push_back(t.text);
  e.overridden = true;
}

}  // namespace whirl::io

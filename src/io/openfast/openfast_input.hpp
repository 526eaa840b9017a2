#pragma once
/// \file
/// Generic reader for OpenFAST-style input files (`.fst`, ElastoDyn, ServoDyn, tower and blade files).
///
/// Such files are line based:
/// - line 1 (and sometimes 2) is a header, the first non-separator line among the first three is the title;
/// - separator lines start with `---` or `===`;
/// - value lines read `value(s)  Key  - description`: the value comes first (a number, a quoted string,
///   True/False in any case, `default`, or a list of numbers separated by blanks or commas), then the key;
/// - an `OutList` line opens a block of output channel names that ends with a line starting with `END`
///   (skipped: whirl does not use output lists);
/// - a table is a header row of column names, a unit row of parenthesised units, then one row of numbers
///   per line (the count is given by a key such as `NTwInpSt`; checking it is the typed reader's job).
///
/// Each key keeps its raw value and line number so that every error reads "file:line: key: reason".
/// Keys are matched by `canonicalKey` (case-insensitive, `Name(k)` = `Namek`). When a key appears twice (e.g. `EDFile`
/// of a second rotor in OpenFAST v5), the first occurrence is the one returned and overridden; the typed readers call
/// `checkLayout` first, which refuses keys given twice (except those a layout repeats) and keys the layout does not
/// have: OpenFAST reads these files by position, so an extra or repeated line shifts every later value, and whirl,
/// reading by key, would silently disagree with OpenFAST.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace whirl::io {

/// One `value  Key` line.
struct OpenFastEntry {
  std::string key;                  ///< key as written in the file, e.g. "BldFile(1)"
  std::string raw;                  ///< value text as written (quotes kept), e.g. "\"blade.dat\"" or "10, 19, 28"
  std::vector<std::string> tokens;  ///< value split into tokens (quotes kept on quoted tokens)
  int line = 0;                     ///< 1-based line number in the file
  bool overridden = false;          ///< true when the value came from an override (`--set KEY=VALUE`)
  /// A comment line (first character `!`, `#` or `%`: NWTC_IO.f90, ProcessComFile, skips them), the
  /// column-name row of a table whose unit row follows, or an `END` line: kept for the readers that
  /// scan entries, but neither found by key nor checked by checkLayout.
  bool informal = false;
};

/// A table: header row of column names, unit row, rows of numbers.
struct OpenFastTable {
  std::vector<std::string> columns;       ///< column names as written
  std::vector<std::string> units;         ///< units as written, e.g. "(kg/m)"; may be shorter than columns
  int header_line = 0;                    ///< line of the column-name row
  std::vector<std::vector<double>> rows;  ///< numbers as read (NaN/inf kept: validation reports them with the line)
  std::vector<int> row_lines;             ///< line of each row
  int end_line = 0;                       ///< first line after the table that is not a row (or last line + 1)
  bool ends_at_eof = false;               ///< true when the file ended right after the last row

  /// Index of a column by name, case-insensitive; -1 when absent.
  int columnIndex(std::string_view name) const;
};

/// The keys of one OpenFAST file type, over the versions whirl reads (for OpenFastFile::checkLayout).
struct OpenFastLayout {
  const char* name = "";  ///< file type for messages, e.g. "ElastoDyn"
  /// Every key in file order (versions merged); an array written `Name(k)` (its entries `Name(1)`,
  /// `Name1`, …); empty: any key accepted.
  std::vector<std::string_view> keys;
  std::vector<std::string_view> repeatable;  ///< keys that may appear more than once (same spelling rule)
  /// Whether lines without a key (a lone value, a lone word) may stand between key lines: true where the
  /// format has them (AeroDyn's `AFNames` continuation lines, airfoil and blade tables without a unit row);
  /// false for files whose every value line carries its key (.fst, ElastoDyn, InflowWind, ServoDyn), where
  /// OpenFAST's ParseVar would stop at such a line or take it for the next key's value.
  bool keyless_lines = true;
};

/// A parsed OpenFAST input file. Read-only apart from `setValue` (overrides).
class OpenFastFile {
 public:
  /// Reads and tokenizes a file. Throws InputError("file: cannot open file") when it cannot be read.
  static OpenFastFile read(const std::filesystem::path& file);
  /// Tokenizes text; `file` is used for messages and to resolve relative paths.
  static OpenFastFile parse(std::string_view text, const std::filesystem::path& file);

  const std::filesystem::path& path() const { return path_; }
  /// The title line, tabs turned into spaces (it may hold other control characters: check before use).
  const std::string& title() const { return title_; }
  int titleLine() const { return title_line_; }  ///< 1-based, 0 without a title
  const std::vector<OpenFastEntry>& entries() const { return entries_; }
  const std::vector<OpenFastTable>& tables() const { return tables_; }

  /// The entry of `key` (matched by canonicalKey: case-insensitive, `BldFile(1)` finds `BldFile1`), or nullptr.
  const OpenFastEntry* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }

  /// "file:line: key: reason" for `key` (line left out when the key is absent).
  std::string where(std::string_view key, const std::string& reason) const;

  // Typed getters. Each throws InputError naming file, line and key when the key is missing, when the
  // value is not of the type asked for, or (numbers) when it is NaN or infinite.
  double getDouble(std::string_view key) const;
  /// nullopt when the value is `default` (any case, quoted or not).
  std::optional<double> getDoubleOrDefault(std::string_view key) const;
  /// True when `key` is present and its value is the keyword `default` (any case, quoted or not), which
  /// OpenFAST's ParseVarWDefault (NWTC_IO.f90) replaces by the module's default value.
  bool isDefault(std::string_view key) const;
  int getInt(std::string_view key) const;
  /// True/False, T/F, .true./.false. in any case.
  bool getBool(std::string_view key) const;
  /// The value with its quotes removed.
  std::string getString(std::string_view key) const;
  /// A file name, resolved against the folder of this file (backslashes read as '/').
  std::filesystem::path getPath(std::string_view key) const;
  /// Like getPath, but throws InputError("file:line: key: file not found: …") when it does not exist.
  std::filesystem::path getExistingPath(std::string_view key) const;
  /// All numbers of a list value such as `10, 19, 28`.
  std::vector<double> getDoubles(std::string_view key) const;

  // Optional variants: nullopt when the key is absent, same errors as above when it is present but bad.
  std::optional<double> findDouble(std::string_view key) const;
  std::optional<int> findInt(std::string_view key) const;
  std::optional<bool> findBool(std::string_view key) const;
  /// findDouble, and `fallback` when the value is `default` (OpenFAST's default, cited by the caller).
  std::optional<double> findDoubleOr(std::string_view key, double fallback) const;
  /// findInt, and `fallback` when the value is `default`.
  std::optional<int> findIntOr(std::string_view key, int fallback) const;

  /// Refuses a key given twice ("file:line: key: given twice (first on line N) …") unless the layout
  /// lists it as repeatable (`BldFile1` and `BldFile(1)` are the same key), and a key the layout does
  /// not have ("file:line: key: not a key of a … file (expected K here)", K being the layout keys the
  /// file lacks between the known keys around that line). Informal entries (comments, table column
  /// rows) are skipped. Where the layout has no keyless lines, a line without a key between two key lines is
  /// refused too ("file:line: TOKEN: a line without a key …"); text after the last key line is not read.
  void checkLayout(const OpenFastLayout& layout) const;

  /// The first table that has a column `column` (case-insensitive), or nullptr.
  const OpenFastTable* findTable(std::string_view column) const;

  /// Replaces the value of an existing key (the `--set KEY=VALUE` override).
  /// Throws InputError("file: key: unknown key") when the key is not in this file.
  void setValue(std::string_view key, const std::string& value);

 private:
  const OpenFastEntry& require(std::string_view key) const;
  std::string where(const OpenFastEntry& e, const std::string& reason) const;
  std::string singleToken(const OpenFastEntry& e, const char* what) const;
  void refuseKeylessLines(const OpenFastLayout& layout) const;

  std::filesystem::path path_;
  std::string title_;
  int title_line_ = 0;
  std::vector<OpenFastEntry> entries_;
  std::vector<OpenFastTable> tables_;
  /// Lines that carry no key (a lone value or word, values without a label), outside tables and output
  /// lists: (line, first token).
  std::vector<std::pair<int, std::string>> keyless_;
  std::unordered_map<std::string, std::size_t> index_;  ///< lower-case key → first entry
};

/// Number parsing shared by the OpenFAST readers: accepts a leading '+' and Fortran 'D' exponents;
/// nullopt unless the whole text is a number. NaN and inf are returned as such (callers reject them).
std::optional<double> parseFortranDouble(std::string_view text);

/// The one rule by which whirl matches the label of a value line to the key it expects, the labels of
/// every OpenFAST version being accepted: case-insensitive (as Fortran), and an array entry written
/// `Name(k)` (FAST 8, OpenFAST templates), `Name( k )` or `Namek` (WISDEM/WEIS, e.g. `BldFile1`,
/// `BldFlDmp1`) is the same key. OpenFAST itself reads these files by position and checks many labels
/// only loosely (ElastoDyn reads `BldFile(k)` with ReadVar, which ignores the label), so files written
/// with either spelling run there. Returns the lower-case label without parentheses and blanks:
/// "BldFile(1)", "BldFile( 1 )" and "BldFile1" all give "bldfile1".
std::string canonicalKey(std::string_view key);

/// Lower-case copy (ASCII), for case-insensitive key and column names.
std::string toLower(std::string_view s);

}  // namespace whirl::io

#pragma once
/// \file
/// Raw lines of an OpenFAST input file, for the parts `OpenFastFile` does not keep: value lists that
/// run over several lines without a key (AeroDyn `AFNames`), tables without a header row (airfoil
/// coefficient tables, whose column names sit in a `!` comment) and tables whose header carries a
/// trailing comment (AeroDyn tower table). Line numbers are 1-based, as in every message.
///
/// Comment lines are those whose first non-blank character is `!`, `#` or `%` (the comment characters
/// of OpenFAST's NWTC library); OpenFAST skips them wherever it reads a file line by line.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace whirl::io {

/// The text of a file, split into lines (line i + 1 of the file is lines[i]; '\r' removed).
class OpenFastLines {
 public:
  /// Reads a file. Throws InputError("file: cannot open file") when it cannot be read.
  static OpenFastLines read(const std::filesystem::path& file);
  /// Splits `text`; `file` is only used in messages.
  static OpenFastLines fromText(std::string_view text, const std::filesystem::path& file);

  const std::filesystem::path& path() const { return path_; }
  int count() const { return static_cast<int>(lines_.size()); }
  /// Line `n` (1-based); "" past the end.
  const std::string& line(int n) const;
  /// The whole text again, lines joined with '\n'.
  std::string text() const;
  /// The text with every comment line replaced by an empty line (line numbers unchanged).
  std::string textWithoutComments() const;

  /// The first line after `n` that is neither blank nor a comment; nullopt at the end of the file.
  std::optional<int> nextContentLine(int n) const;

 private:
  std::filesystem::path path_;
  std::vector<std::string> lines_;
};

/// True when the first non-blank character is '!', '#' or '%'.
bool isCommentLine(std::string_view line);
/// True when the line holds only blanks.
bool isBlankLine(std::string_view line);

/// Splits a line into words at blanks and commas; a word opening with a quote runs to the closing quote
/// (quotes kept). Text from a '!' outside quotes onwards is a comment and is dropped.
std::vector<std::string> splitWords(std::string_view line);

/// The word without its surrounding quotes.
std::string unquoted(std::string_view word);

/// The numbers of a row such as "-180.00  0.000  0.0185  0.0000" (Fortran 'D' exponents accepted;
/// NaN and inf returned as such for the caller to report); nullopt when any word is not a number or
/// the line is empty. Words after a '!' are ignored.
std::optional<std::vector<double>> parseNumberRow(std::string_view line);

}  // namespace whirl::io

#pragma once
/// \file
/// Names and other text that whirl takes from input files and writes into generated files (plot
/// scripts, tables, .lin, .mat). A control character in such text — a newline above all — would end
/// a quoted string in a generated script and turn the rest into commands (a Gnuplot line starting
/// with `!` runs a shell), or break a table's line structure. So input text is checked once, where
/// it is read, and the writers of each format escape or replace what remains on their own.
#include <string>
#include <string_view>

namespace whirl {

/// True for the ASCII control characters: below 0x20 (newline, carriage return, tab, escape, …) and 0x7F.
constexpr bool isControlCharacter(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x20 || u == 0x7F;
}

/// Why `s` is not UTF-8 text: "contains a byte that is not UTF-8 text (0xFF) at byte 4: …"; empty
/// when it is (RFC 3629: no overlong forms, no surrogates). JSON and the tables are UTF-8: a name
/// that is not would stop the JSON writer mid-way (issue 48, item 5).
std::string invalidUtf8Reason(std::string_view s);

/// Why `s` cannot be a name: "contains a control character (line feed, 0x0A) at character 3: names
/// are printable text on one line", or invalidUtf8Reason(s); empty when it is a printable UTF-8
/// name. The message does not repeat `s` (it would carry the character into the message).
std::string controlCharacterReason(std::string_view s);

/// \throws InputError "file:line: key: <controlCharacterReason(s)>" when `s` holds a control character.
void requirePrintable(std::string_view s, const std::string& file, int line, const std::string& key);

/// `s` with tabs turned into spaces: free-text columns of other tools' files (an OpenFAST title,
/// a .lin description) may use tabs as spacing; any other control character stays an error.
std::string tabsToSpaces(std::string_view s);

/// `s` with every control character replaced by a space, for writers of line-based formats (a .lin
/// column, a comment in a script): the last line of defence when a name did not come through a reader.
std::string withoutControlCharacters(std::string_view s);

/// `s` without the blanks (space, tab, CR, LF, FF, VT) at either end.
constexpr std::string_view trimBlanks(std::string_view s) {
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

/// `s` with control characters and bytes that are not UTF-8 written as C escapes (\n, \t, \r, \x1B,
/// \xFF; other text unchanged): error messages stay one line of text whatever name they quote.
std::string escapeControlCharacters(std::string_view s);

/// `s` as quoted in a message: at most 40 bytes, longer text cut to 37 and "..." at a UTF-8 character
/// boundary (a cut inside a character would make the message itself invalid UTF-8).
std::string shortenedForMessage(std::string_view s);

}  // namespace whirl

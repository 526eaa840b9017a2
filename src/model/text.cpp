#include "src/model/text.hpp"

#include <cstdio>

#include "src/model/error.hpp"

namespace whirl {
namespace {

std::string hex(unsigned char c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", c);
  return buf;
}

const char* controlName(unsigned char c) {
  switch (c) {
    case '\n': return "line feed";
    case '\r': return "carriage return";
    case '\t': return "tab";
    case 0x1B: return "escape";
    case 0x00: return "null";
    case 0x7F: return "delete";
    default: return "control character";
  }
}

}  // namespace

std::string controlCharacterReason(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!isControlCharacter(s[i])) continue;
    const auto c = static_cast<unsigned char>(s[i]);
    return std::string("contains a control character (") + controlName(c) + ", " + hex(c) + ") at character " +
           std::to_string(i + 1) + ": names and titles must be printable text on one line";
  }
  return "";
}

void requirePrintable(std::string_view s, const std::string& file, int line, const std::string& key) {
  const std::string reason = controlCharacterReason(s);
  if (!reason.empty()) throw InputError(where(file, line, escapeControlCharacters(key), reason));
}

std::string tabsToSpaces(std::string_view s) {
  std::string t(s);
  for (char& c : t)
    if (c == '\t') c = ' ';
  return t;
}

std::string withoutControlCharacters(std::string_view s) {
  std::string t(s);
  for (char& c : t)
    if (isControlCharacter(c)) c = ' ';
  return t;
}

std::string escapeControlCharacters(std::string_view s) {
  std::string t;
  t.reserve(s.size());
  for (char c : s) {
    if (c == '\n') t += "\\n";
    else if (c == '\r') t += "\\r";
    else if (c == '\t') t += "\\t";
    else if (isControlCharacter(c)) t += "\\x" + hex(static_cast<unsigned char>(c)).substr(2);
    else t += c;
  }
  return t;
}

}  // namespace whirl

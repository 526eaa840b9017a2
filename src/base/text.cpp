#include "src/base/text.hpp"

#include <cstdio>

#include "src/base/error.hpp"

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

/// Length of the UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no surrogates, at most
/// U+10FFFF), 0 when the bytes there are not one.
std::size_t utf8Length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the range of the second byte
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;  // overlong
    if (c == 0xED) hi = 0x9F;  // surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;  // overlong
    if (c == 0xF4) hi = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  return n;
}

}  // namespace

std::string invalidUtf8Reason(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8Length(s, i);
    if (n == 0)
      return "contains a byte that is not UTF-8 text (" + hex(static_cast<unsigned char>(s[i])) + ") at byte " +
             std::to_string(i + 1) + ": names and titles must be UTF-8 text (save the file as UTF-8)";
    i += n;
  }
  return "";
}

std::string controlCharacterReason(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!isControlCharacter(s[i])) continue;
    const auto c = static_cast<unsigned char>(s[i]);
    return std::string("contains a control character (") + controlName(c) + ", " + hex(c) + ") at character " +
           std::to_string(i + 1) + ": names and titles must be printable text on one line";
  }
  return invalidUtf8Reason(s);
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
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const std::size_t n = utf8Length(s, i);
    if (n == 0) {  // a byte that is not UTF-8: as an escape, so the message is valid text
      t += "\\x" + hex(static_cast<unsigned char>(c)).substr(2);
      continue;
    }
    if (n > 1) {
      t.append(s.substr(i, n));
      i += n - 1;
      continue;
    }
    if (c == '\n') t += "\\n";
    else if (c == '\r') t += "\\r";
    else if (c == '\t') t += "\\t";
    else if (isControlCharacter(c)) t += "\\x" + hex(static_cast<unsigned char>(c)).substr(2);
    else t += c;
  }
  return t;
}

std::string shortenedForMessage(std::string_view s) {
  if (s.size() <= 40) return std::string(s);
  std::size_t n = 37;
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
  return std::string(s.substr(0, n)) + "...";
}

}  // namespace whirl

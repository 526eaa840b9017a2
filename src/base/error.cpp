#include "src/base/error.hpp"

#include "src/base/text.hpp"

namespace whirl {

std::string where(const std::string& file, int line, const std::string& key, const std::string& reason) {
  std::string s;
  if (!file.empty()) s += file;
  if (line > 0) s += ":" + std::to_string(line);
  if (!s.empty()) s += ": ";
  if (!key.empty()) s += key + ": ";
  // A quoted name or value with a newline would split the one-line message: written as \n.
  return escapeControlCharacters(s + reason);
}

void Where::fail(const std::string& reason) const { throw InputError(whirl::where(file, line, key, reason + note)); }

}  // namespace whirl

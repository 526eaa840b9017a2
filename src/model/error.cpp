#include "src/model/error.hpp"

namespace whirl {

std::string where(const std::string& file, int line, const std::string& key, const std::string& reason) {
  std::string s;
  if (!file.empty()) s += file;
  if (line > 0) s += ":" + std::to_string(line);
  if (!s.empty()) s += ": ";
  if (!key.empty()) s += key + ": ";
  return s + reason;
}

}  // namespace whirl

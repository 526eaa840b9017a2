#include "src/io/openfast/elastodyn_common.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"

namespace whirl::io {

std::string indexedKey(std::string_view base, int index) {
  return std::string(base) + "(" + std::to_string(index) + ")";
}

std::filesystem::path resolveInputPath(const std::filesystem::path& from, std::string name) {
  std::replace(name.begin(), name.end(), '\\', '/');
  const std::filesystem::path p(name);
  return (p.is_absolute() ? p : from.parent_path() / p).lexically_normal();
}

namespace {

const OpenFastEntry* entryAt(const OpenFastFile& f, int line) {
  for (const OpenFastEntry& e : f.entries())
    if (e.line == line) return &e;
  return nullptr;
}

}  // namespace

AirfoilNameList readAirfoilNameList(const OpenFastFile& f, const OpenFastLines& lines, std::string_view count_key,
                                    std::string_view list_key, int count) {
  AirfoilNameList out;
  const OpenFastEntry* first = f.find(list_key);
  if (!first) throw InputError(f.where(list_key, "key not found in this file"));
  out.paths.push_back(resolveInputPath(f.path(), f.getString(list_key)));
  out.lines.push_back(first->line);
  const std::string list = toLower(list_key);
  int at = first->line;
  for (int k = 2; k <= count; ++k) {
    const std::optional<int> next = lines.nextContentLine(at);
    const std::vector<std::string> words = next ? splitWords(lines.line(*next)) : std::vector<std::string>{};
    const OpenFastEntry* keyed = next ? entryAt(f, *next) : nullptr;  // e.g. "True  UseBlCm": the list ended
    if (!next || words.empty() || parseFortranDouble(words.front()) || words.front().rfind("==", 0) == 0 ||
        words.front().rfind("--", 0) == 0 || (keyed && toLower(keyed->key).rfind(list, 0) != 0))
      throw InputError(f.where(count_key, "announces " + std::to_string(count) + " airfoil files, only " +
                                              std::to_string(k - 1) + " names follow " + std::string(list_key) +
                                              " (line " + std::to_string(first->line) + ")"));
    out.paths.push_back(resolveInputPath(f.path(), unquoted(words.front())));
    out.lines.push_back(*next);
    at = *next;
  }
  return out;
}

std::string numberText(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

ModeShapeCoeffs readModeShape(const OpenFastFile& f, std::string_view base) {
  const ModeShapeCoeffs c = getIndexed<5>(f, base, 2);
  const double sum = c[0] + c[1] + c[2] + c[3] + c[4];
  if (!(std::abs(sum - 1.0) <= 1e-2))
    throw InputError(f.where(indexedKey(base, 6), "mode shape coefficients " + std::string(base) + "(2..6) sum to " +
                                                      numberText(sum) +
                                                      ", must sum to 1 (tip deflection normalised to 1)"));
  return c;
}

void requirePositive(const OpenFastFile& f, std::string_view key, double value) {
  if (!(value > 0.0)) throw InputError(f.where(key, "must be positive (is " + numberText(value) + ")"));
}

void requireNonnegative(const OpenFastFile& f, std::string_view key, double value) {
  if (!(value >= 0.0)) throw InputError(f.where(key, "must not be negative (is " + numberText(value) + ")"));
}

void requireGravity(const OpenFastFile& f, double value) {
  requireNonnegative(f, "Gravity", value);
  if (value > limits::kMaxGravity)
    throw InputError(f.where("Gravity", "is " + numberText(value) + " m/s², above the limit of " +
                                            numberText(limits::kMaxGravity) + " m/s² (100 g)"));
}

}  // namespace whirl::io

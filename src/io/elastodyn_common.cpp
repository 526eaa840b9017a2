#include "src/io/elastodyn_common.hpp"

#include <charconv>
#include <cmath>

#include "src/model/error.hpp"

namespace whirl::io {

std::string indexedKey(std::string_view base, int index) {
  return std::string(base) + "(" + std::to_string(index) + ")";
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

}  // namespace whirl::io

#pragma once
/// \file
/// Small helpers shared by the ElastoDyn readers: indexed keys such as `BlPitch(1..3)`, polynomial mode
/// shapes, and sign checks that report "file:line: key: reason".
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/io/openfast/openfast_input.hpp"
#include "src/io/openfast/openfast_lines.hpp"

namespace whirl::io {

/// Coefficients of x^2 … x^6 of an ElastoDyn polynomial mode shape φ(x) = Σ c_k x^k, x = fraction of the
/// flexible length (index 0 ↔ x^2, key `Name(2)`; index 4 ↔ x^6, key `Name(6)`). Dimensionless; they
/// sum to 1 (tip deflection normalised to 1).
using ModeShapeCoeffs = std::array<double, 5>;

/// "BlPitch(2)" from ("BlPitch", 2).
std::string indexedKey(std::string_view base, int index);

/// Values of `base(first)` … `base(first+N-1)`; InputError when any is missing or not a finite number.
template <std::size_t N>
std::array<double, N> getIndexed(const OpenFastFile& f, std::string_view base, int first = 1) {
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = f.getDouble(indexedKey(base, first + static_cast<int>(i)));
  return out;
}

/// Like getIndexed, but nullopt when `base(first)` is absent (keys added in later file versions).
template <std::size_t N>
std::optional<std::array<double, N>> findIndexed(const OpenFastFile& f, std::string_view base, int first = 1) {
  if (!f.has(indexedKey(base, first))) return std::nullopt;
  return getIndexed<N>(f, base, first);
}

/// Reads `base(2)` … `base(6)` and checks that they sum to 1 within 0.01: a shape normalised to a unit
/// tip deflection, as ElastoDyn's DOFs assume. The tolerance is loose on purpose: coefficients printed
/// to 4–6 digits sum to 0.999 (NREL 5MW TwSSM2Sh) or 1.0001 (BldFl2Sh); the check is there to catch a
/// mistyped coefficient, which moves the sum far more.
ModeShapeCoeffs readModeShape(const OpenFastFile& f, std::string_view base);

/// InputError "file:line: key: must be positive (is -1)" unless value > 0.
void requirePositive(const OpenFastFile& f, std::string_view key, double value);
/// InputError "file:line: key: must not be negative (is -1)" unless value >= 0.
void requireNonnegative(const OpenFastFile& f, std::string_view key, double value);
/// `Gravity` [m/s²]: not negative and at most limits::kMaxGravity.
void requireGravity(const OpenFastFile& f, double value);

/// A file name as OpenFAST resolves it: relative to the folder of `from`, backslashes read as '/'.
std::filesystem::path resolveInputPath(const std::filesystem::path& from, std::string name);

/// Airfoil file names given over several lines (AeroDyn's `AFNames`, AeroDyn v14's `FoilNm`).
struct AirfoilNameList {
  std::vector<std::filesystem::path> paths;  ///< resolved against the folder of the file read
  std::vector<int> lines;                    ///< file line of each name
};

/// `count` names: the first is the value of `list_key`, the others alone on the next content lines.
/// InputError "file:line: count_key: announces N airfoil files, only K names follow list_key (line L)" when the
/// list ends early (a number, a separator or another key where a name should be).
AirfoilNameList readAirfoilNameList(const OpenFastFile& f, const OpenFastLines& lines, std::string_view count_key,
                                    std::string_view list_key, int count);

/// Shortest round-trip text of a number, for messages.
std::string numberText(double v);

}  // namespace whirl::io

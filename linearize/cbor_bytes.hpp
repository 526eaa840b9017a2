#pragma once
/// \file
/// The envelope of the results that travel between MPI ranks as bytes (export points, Campbell
/// points): a JSON value written as CBOR, so doubles keep their 8 bytes, and read back with every
/// failure — malformed CBOR, a missing key, a wrong type, a size that does not match — reported as
/// one ComputeError naming what was being decoded.
#include <bit>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/base/error.hpp"

namespace whirl {

/// CBOR bytes of `j`.
inline std::string cborBytes(const nlohmann::json& j) {
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(j);
  return std::string(bytes.begin(), bytes.end());
}

/// `n` doubles as one CBOR byte string of little-endian 8-byte words: the bits, whatever the value
/// (nlohmann's own float encoding keeps the value but not a NaN's payload; byte strings are compact).
inline nlohmann::json cborDoubles(const double* v, std::size_t n) {
  std::vector<std::uint8_t> b(8 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto w = std::bit_cast<std::uint64_t>(v[i]);
    for (std::size_t k = 0; k < 8; ++k) b[8 * i + k] = static_cast<std::uint8_t>(w >> (8 * k));
  }
  return nlohmann::json::binary(std::move(b));
}

/// The `n` doubles of cborDoubles into `v`. \throws std::runtime_error when the byte string does not
/// hold exactly `n` (nlohmann::json's type_error when `j` is no byte string).
inline void readCborDoubles(const nlohmann::json& j, double* v, std::size_t n) {
  const auto& b = j.get_binary();
  if (b.size() != 8 * n)
    throw std::runtime_error(std::to_string(b.size()) + " bytes for " + std::to_string(n) + " doubles");
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t w = 0;
    for (std::size_t k = 0; k < 8; ++k) w |= static_cast<std::uint64_t>(b[8 * i + k]) << (8 * k);
    v[i] = std::bit_cast<double>(w);
  }
}

/// `decode(json)` of the value in `bytes`. \throws ComputeError "<what>: corrupt result bytes (…)" when
/// the bytes are not CBOR or `decode` fails (nlohmann::json errors or std::runtime_error).
template <class Decode>
auto decodeCborBytes(const std::string& bytes, const char* what, Decode decode) {
  try {
    return decode(nlohmann::json::from_cbor(bytes));
  } catch (const nlohmann::json::exception& e) {
    throw ComputeError(std::string(what) + ": corrupt result bytes (" + e.what() + ")");
  } catch (const ComputeError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw ComputeError(std::string(what) + ": corrupt result bytes (" + e.what() + ")");
  }
}

}  // namespace whirl

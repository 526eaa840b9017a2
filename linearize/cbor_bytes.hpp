#pragma once
/// \file
/// The envelope of the results that travel between MPI ranks as bytes (export points, Campbell
/// points): a JSON value written as CBOR, so doubles keep their 8 bytes, and read back with every
/// failure — malformed CBOR, a missing key, a wrong type, a size that does not match — reported as
/// one ComputeError naming what was being decoded.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "src/base/error.hpp"

namespace whirl {

/// CBOR bytes of `j`.
inline std::string cborBytes(const nlohmann::json& j) {
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(j);
  return std::string(bytes.begin(), bytes.end());
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

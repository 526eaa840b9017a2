#pragma once
/// \file
/// Errors reported to the user. Every message names where (file, line, key or field) and why,
/// so the command line can print it as one line and exit non-zero.
#include <stdexcept>
#include <string>

namespace whirl {

/// Bad user input: a file that is missing, malformed or truncated, an unknown key, a value out of range.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A computation that cannot deliver a valid result (no convergence, singular matrix, not an equilibrium).
class ComputeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "file:line: key: reason" with the empty parts left out; control characters written as escapes (\n).
std::string where(const std::string& file, int line, const std::string& key, const std::string& reason);

/// Where a value came from, for messages.
struct Where {
  std::string file;
  int line = 0;      ///< 1-based, 0 = unknown
  std::string key;   ///< dotted path or column name
  std::string note;  ///< appended to the reason, e.g. " (value from --set k=v)"
  /// \throws InputError "file:line: key: reason note".
  [[noreturn]] void fail(const std::string& reason) const;
};

}  // namespace whirl

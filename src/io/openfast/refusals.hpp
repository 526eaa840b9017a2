#pragma once
/// \file
/// Options of an OpenFAST input whirl cannot model are refused, all at once and each with its place:
/// "file:line: key: <raw value> not supported by whirl (<reason>)", joined with "; ".
#include <string>
#include <vector>

#include "src/base/error.hpp"
#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

class Refusals {
 public:
  explicit Refusals(const OpenFastFile& f) : f_(f) {}
  /// Adds "file:line: key: <raw value> not supported by whirl (reason)" when `refused`.
  void addIf(bool refused, const std::string& key, const std::string& reason) {
    if (!refused) return;
    const OpenFastEntry* e = f_.find(key);
    const std::string value = e ? e->raw : "?";
    out_.push_back(f_.where(key, value + " not supported by whirl (" + reason + ")"));
  }
  /// The same with the reason "<what>; whirl supports only <supported>".
  void addIf(bool refused, const std::string& key, const std::string& what, const std::string& supported) {
    addIf(refused, key, what + "; whirl supports only " + supported);
  }
  std::vector<std::string> take() { return std::move(out_); }

 private:
  const OpenFastFile& f_;
  std::vector<std::string> out_;
};

/// Throws InputError with every message, "; "-separated, when there is any.
inline void throwIfAny(const std::vector<std::string>& issues) {
  if (issues.empty()) return;
  std::string msg;
  for (const std::string& s : issues) msg += (msg.empty() ? "" : "; ") + s;
  throw InputError(msg);
}

}  // namespace whirl::io

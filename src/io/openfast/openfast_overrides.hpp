#pragma once
/// \file
/// `--set KEY=VALUE` overrides of values in OpenFAST input files.
///
/// An override replaces the value of a key wherever a reader meets that key: a run reads several files
/// (.fst, ElastoDyn, tower, blade, ServoDyn), and `--set NacMass=250000` or `--set TwFAM1Sh(2)=0.71`
/// should not need to say which. A key that no file read contains is an error ("unknown key"), checked
/// once all files are read by `requireAllUsed`.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/io/openfast/openfast_input.hpp"

namespace whirl::io {

/// One override, e.g. {"NacMass", "250000"}.
struct KeyOverride {
  std::string key;
  std::string value;
};

/// Parses "KEY=VALUE". Throws InputError("--set 'text': reason") when '=' is missing or a side is empty.
KeyOverride parseOverride(std::string_view text);

/// Overrides to apply to every file read, with a record of which ones some file used.
class OverrideSet {
 public:
  OverrideSet() = default;
  explicit OverrideSet(std::vector<KeyOverride> overrides);

  /// Sets each override whose key `file` contains; remembers the file name for messages.
  void applyTo(OpenFastFile& file);

  /// The value given for `key` (case-insensitive) in a file read by its own parser (ROSCO's DISCON.IN),
  /// marking it used and remembering `file` for messages; nullopt when no override names the key.
  std::optional<std::string> take(const std::string& key, const std::string& file);

  /// Throws InputError("key: unknown key (not in any file read: a.fst, b.dat)") for the first override
  /// that no file contained.
  void requireAllUsed() const;

  bool empty() const { return overrides_.empty(); }

 private:
  std::vector<KeyOverride> overrides_;
  std::vector<bool> used_;
  std::vector<std::string> files_;
};

}  // namespace whirl::io

#include "src/io/openfast/openfast_overrides.hpp"

#include <algorithm>
#include <cctype>

#include "src/base/error.hpp"

namespace whirl::io {

KeyOverride parseOverride(std::string_view text) {
  const std::size_t eq = text.find('=');
  auto bad = [&](const char* reason) { return InputError("--set '" + std::string(text) + "': " + reason); };
  if (eq == std::string_view::npos) throw bad("expected KEY=VALUE");
  auto strip = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return std::string(s);
  };
  KeyOverride o{strip(text.substr(0, eq)), strip(text.substr(eq + 1))};
  if (o.key.empty()) throw bad("empty key");
  if (o.value.empty()) throw bad("empty value");
  return o;
}

OverrideSet::OverrideSet(std::vector<KeyOverride> overrides)
    : overrides_(std::move(overrides)), used_(overrides_.size(), false) {}

void OverrideSet::applyTo(OpenFastFile& file) {
  const std::string name = file.path().string();
  if (std::find(files_.begin(), files_.end(), name) == files_.end()) files_.push_back(name);
  for (std::size_t i = 0; i < overrides_.size(); ++i) {
    if (!file.has(overrides_[i].key)) continue;
    file.setValue(overrides_[i].key, overrides_[i].value);
    used_[i] = true;
  }
}

std::optional<std::string> OverrideSet::take(const std::string& key, const std::string& file) {
  if (std::find(files_.begin(), files_.end(), file) == files_.end()) files_.push_back(file);
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  std::optional<std::string> value;
  for (std::size_t i = 0; i < overrides_.size(); ++i)
    if (lower(overrides_[i].key) == lower(key)) {
      value = overrides_[i].value;  // the last one given wins, as in applyTo
      used_[i] = true;
    }
  return value;
}

void OverrideSet::requireAllUsed() const {
  const auto it = std::find(used_.begin(), used_.end(), false);
  if (it == used_.end()) return;
  std::string list;
  for (const std::string& f : files_) list += (list.empty() ? "" : ", ") + f;
  const KeyOverride& o = overrides_[static_cast<std::size_t>(it - used_.begin())];
  throw InputError(where("", 0, o.key, "unknown key (not in any file read: " + (list.empty() ? "none" : list) + ")"));
}

}  // namespace whirl::io

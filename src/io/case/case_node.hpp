#pragma once
/// \file
/// Checked access to a parsed YAML case: every value knows its file, 1-based line and dotted key
/// path, so that any complaint about it becomes one InputError line "file:line: key: reason".
/// Maps are read after allowKeys() (unknown and duplicate keys are errors), scalars through
/// number()/integer()/boolean()/text(), which refuse the wrong type and non-finite numbers.
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "src/base/error.hpp"
#include "src/base/types.hpp"

namespace whirl {

/// The file a case came from and the overrides applied to it (for messages).
struct CaseSource {
  std::string file;    ///< the case file as given to readCase
  std::string folder;  ///< its folder: relative paths inside the case start here
  struct Set {
    std::string path;  ///< canonical dotted path of the value that was set
    std::string text;  ///< "key=value" as given
    int line = 0;      ///< line of the value (or of its closest existing parent) in the file
  };
  std::vector<Set> sets;
  bool allow_outside_files = false;  ///< `file:` entries may name files outside the case folder
  /// The file a path inside the case names, relative to the case folder unless absolute.
  std::string resolve(const std::string& relative) const;
  /// Empty when `resolved` (from resolve) may be read, else the reason: outside the case folder
  /// (absolute, or `..`/a symbolic link leading out) while allow_outside_files is false.
  std::string outsideReason(const std::string& resolved) const;
};

/// A number for messages, shortest form ("2.4e+05", "80").
std::string num(double v);

/// Path of a map value: "parent.key" (or "key" at the top).
std::string mapChildPath(const std::string& parent, const std::string& key);
/// Path of a list entry: "parent.<name>" when the entry is a map with a `name`, else "parent[i]".
std::string listChildPath(const std::string& parent, const YAML::Node& item, size_t index);

struct MapEntry;

class CaseNode {
 public:
  /// The document root.
  CaseNode(YAML::Node node, const CaseSource& source);

  const YAML::Node& yaml() const { return node_; }
  const std::string& path() const { return path_; }
  int line() const { return line_; }
  const CaseSource& source() const { return *source_; }
  Where where() const;
  /// \throws InputError at this value.
  [[noreturn]] void fail(const std::string& reason) const;

  bool isMap() const { return node_.IsMap(); }
  bool isList() const { return node_.IsSequence(); }
  bool isScalar() const { return node_.IsScalar(); }
  bool isNull() const { return !node_.IsDefined() || node_.IsNull(); }

  /// Fails unless this is a map whose keys are all in `allowed` (the message lists them) and unique.
  void allowKeys(std::initializer_list<std::string_view> allowed) const;
  void allowKeys(const std::vector<std::string>& allowed) const;
  bool has(std::string_view key) const;
  /// The value at `key` (required: fails when missing).
  CaseNode at(std::string_view key) const;
  std::optional<CaseNode> find(std::string_view key) const;
  /// Keys and values in the order written (a map; duplicate keys fail).
  std::vector<MapEntry> entries() const;
  /// Entries of a list (fails if not a list; an empty value is an empty list).
  std::vector<CaseNode> items() const;

  double number() const;  ///< a finite number
  int integer() const;
  bool boolean() const;  ///< true or false
  /// Text on one printable line (names, units, file names): fails on a control character.
  std::string text() const;
  /// Text that may span lines (a description, never written into generated files).
  std::string freeText() const;
  std::vector<double> numbers() const;  ///< a list of finite numbers
  Vec3 vec3() const;
  /// rows × cols matrix written as a list of rows.
  MatX matrix(int rows, int cols) const;

  // Optional keys with a default.
  double number(std::string_view key, double fallback) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string text(std::string_view key, const std::string& fallback) const;
  Vec3 vec3(std::string_view key, const Vec3& fallback) const;

 private:
  CaseNode(YAML::Node node, std::string path, int fallback_line, const CaseSource* source);
  CaseNode child(const YAML::Node& node, std::string path) const;
  const CaseSource::Set* setBy() const;

  YAML::Node node_;
  std::string path_;
  int line_ = 0;
  const CaseSource* source_ = nullptr;
};

/// One key of a map with its value.
struct MapEntry {
  std::string key;
  Where key_where;  ///< where the key is written
  CaseNode value;
};

}  // namespace whirl

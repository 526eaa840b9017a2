#pragma once
/// \file
/// Several output files that appear together or not at all: each is written to a temporary file in
/// its target folder, and only when all are written are they renamed into place. If anything fails
/// before commit(), the destructor removes the temporaries (no half-written output).
#include <string>
#include <utility>
#include <vector>

namespace whirl {

class StagedFiles {
 public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();

  /// Registers `path` and returns the temporary path to write it to (the folder must exist).
  std::string stage(const std::string& path);
  /// Stages `path` and writes `content` to its temporary file; InputError naming it on failure.
  void write(const std::string& path, const std::string& content);
  /// Renames every temporary into place; InputError naming the file when a rename fails.
  void commit();
  /// The final paths, in the order staged.
  std::vector<std::string> paths() const;

 private:
  std::vector<std::pair<std::string, std::string>> files_;  ///< (target, temporary)
  bool committed_ = false;
};

}  // namespace whirl

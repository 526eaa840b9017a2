#include "src/io/staged_files.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/model/error.hpp"

namespace whirl {

namespace fs = std::filesystem;

StagedFiles::~StagedFiles() {
  if (committed_) return;
  for (const auto& [target, tmp] : files_) std::remove(tmp.c_str());
}

std::string StagedFiles::stage(const std::string& path) {
  const fs::path p(path);
  const std::string tmp =
      (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
  files_.emplace_back(path, tmp);
  return tmp;
}

void StagedFiles::write(const std::string& path, const std::string& content) {
  const std::string tmp = stage(path);
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
  out << content;
  out.flush();
  if (!out) throw InputError(path + ": write failed (disk full?)");
}

void StagedFiles::commit() {
  for (const auto& [target, tmp] : files_) {
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) throw InputError(target + ": cannot rename the temporary file into place (" + ec.message() + ")");
  }
  committed_ = true;
}

std::vector<std::string> StagedFiles::paths() const {
  std::vector<std::string> p;
  for (const auto& f : files_) p.push_back(f.first);
  return p;
}

}  // namespace whirl

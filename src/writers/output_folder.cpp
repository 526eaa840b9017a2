// prepareOutputFolder: completes or removes what a killed whirl left in and next to an output
// folder, and the shared helpers of output sets (journal roll-forward, folder lock, fsync).
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <vector>

#include "src/writers/atomic_file.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/output_set_internal.hpp"
#include "src/model/error.hpp"

namespace whirl {
namespace output {

std::string withErrno(const std::string& message, int err) { return message + " (" + std::strerror(err) + ")"; }

long pidAfter(const std::string& file, const std::string& prefix) {
  if (file.size() <= prefix.size() || file.size() > prefix.size() + 9 || file.compare(0, prefix.size(), prefix) != 0)
    return -1;
  long pid = 0;
  for (size_t i = prefix.size(); i < file.size(); ++i) {
    if (file[i] < '0' || file[i] > '9') return -1;
    pid = 10 * pid + (file[i] - '0');
  }
  return pid;
}

bool processGone(long pid) { return pid <= 0 || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH); }

void syncPath(const fs::path& p, const std::string& shown) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(withErrno(shown + ": cannot open to flush it to disk", errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw InputError(withErrno(shown + ": cannot flush to disk", err));
}

FolderLock::FolderLock(const fs::path& folder) {
  fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ >= 0)
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

void rollForward(const fs::path& staging, const fs::path& dir, const std::string& shown) {
  std::ifstream journal(staging / kJournal);
  for (std::string name; std::getline(journal, name);) {
    if (name.empty() || name.find('/') != std::string::npos) continue;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(staging / name, ec))) continue;  // moved before the kill
    if (::rename((staging / name).c_str(), (dir / name).c_str()) != 0)
      throw InputError(withErrno((fs::path(shown) / name).string() + ": cannot move the new file into place", errno) +
                       "; the next whirl run writing to " + shown + " completes the set from " + staging.string());
  }
  syncPath(dir, shown);
}

namespace {

// A killed run's staging folder: completed when its journal was written (the set was committed),
// removed otherwise. A roll-forward that fails again is left for later with a warning.
void recover(const fs::path& staging, const fs::path& dir, const std::string& shown, long pid) {
  std::error_code ec;
  if (fs::exists(staging / kJournal, ec)) {
    try {
      rollForward(staging, dir, shown);
      std::cerr << "whirl: note: " << shown << ": completed the output of an interrupted run (process " << pid << ")"
                << std::endl;
    } catch (const InputError& e) {
      std::cerr << "whirl: warning: " << e.what() << std::endl;
      return;
    }
  }
  fs::remove_all(staging, ec);
}

// `name.tmp<pid>` (writeFileAtomic, Gnuplot images) and `.name.tmp<pid>` (whirl before output sets).
long tmpPid(const std::string& file) {
  const size_t at = file.rfind(".tmp");
  return at == std::string::npos || at == 0 ? -1 : pidAfter(file.substr(at), ".tmp");
}

}  // namespace
}  // namespace output

void prepareOutputFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  ensureWritableFolder(dir);
  std::error_code ec;
  const fs::path abs = fs::canonical(dir.empty() ? "." : dir, ec);
  if (ec) throw InputError(dir + ": cannot resolve the output folder (" + ec.message() + ")");
  const std::string shown = dir.empty() ? "." : dir;
  const fs::path parent = abs.parent_path();
  const std::string name = abs.filename().string();
  output::FolderLock lock(parent);
  if (!name.empty()) {
    const std::string prefix = "." + name + output::kStagingTag;
    std::vector<fs::directory_entry> entries;  // listed first: removing while iterating may skip some
    for (const auto& e : fs::directory_iterator(parent, ec)) entries.push_back(e);
    for (const auto& e : entries) {
      const long pid = output::pidAfter(e.path().filename().string(), prefix);
      if (pid > 0 && e.is_directory(ec) && output::processGone(pid)) output::recover(e.path(), abs, shown, pid);
    }
  }
  std::vector<fs::directory_entry> entries;
  for (const auto& e : fs::directory_iterator(abs, ec)) entries.push_back(e);
  for (const auto& e : entries) {
    const std::string file = e.path().filename().string();
    const bool is_dir = e.is_directory(ec) && !e.is_symlink(ec);
    if (const long pid = output::pidAfter(file, output::kStagingTag); pid > 0 && is_dir) {
      if (output::processGone(pid)) output::recover(e.path(), abs, shown, pid);
    } else if (const long tmp = output::tmpPid(file); tmp > 0 && e.is_regular_file(ec) && !e.is_symlink(ec)) {
      if (output::processGone(tmp)) fs::remove(e.path(), ec);
    }
  }
}

}  // namespace whirl

// prepareOutputFolder: completes or removes what a killed whirl left in and next to an output
// folder, and the shared helpers of output sets (journal roll-forward, folder lock, fsync).
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "src/base/error.hpp"
#include "src/writers/atomic_file.hpp"
#include "src/writers/output_set.hpp"
#include "src/writers/output_set_internal.hpp"

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

long stagingPid(const std::string& file, const std::string& prefix) {
  constexpr size_t kRandom = 6;  // mkdtemp's XXXXXX
  const size_t dash = file.size() > kRandom ? file.size() - kRandom - 1 : 0;
  if (dash <= prefix.size() || file[dash] != '-') return -1;
  for (size_t i = dash + 1; i < file.size(); ++i)
    if (!std::isalnum(static_cast<unsigned char>(file[i]))) return -1;
  return pidAfter(file.substr(0, dash), prefix);
}

bool writeMarker(const fs::path& staging) {
  const std::string name = staging.filename().string();
  const int fd = ::open((staging / kMarker).c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  const bool ok = ::write(fd, name.data(), name.size()) == static_cast<ssize_t>(name.size());
  return ::close(fd) == 0 && ok;
}

fs::path makeStaging(const fs::path& folder, const std::string& prefix) {
  std::string tmpl = (folder / (prefix + std::to_string(::getpid()) + "-XXXXXX")).string();
  if (::mkdtemp(tmpl.data()) == nullptr) return {};
  if (!writeMarker(tmpl)) {
    const int err = errno;
    std::error_code ec;
    fs::remove_all(tmpl, ec);
    errno = err;
    return {};
  }
  return tmpl;
}

namespace {

/// True when `p` is, without following a symbolic link, of type `type` (S_IFDIR, S_IFREG) and
/// owned by the effective user; `st` receives its status.
bool ownedEntry(const fs::path& p, mode_t type, struct stat& st) {
  return ::lstat(p.c_str(), &st) == 0 && (st.st_mode & S_IFMT) == type && st.st_uid == ::geteuid();
}

}  // namespace

bool trustedStaging(const fs::path& staging) {
  struct stat st {};
  if (!ownedEntry(staging, S_IFDIR, st) || (st.st_mode & 077) != 0) return false;
  if (!ownedEntry(staging / kMarker, S_IFREG, st) || st.st_size > 4096) return false;
  std::ifstream in(staging / kMarker, std::ios::binary);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return content == staging.filename().string();
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
  struct stat st {};
  if (!ownedEntry(staging / kJournal, S_IFREG, st)) return;  // not this user's journal (a link, a planted file)
  std::ifstream journal(staging / kJournal);
  for (std::string name; std::getline(journal, name);) {
    if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..") continue;
    if (!ownedEntry(staging / name, S_IFREG, st)) continue;  // moved before the kill, or not a file whirl wrote
    if (::rename((staging / name).c_str(), (dir / name).c_str()) != 0)
      throw InputError(withErrno((fs::path(shown) / name).string() + ": cannot move the new file into place", errno) +
                       "; the next whirl run writing to " + shown + " completes the set from " + staging.string());
  }
  syncPath(dir, shown);
}

namespace {

// A killed run's staging folder: completed when its journal was written (the set was committed),
// removed otherwise. A roll-forward that fails again is left for later with a warning. Only folders
// this user owns are touched, and only a trusted one (trustedStaging: mode 0700, whirl's marker) is
// ever merged: a folder planted beside the output by someone who can write the parent folder stays
// where it is, unread (issue 48, item 2). A folder this user owns but without the marker is what a
// kill leaves between the swap of commit() and the removal of the old tree: removed.
void recover(const fs::path& staging, const fs::path& dir, const std::string& shown, long pid) {
  std::error_code ec;
  struct stat st {};
  if (!ownedEntry(staging, S_IFDIR, st)) return;
  if (fs::exists(fs::symlink_status(staging / kJournal, ec))) {
    if (!trustedStaging(staging)) {
      std::cerr << "whirl: warning: " << staging.string()
                << ": not completed into the output folder: not a staging folder this user's whirl created "
                   "(owner, mode or marker differ); left as it is"
                << std::endl;
      return;
    }
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
      const long pid = output::stagingPid(e.path().filename().string(), prefix);
      if (pid > 0 && output::processGone(pid)) output::recover(e.path(), abs, shown, pid);
    }
  }
  // Inside the folder only whirl's staging folders; files are never removed by their name alone
  // (a user's `data.tmp999999` is theirs: whirl's temporary files live in its staging folders).
  std::vector<fs::directory_entry> entries;
  for (const auto& e : fs::directory_iterator(abs, ec)) entries.push_back(e);
  for (const auto& e : entries) {
    const long pid = output::stagingPid(e.path().filename().string(), output::kStagingTag);
    if (pid > 0 && output::processGone(pid)) output::recover(e.path(), abs, shown, pid);
  }
}

}  // namespace whirl

// OutputSet: a command's files staged beside the output folder, then swapped in with the folder
// (renameat2 RENAME_EXCHANGE), or rolled forward from a journal where no swap is possible.
#include "src/writers/output_set.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "src/base/error.hpp"
#include "src/writers/output_set_internal.hpp"

namespace whirl {
namespace {

namespace fs = std::filesystem;
using output::withErrno;

// Folders with more entries than this are rolled forward instead of mirrored with hard links.
constexpr int kMaxMirrored = 20000;

bool sameDevice(const fs::path& a, const fs::path& b) {
  struct stat sa {
  }, sb{};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev;
}

// True when the working directory is `dir` or inside it: swapping `dir` would leave this process
// (and the shell that started it) in the removed old folder.
bool holdsWorkingDirectory(const fs::path& dir) {
  std::error_code ec;
  const fs::path cwd = fs::canonical(fs::current_path(ec), ec);
  if (ec) return true;
  auto d = dir.begin(), c = cwd.begin();
  for (; d != dir.end() && c != cwd.end(); ++d, ++c)
    if (*d != *c) return false;
  return d == dir.end();
}

void writeAll(const std::string& path, const std::string& content, const std::string& shown) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError(withErrno(shown + ": cannot write", errno));
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw InputError(withErrno(shown + ": write failed", err));
    }
    done += static_cast<size_t>(n);
  }
  // Start writing it to disk now, so that the fsync of commit() mostly finds it done (936 .lin
  // files one fsync after the other otherwise wait for each in turn).
  ::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
  if (::close(fd) != 0) throw InputError(withErrno(shown + ": write failed", errno));
}

// Recreates `src` at `dst` without copying data: files hard-linked, symbolic links re-made, folders
// rebuilt (their mode kept). False when some entry cannot be (another file type, a link refused).
bool mirror(const fs::path& src, const fs::path& dst, int& budget) {
  if (--budget < 0) return false;
  struct stat st {};
  if (::lstat(src.c_str(), &st) != 0) return false;
  if (S_ISREG(st.st_mode)) return ::link(src.c_str(), dst.c_str()) == 0;
  if (S_ISLNK(st.st_mode)) {
    std::error_code ec;
    const fs::path target = fs::read_symlink(src, ec);
    if (!ec) fs::create_symlink(target, dst, ec);
    return !ec;
  }
  if (!S_ISDIR(st.st_mode) || ::mkdir(dst.c_str(), 0700) != 0) return false;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(src, ec))
    if (!mirror(e.path(), dst / e.path().filename(), budget)) return false;
  if (ec || ::chmod(dst.c_str(), st.st_mode & 07777) != 0) return false;
  if (::geteuid() == 0 && ::chown(dst.c_str(), st.st_uid, st.st_gid) != 0) return false;
  return true;
}

// The new folder: the staged files plus every other entry of `dir`, with `dir`'s mode and owner.
bool mirrorOthers(const fs::path& dir, const fs::path& staging, const std::set<std::string>& names) {
  int budget = kMaxMirrored;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (!names.count(e.path().filename().string()) && !mirror(e.path(), staging / e.path().filename(), budget))
      return false;
  struct stat st {};
  if (ec || ::stat(dir.c_str(), &st) != 0 || ::chmod(staging.c_str(), st.st_mode & 07777) != 0) return false;
  return ::geteuid() != 0 || ::chown(staging.c_str(), st.st_uid, st.st_gid) == 0;
}

}  // namespace

OutputSet::OutputSet(std::string dir) : dir_(std::move(dir)) {}

OutputSet::~OutputSet() {
  if (staging_.empty() || keep_staging_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);  // uncommitted: the new files; committed by swap: the old tree
}

std::string OutputSet::stagingFolder() {
  if (!staging_.empty()) return staging_;
  const std::string shown = dir_.empty() ? "." : dir_;
  std::error_code ec;
  const fs::path abs = fs::canonical(shown, ec);
  if (ec) throw InputError(shown + ": cannot resolve the output folder (" + ec.message() + ")");
  const fs::path parent = abs.parent_path(), name = abs.filename();
  fs::path staging;
  if (!name.empty() && ::access(parent.c_str(), W_OK) == 0 && sameDevice(parent, abs) && !holdsWorkingDirectory(abs)) {
    staging = output::makeStaging(parent, "." + name.string() + output::kStagingTag);
    swap_ = !staging.empty();
  }
  if (!swap_) {
    staging = output::makeStaging(abs, output::kStagingTag);
    if (staging.empty()) throw InputError(withErrno(shown + ": cannot create a staging folder", errno));
  }
  staging_ = staging.string();
  return staging_;
}

std::string OutputSet::stage(const std::string& name) {
  if (name.empty() || name.find('/') != std::string::npos || name.rfind(output::kStagingTag, 0) == 0)
    throw std::invalid_argument("OutputSet::stage: not a plain output file name: " + name);
  if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(name);
  return (fs::path(stagingFolder()) / name).string();
}

void OutputSet::write(const std::string& name, const std::string& content) {
  const std::string path = stage(name);
  writeAll(path, content, (fs::path(dir_.empty() ? "." : dir_) / name).string());
}

std::vector<std::string> OutputSet::paths() const {
  std::vector<std::string> p;
  for (const auto& n : names_) p.push_back((fs::path(dir_.empty() ? "." : dir_) / n).string());
  return p;
}

void OutputSet::commit() {
  if (committed_) return;
  const std::string shown = dir_.empty() ? "." : dir_;
  const fs::path staging(stagingFolder());
  std::error_code ec;
  const fs::path abs = fs::canonical(shown, ec);
  if (ec) throw InputError(shown + ": cannot resolve the output folder (" + ec.message() + ")");

  // The set: the staged files, then what a program run in the staging folder added (images).
  std::vector<std::string> extra;
  for (const auto& e : fs::directory_iterator(staging, ec)) {
    const std::string n = e.path().filename().string();
    if (n.rfind(output::kStagingTag, 0) == 0) continue;  // whirl's own: the marker
    if (std::find(names_.begin(), names_.end(), n) == names_.end()) extra.push_back(n);
  }
  std::sort(extra.begin(), extra.end());
  names_.insert(names_.end(), extra.begin(), extra.end());
  const std::set<std::string> names(names_.begin(), names_.end());
  for (const auto& n : names_) {
    const std::string target = (fs::path(shown) / n).string();
    if (!fs::is_regular_file(fs::symlink_status(staging / n, ec)))
      throw InputError(target + ": the output file was not written; the previous results are unchanged");
    output::syncPath(staging / n, target);
  }
  output::syncPath(staging, shown);

  output::FolderLock lock(abs.parent_path());  // one commit at a time: another's files are mirrored, never lost
  for (const auto& n : names_) {
    const fs::path target = abs / n;
    if (fs::is_directory(fs::symlink_status(target, ec)))
      throw InputError((fs::path(shown) / n).string() +
                       ": is a folder, so the output file of that name cannot replace it; nothing was written, the "
                       "previous results are unchanged");
  }
  // The marker stays behind: after the swap the folder is the output folder. Restored (with mode
  // 0700) when the swap fails and the set rolls forward from this folder.
  const fs::path marker = staging / output::kMarker;
  if (swap_ && mirrorOthers(abs, staging, names) && ::unlink(marker.c_str()) == 0 &&
      ::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, abs.c_str(), RENAME_EXCHANGE) == 0) {
    committed_ = true;
    try {
      output::syncPath(abs.parent_path(), abs.parent_path().string());  // the swap itself on disk
    } catch (const InputError&) {  // visible already; the next sync of the file system writes it
    }
    fs::remove_all(staging, ec);  // the old tree, now under the staging name
    return;
  }

  // Roll forward: the journal makes the set committed; a kill from here on is completed by the next run,
  // which trusts only a folder of mode 0700 with whirl's marker (output::trustedStaging).
  if (::chmod(staging.c_str(), 0700) != 0 ||
      (!fs::exists(fs::symlink_status(marker, ec)) && !output::writeMarker(staging)))
    throw InputError(withErrno(shown + ": cannot prepare the commit of the output files", errno));
  const fs::path journal = staging / output::kJournal, draft = staging / (std::string(output::kJournal) + ".tmp");
  std::string list;
  for (const auto& n : names_) list += n + "\n";
  writeAll(draft.string(), list, shown);
  output::syncPath(draft, shown);
  if (::rename(draft.c_str(), journal.c_str()) != 0)
    throw InputError(withErrno(shown + ": cannot commit the output files", errno));
  output::syncPath(staging, shown);
  keep_staging_ = true;  // from here the journal must survive a failure: the next run completes it
  output::rollForward(staging, abs, shown);
  committed_ = true;
  keep_staging_ = false;
}

}  // namespace whirl

#pragma once
/// \file
/// Pieces shared by OutputSet::commit() and prepareOutputFolder() (src/writers/output_set.hpp): whirl's
/// names for staging folders, the roll-forward journal, the folder lock, fsync.
#include <filesystem>
#include <string>

namespace whirl::output {

namespace fs = std::filesystem;

/// File in a staging folder listing the set's file names, one a line: present = committed.
inline constexpr const char* kJournal = ".whirl-commit";
/// Staging folders: `.whirl-<pid>-XXXXXX` inside the output folder, `.<name>.whirl-<pid>-XXXXXX`
/// beside it, the last six characters chosen by mkdtemp (unguessable, created mode 0700).
inline constexpr const char* kStagingTag = ".whirl-";
/// File in a staging folder that whirl writes when it creates the folder, holding the folder's own
/// name: with the owner and mode, what makes a folder one this user's whirl created (trustedStaging).
inline constexpr const char* kMarker = ".whirl-staging";

/// Creates a staging folder `<folder>/<prefix><pid>-XXXXXX` with mkdtemp (mode 0700, this user's)
/// and its marker; the path, or empty with errno set when it cannot.
fs::path makeStaging(const fs::path& folder, const std::string& prefix);

/// Writes the marker of `staging` (kMarker); false when it cannot.
bool writeMarker(const fs::path& staging);

/// The process id in a staging folder's name `<prefix><digits>-XXXXXX` (prefix matched exactly,
/// six letters or digits after the dash), else −1.
long stagingPid(const std::string& file, const std::string& prefix);

/// True when `staging` is a folder this user's whirl created: not a symbolic link, a folder owned
/// by the effective user with no permission for group or others, holding a regular marker file of
/// the same owner whose content is the folder's name. A folder anyone else could have made (in a
/// shared parent folder) is never read, merged or removed.
bool trustedStaging(const fs::path& staging);

/// "message (reason)" of the last errno.
std::string withErrno(const std::string& message, int err);

/// The process id in `file` when it is `<prefix><digits>` (prefix matched exactly), else −1.
long pidAfter(const std::string& file, const std::string& prefix);

/// True when no process has id `pid` (kill(pid, 0) gives ESRCH).
bool processGone(long pid);

/// fsync of a file or folder; throws InputError naming `shown` when it fails.
void syncPath(const fs::path& p, const std::string& shown);

/// Exclusive flock on a folder for the lifetime of the object; no lock when the folder cannot be
/// opened (no read permission): commits are then not serialized against each other.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& folder);
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock();

 private:
  int fd_ = -1;
};

/// Moves every file the journal of `staging` lists, when still there, into `dir`, then fsyncs
/// `dir`. Idempotent, so a killed roll-forward is completed by running it again. InputError naming
/// `shown/<name>` when a rename fails.
void rollForward(const fs::path& staging, const fs::path& dir, const std::string& shown);

}  // namespace whirl::output

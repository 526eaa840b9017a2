#pragma once
/// \file
/// The files one command writes into its output folder appear together or not at all, even when
/// the process is killed (SIGKILL, power loss after the data reached the disk) at any instant.
///
/// How: the files are written into a staging folder next to the output folder (`.NAME.whirl-<pid>`
/// beside `DIR`), each fsync'ed. commit() then, holding an exclusive lock (flock) on the parent
/// folder, adds hard links of every other entry of `DIR` (other commands' results, anything the user
/// put there; subfolders recreated with their files linked) and swaps the staging folder with `DIR`
/// in one `renameat2(RENAME_EXCHANGE)` (Linux ≥ 3.15). A reader sees the old folder or the new one,
/// never a mixture; the old tree, now under the staging name, is removed.
///
/// Where the swap cannot be done — the parent folder is not writable, `DIR` is a mount point or
/// the current working directory (or holds it), the file system has no RENAME_EXCHANGE, an entry
/// cannot be hard-linked — the staging folder is `DIR/.whirl-<pid>` and commit() rolls forward: it
/// writes the list of the set's files (`.whirl-commit`, fsync'ed) into the staging folder, then
/// renames the files into place one by one. A kill during those renames leaves a mixture that the
/// next whirl command writing into `DIR` completes first (prepareOutputFolder()).
///
/// Stale temporaries (a killed run's staging folders, `*.tmp<pid>` files of earlier whirl
/// versions) are recognised by whirl's naming and a process id that no longer runs.
#include <string>
#include <vector>

namespace whirl {

/// Makes `dir` ready for a command's output: creates it with its parents, checks it is writable,
/// completes a commit that a killed whirl left half done, and removes stale whirl temporaries in
/// and next to it. Throws InputError naming the folder when it cannot be created or written.
void prepareOutputFolder(const std::string& dir);

/// One command's output files, committed together. Not copyable. Destroyed uncommitted (an
/// exception on the way), it removes its staging folder: the previous results stay as they were.
class OutputSet {
 public:
  /// A set for the folder `dir` (call prepareOutputFolder(dir) first). Nothing happens on disk
  /// until a file is staged.
  explicit OutputSet(std::string dir);
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();

  /// Registers the file `name` (no folder part) and returns the path to write it to.
  std::string stage(const std::string& name);
  /// Stages `name` and writes `content` to it; InputError naming `dir/name` and the reason on failure.
  void write(const std::string& name, const std::string& content);
  /// The staging folder, created when missing: a program run there (Gnuplot) may add files, which
  /// become part of the set.
  std::string stagingFolder();
  /// Makes the set visible in the output folder at once. InputError naming the path and reason when
  /// it cannot (the previous results are then unchanged), e.g. when an entry of the folder with an
  /// output file's name is a folder.
  void commit();
  /// `dir/name` of every file of the set: the staged ones in order, then the others found in the
  /// staging folder at commit, sorted.
  std::vector<std::string> paths() const;

 private:
  std::string dir_;                 ///< as given (messages, paths())
  std::string staging_;             ///< empty until the first file is staged
  bool swap_ = false;               ///< staging next to the folder, committed by exchange
  std::vector<std::string> names_;  ///< the set's file names, in order
  bool committed_ = false;
  bool keep_staging_ = false;  ///< a roll-forward was left to the next run: its journal must stay
};

}  // namespace whirl

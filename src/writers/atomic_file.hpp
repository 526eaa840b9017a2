#pragma once
/// \file
/// Output files appear whole or not at all: content goes to a temporary file in the same folder,
/// flushed to disk and renamed over the target (rename is atomic on POSIX within one file system).
/// One file only: a command's several files go through OutputSet (src/writers/output_set.hpp).
#include <string>

namespace whirl {

/// Writes `content` to `path` atomically; creates missing parent folders. Throws InputError naming
/// the path when the folder cannot be created or written.
void writeFileAtomic(const std::string& path, const std::string& content);

/// Creates the folder (and parents); InputError naming it when that fails or it is not writable.
void ensureWritableFolder(const std::string& folder);

}  // namespace whirl

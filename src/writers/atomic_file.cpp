#include "src/writers/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/base/error.hpp"

namespace whirl {

namespace fs = std::filesystem;

void ensureWritableFolder(const std::string& folder) {
  std::error_code ec;
  if (!folder.empty()) fs::create_directories(folder, ec);
  if (ec) throw InputError(folder + ": cannot create the output folder (" + ec.message() + ")");
  const std::string dir = folder.empty() ? "." : folder;
  if (::access(dir.c_str(), W_OK) != 0) throw InputError(dir + ": output folder is not writable");
}

void writeFileAtomic(const std::string& path, const std::string& content) {
  const fs::path target(path);
  ensureWritableFolder(target.parent_path().string());
  // An unguessable name of whirl's making (mkstemp: created, not opened if it exists), so no file
  // of the user's is ever overwritten or removed in its place.
  std::string tmp = (target.parent_path() / ("." + target.filename().string() + ".whirl-tmp-XXXXXX")).string();
  const int tmp_fd = ::mkstemp(tmp.data());
  if (tmp_fd < 0) throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
  const mode_t mask = ::umask(0);  // mkstemp makes 0600; the file gets the mode a plain create gives
  ::umask(mask);
  ::fchmod(tmp_fd, 0666 & ~mask);
  ::close(tmp_fd);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      std::remove(tmp.c_str());
      throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
    }
    out << content;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw InputError(path + ": write failed (disk full?)");
    }
  }
  // On disk before the rename: after a crash the name holds the old content or the new, never an empty file.
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int err = errno;
    if (fd >= 0) ::close(fd);
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot flush to disk (" + std::strerror(err) + ")");
  }
  ::close(fd);
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot rename the temporary file into place (" + ec.message() + ")");
  }
}

}  // namespace whirl

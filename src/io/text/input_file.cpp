// The common preamble of every reader: a regular file of bounded size, read in one go.
#include "src/io/text/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"

namespace whirl::io {
namespace {

/// What `mode` is, for the message refusing a file that is not a regular one.
std::string fileKind(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  return "not a file";
}

std::string megabytes(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f MB", bytes / 1e6);
  return buf;
}

[[noreturn]] void tooLarge(const std::string& path, double bytes) {
  throw InputError(where(path, 0, "",
                         "is " + (bytes > limits::kMaxInputFileBytes ? megabytes(bytes) : std::string("growing")) +
                             ", more than the " + megabytes(limits::kMaxInputFileBytes) +
                             " an input file may have (src/base/limits.hpp, kMaxInputFileBytes): not an input "
                             "whirl reads (data appended to it?)"));
}

/// Closes the descriptor on every way out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

bool readInputFile(const std::string& path, std::string& text) {
  // O_NONBLOCK: opening a FIFO without a writer would block; fstat then tells what it is.
  Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (f.fd < 0) return false;
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) return false;
  if (S_ISDIR(st.st_mode)) {
    errno = EISDIR;
    return false;
  }
  if (!S_ISREG(st.st_mode))
    throw InputError(
        where(path, 0, "", "is " + fileKind(st.st_mode) + ", not a regular file: whirl reads input only from files"));
  if (st.st_size > limits::kMaxInputFileBytes) tooLarge(path, static_cast<double>(st.st_size));
  text.assign(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t done = 0;
  for (;;) {
    if (done == text.size()) {  // the file grew since fstat: read on, within the bound
      if (text.size() >= static_cast<std::size_t>(limits::kMaxInputFileBytes)) {
        char probe;
        if (::read(f.fd, &probe, 1) > 0) tooLarge(path, static_cast<double>(text.size()) + 1);
        break;
      }
      text.resize(std::min<std::size_t>(2 * text.size() + 4096, limits::kMaxInputFileBytes));
    }
    const ssize_t n = ::read(f.fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(where(path, 0, "", std::string("cannot read (") + std::strerror(errno) + ")"));
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return true;
}

std::string tooManyRows(const std::string& file, int line) {
  return where(file, line, "",
               "more than " + std::to_string(limits::kMaxTableRows) +
                   " rows, the bound of a table (src/base/limits.hpp, kMaxTableRows): not a table whirl reads");
}

bool openInputFile(const std::string& path, std::istringstream& in) {
  std::string text;
  if (!readInputFile(path, text)) return false;
  in.str(std::move(text));
  in.clear();
  return true;
}

}  // namespace whirl::io

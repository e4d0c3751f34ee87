#include "hertzdash/io/output_lock.hpp"

#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/remove_on_signal.hpp"

#include <cerrno>
#include <fcntl.h>
#include <optional>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace hertzdash {

namespace {

std::string reason_of(int error) { return std::generic_category().message(error); }

// The process id written in the lock file `fd`, as text ("unknown" if none can be read).
std::string holder_of(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  return n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "unknown";
}

// Whether the lock file open as `fd` is still the one at `path` (a holder that ended removed
// it, and a new writer may have made another: locking the old one would lock nothing).
bool still_linked(int fd, const std::filesystem::path& path) {
  struct stat open_file {}, named {};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 && open_file.st_dev == named.st_dev &&
         open_file.st_ino == named.st_ino;
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& file) : lock_path_(sibling_path(file, ".lock")) {
  for (;;) {
    fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd_ < 0) throw std::runtime_error("cannot lock " + file.string() + ": " + lock_path_.string() + ": " + reason_of(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = holder_of(fd_);
      ::close(fd_);
      if (error == EWOULDBLOCK)
        throw OutputBusy(file.string() + " is being written by another process (PID " + holder + " holds " +
                         lock_path_.string() + ")");
      throw std::runtime_error("cannot lock " + file.string() + ": " + reason_of(error));
    }
    if (still_linked(fd_, lock_path_)) break;
    ::close(fd_);  // removed by its holder between our open and our lock: take the new one
  }
  registered_.emplace(lock_path_);
  // The process id is for a second writer's message only: the lock holds without it.
  const std::string pid = std::to_string(::getpid());
  [[maybe_unused]] const ssize_t written = ::ftruncate(fd_, 0) == 0 ? ::pwrite(fd_, pid.data(), pid.size(), 0) : -1;
}

OutputLock::~OutputLock() {
  registered_.reset();  // first: a signal from here on leaves an unheld lock file, never removes another's
  ::unlink(lock_path_.c_str());  // while still holding it: a writer that opened it meanwhile sees it unlinked and retries
  ::close(fd_);
}

}  // namespace hertzdash

#include "hertzdash/io/atomic_file.hpp"

#include "hertzdash/io/remove_on_signal.hpp"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <climits>
#include <deque>
#include <cstdio>
#include <fcntl.h>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace hertzdash {

namespace {

namespace fs = std::filesystem;

/// `what` names the path as given, and where its symbolic links led.
[[noreturn]] void fail(const std::string& what, const std::string& reason) {
  throw std::runtime_error("cannot write " + what + ": " + reason);
}

std::string reason_of(int error) { return std::generic_category().message(error); }

/// Writes all of `content` to `fd`; 0, or the errno of the failure.
int write_all(int fd, std::string_view content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

/// The descriptor N of this process that `target` (/proc/PID/fd/N, PID ours) names, else -1.
int own_descriptor(const fs::path& target) {
  const fs::path own = fs::path("/proc") / std::to_string(::getpid()) / "fd";
  if (target.parent_path() != own) return -1;
  const std::string n = target.filename().string();
  int fd = -1;
  const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), fd);
  return ec == std::errc() && end == n.data() + n.size() ? fd : -1;
}

struct Target {
  fs::path path;       // symbolic links followed, parent directory canonical
  std::string what;    // the path as given, and the link's target if one was followed
  bool write_through;  // not a regular file (or not yet existing): no temporary, no rename
};

/// Where a write to `path` lands. A path under /proc (where /dev/stdout and /dev/fd lead) names
/// an open file: it is written through whatever it is.
Target resolve(const fs::path& path) {
  fs::path p = fs::absolute(path);
  std::string what = path.string();
  for (int links = 0;; ++links) {
    if (links > 0) what = path.string() + " (-> " + p.string() + ")";
    if (links > 40) fail(what, reason_of(ELOOP));
    std::error_code ec;
    const fs::path parent = fs::canonical(p.parent_path(), ec);
    if (ec == std::errc::no_such_file_or_directory)
      fail(what, "the directory " + p.parent_path().string() + " does not exist");
    if (ec) fail(what, p.parent_path().string() + ": " + ec.message());
    p = parent / p.filename();
    if (p.native().starts_with("/proc/")) return {p, what, true};
    if (fs::symlink_status(p, ec).type() != fs::file_type::symlink) break;
    const fs::path next = fs::read_symlink(p, ec);
    if (ec) fail(what, ec.message());
    p = next.is_absolute() ? next : parent / next;
  }
  std::error_code ec;
  switch (fs::status(p, ec).type()) {
    case fs::file_type::not_found:
    case fs::file_type::regular: return {p, what, false};
    case fs::file_type::directory: fail(what, reason_of(EISDIR));
    default:
      if (ec) fail(what, ec.message());
      return {p, what, true};
  }
}

/// Every piece of `content` to `fd`: 0, or the errno of the first write that failed (the
/// pieces after it are still made, and dropped).
int write_pieces(int fd, const ContentPieces& content) {
  int error = 0;
  content([&](std::string_view piece) {
    if (error == 0) error = write_all(fd, piece);
  });
  return error;
}

void write_through(const Target& t, const ContentPieces& content) {
  if (const int fd = own_descriptor(t.path); fd >= 0) {
    std::fflush(nullptr);  // what the program printed to that descriptor comes first
    if (const int error = write_pieces(fd, content)) fail(t.what, reason_of(error));
    return;
  }
  const int fd = ::open(t.path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail(t.what, reason_of(errno));
  int error = write_pieces(fd, content);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) fail(t.what, reason_of(error));
}

std::atomic<unsigned> temporaries{0};

/// NAME.tmp.PID.N beside `target`: PID.N alone keeps the name unique.
fs::path temporary_path(const fs::path& target) {
  return sibling_path(target, ".tmp." + std::to_string(::getpid()) + "." + std::to_string(temporaries++));
}

/// Flush the directory `dir`'s entries to the disk, so that a rename in it survives a power cut.
/// Best effort: a file system that cannot sync a directory (EINVAL) has nothing to flush.
void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

/// The directory of `file`: a bare name lives in the working directory.
fs::path directory_of(const fs::path& file) {
  const fs::path parent = file.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

/// `content` in the temporary `tmp` (registered for removal by the caller), synced, with the
/// permissions of the file it replaces; 0, or the errno of the failure (the temporary removed).
int write_temporary(const Target& t, const fs::path& tmp, const ContentPieces& content) {
  struct stat previous {};
  const bool replacing = ::stat(t.path.c_str(), &previous) == 0;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  // The file replaced keeps its permissions (0600 stays 0600, 0755 stays 0755); a new one has
  // 0666 less the umask. Owner and group are the writer's; set-id and sticky bits are not copied.
  int error = replacing && ::fchmod(fd, previous.st_mode & 0777) != 0 ? errno : 0;
  try {
    if (error == 0) error = write_pieces(fd, content);
  } catch (...) {  // the content's maker failed: no temporary stays
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;  // the data on disk before the name points to it
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) ::unlink(tmp.c_str());
  return error;
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::string& content) {
  write_files_atomically({{path, content}});
}

void write_files_atomically(const std::vector<std::pair<fs::path, std::string>>& files) {
  std::vector<std::pair<fs::path, ContentPieces>> pieces;
  for (const auto& file : files) {  // no structured binding: clang 14 (make fuzz) cannot capture one
    const std::string& content = file.second;
    pieces.emplace_back(file.first, [&content](const std::function<void(std::string_view)>& write) { write(content); });
  }
  write_files_atomically(pieces);
}

void write_files_atomically(const std::vector<std::pair<fs::path, ContentPieces>>& files) {
  std::vector<Target> targets;
  for (const auto& file : files) targets.push_back(resolve(file.first));
  std::vector<fs::path> tmp_paths(files.size());  // empty: written through
  std::deque<RemoveOnSignal> registered;  // each before its file exists: no moment when a signal would orphan it
  auto remove_temporaries = [&tmp_paths](std::size_t from) {
    for (std::size_t i = from; i < tmp_paths.size(); ++i)
      if (!tmp_paths[i].empty()) ::unlink(tmp_paths[i].c_str());
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (targets[i].write_through) continue;
    const fs::path tmp = temporary_path(targets[i].path);
    registered.emplace_back(tmp);
    int error = 0;
    try {
      error = write_temporary(targets[i], tmp, files[i].second);
    } catch (...) {  // a content's maker failed: the temporaries before it go too
      remove_temporaries(0);
      throw;
    }
    if (error != 0) {
      remove_temporaries(0);
      fail(targets[i].what, reason_of(error));
    }
    tmp_paths[i] = tmp;
  }
  {
    const SignalHold hold;  // every rename done, or none begun, when a signal ends the program
    for (std::size_t i = 0; i < files.size(); ++i) {
      if (tmp_paths[i].empty() || ::rename(tmp_paths[i].c_str(), targets[i].path.c_str()) == 0) continue;
      const int error = errno;
      remove_temporaries(i);
      fail(targets[i].what, reason_of(error) + (i > 0 ? " (the files before it were replaced)" : ""));
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (targets[i].write_through) write_through(targets[i], files[i].second);
    else sync_directory(directory_of(targets[i].path));
  }
}

std::optional<fs::path> replaced_file(const fs::path& path) {
  Target t = resolve(path);
  if (t.write_through) return std::nullopt;
  return std::move(t.path);
}

void check_writable(const fs::path& path) {
  const Target t = resolve(path);
  if (t.write_through) {
    if (own_descriptor(t.path) < 0 && ::access(t.path.c_str(), W_OK) != 0) fail(t.what, reason_of(errno));
    return;
  }
  const fs::path tmp = temporary_path(t.path);
  const RemoveOnSignal registered(tmp);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) fail(t.what, reason_of(errno));
  ::close(fd);
  ::unlink(tmp.c_str());
}

fs::path sibling_path(const fs::path& target, const std::string& suffix) {
  std::string base = target.filename().string();
  if (base.size() + suffix.size() > NAME_MAX) {
    base.resize(NAME_MAX - suffix.size());
    while (!base.empty() && (static_cast<unsigned char>(base.back()) & 0xC0) == 0x80) base.pop_back();
    if (!base.empty() && static_cast<unsigned char>(base.back()) >= 0xC0) base.pop_back();  // a cut character's lead
  }
  return target.parent_path() / (base + suffix);
}

}  // namespace hertzdash

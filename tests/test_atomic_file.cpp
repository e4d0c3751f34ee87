// Output files (io/atomic_file.hpp): regular files by temporary + rename, symbolic links
// followed, FIFOs and devices written through, errno in the messages, no temporaries left
// behind by a failure or by any signal but SIGKILL (io/remove_on_signal.hpp), a set of files
// replaced together, a file size limit reported, one writer per file (io/output_lock.hpp).
#include "scratch_dir.hpp"
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/output_directories.hpp"
#include "hertzdash/io/output_lock.hpp"
#include "hertzdash/io/remove_on_signal.hpp"
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using hertzdash::write_file_atomically;
using hertzdash::test::slurp;
namespace fs = std::filesystem;

using hertzdash::test::ScratchDir;

namespace {

std::string message_of(const fs::path& p, const std::string& content) {
  try {
    write_file_atomically(p, content);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

struct stat stat_of(const fs::path& p) {
  struct stat st {};
  REQUIRE(::stat(p.c_str(), &st) == 0);
  return st;
}

// Runs `body` in a child process with `signal` at its default disposition and no core file;
// returns the child's wait status.
template <class Body>
int in_child(int signal, Body body) {
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const struct rlimit no_core {0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    std::signal(signal, SIG_DFL);
    body();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

}  // namespace

TEST_CASE("atomic file: a regular file is replaced by a new inode, nothing else left in the directory",
          "[atomic_file]") {
  // Replaced by rename: the new content lives in a new inode, the old inode (held open here)
  // keeps the old content; the directory holds only the target (no temporary).
  const ScratchDir s;
  const fs::path p = s.path / "out.csv";
  std::ofstream(p) << "old\n";
  std::ifstream old_reader(p);
  const ino_t before = stat_of(p).st_ino;
  write_file_atomically(p, "new\n");
  CHECK(slurp(p) == "new\n");
  CHECK(stat_of(p).st_ino != before);
  std::string old_line;
  std::getline(old_reader, old_line);
  CHECK(old_line == "old");
  CHECK(s.names() == std::vector<std::string>{"out.csv"});
}

TEST_CASE("atomic file: a symbolic link is followed, the link stays a link", "[atomic_file]") {
  const ScratchDir s;
  fs::create_directories(s.path / "real");
  const fs::path target = s.path / "real" / "data.csv", link = s.path / "link.csv";
  std::ofstream(target) << "old\n";
  fs::create_symlink("real/data.csv", link);  // relative: resolved against the link's directory
  write_file_atomically(link, "through the link\n");
  CHECK(fs::is_symlink(link));
  CHECK(fs::read_symlink(link) == "real/data.csv");
  CHECK(slurp(target) == "through the link\n");
  CHECK(fs::directory_iterator(s.path / "real")->path().filename() == "data.csv");  // no temporary left

  // A dangling link: the file it names is created (as a shell redirection would).
  const fs::path dangling = s.path / "dangling.csv";
  fs::create_symlink(s.path / "real" / "new.csv", dangling);
  write_file_atomically(dangling, "created\n");
  CHECK(fs::is_symlink(dangling));
  CHECK(slurp(s.path / "real" / "new.csv") == "created\n");
}

TEST_CASE("atomic file: a FIFO is written through to its reader and stays a FIFO", "[atomic_file]") {
  // The old code renamed a regular file over the FIFO and its reader saw nothing. Should that
  // come back, the reader, blocked opening the FIFO, is released through a second link to it,
  // so the test fails instead of hanging.
  const ScratchDir s;
  const fs::path fifo = s.path / "pipe", keep = s.path / "pipe.keep";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  fs::create_hard_link(fifo, keep);
  std::string received;
  std::atomic<bool> done{false};
  std::thread reader([&] {
    received = slurp(keep);
    done = true;
  });
  const std::string content = std::string(200000, 'x') + "\n";  // beyond the pipe's 64 KiB buffer
  const std::string error = message_of(fifo, content);
  while (!done) {  // a writer opening and closing gives the reader its end of file
    if (const int fd = ::open(keep.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) ::close(fd);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  reader.join();
  CHECK(error.empty());
  CHECK(S_ISFIFO(stat_of(fifo).st_mode));
  CHECK(received == content);
}

TEST_CASE("atomic file: character devices are written through and stay devices", "[atomic_file]") {
  // As root, on device nodes made here (a bug must not turn the machine's /dev/null into a
  // regular file); otherwise on /dev/null and /dev/full themselves (renaming over them is
  // refused to a user, so the old code failed there). Null (1,3) swallows, full (1,7) fails
  // every write with ENOSPC, which the message must carry.
  const ScratchDir s;
  fs::path null_device = "/dev/null", full_device = "/dev/full";
  if (::geteuid() == 0) {
    null_device = s.path / "null";
    full_device = s.path / "full";
    if (::mknod(null_device.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
        ::mknod(full_device.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
      WARN("cannot make device nodes here (no CAP_MKNOD): device write-through not tested");
      return;
    }
  }
  const struct stat before = stat_of(null_device);
  REQUIRE(S_ISCHR(before.st_mode));
  CHECK(message_of(null_device, "discarded\n").empty());
  const struct stat after = stat_of(null_device);
  CHECK(S_ISCHR(after.st_mode));
  CHECK(after.st_ino == before.st_ino);
  CHECK(after.st_rdev == before.st_rdev);

  const std::string full = message_of(full_device, "no room\n");
  CHECK(full.find("cannot write " + full_device.string()) != std::string::npos);
  CHECK(full.find("No space left on device") != std::string::npos);
  CHECK(S_ISCHR(stat_of(full_device).st_mode));
}

TEST_CASE("atomic file: a directory is refused with 'Is a directory', never 'Success'", "[atomic_file]") {
  const ScratchDir s;
  const std::string m = message_of(s.path, "x\n");
  CHECK(m == "cannot write " + s.path.string() + ": Is a directory");
  CHECK(m.find("Success") == std::string::npos);
  CHECK(fs::is_directory(s.path));
  CHECK(s.names().empty());
}

TEST_CASE("atomic file: a missing parent directory is an error naming it, and is not created", "[atomic_file]") {
  const ScratchDir s;
  const fs::path p = s.path / "missing" / "deeper" / "out.csv";
  const std::string m = message_of(p, "x\n");
  CHECK(m == "cannot write " + p.string() + ": the directory " + (s.path / "missing" / "deeper").string() +
                 " does not exist");
  CHECK(s.names().empty());
}

TEST_CASE("atomic file: a failed write leaves the old file and no temporary", "[atomic_file]") {
  // A write fails on a file-size limit for any user, root included (SIGXFSZ ignored: write(2)
  // gives EFBIG). In a child, so the limit stays there.
  const ScratchDir s;
  const fs::path p = s.path / "out.csv";
  std::ofstream(p) << "previous\n";
  const int status = in_child(SIGXFSZ, [&] {
    std::signal(SIGXFSZ, SIG_IGN);
    const struct rlimit limit {100, 100};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const std::string m = message_of(p, std::string(1000, 'x'));
    ::_exit(m.find("File too large") != std::string::npos ? 0 : 1);
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(slurp(p) == "previous\n");
  CHECK(s.names() == std::vector<std::string>{"out.csv"});
}

TEST_CASE("atomic file: SIGTERM removes a registered temporary, then terminates", "[atomic_file]") {
  // In a child with the default SIGTERM disposition (Catch installs its own in this process):
  // the handler unlinks the registered file and re-raises, so the child dies of SIGTERM.
  const ScratchDir s;
  const fs::path tmp = s.path / "big.csv.tmp.1.0";
  std::ofstream(tmp) << "half a file";
  const int status = in_child(SIGTERM, [&] {
    const hertzdash::RemoveOnSignal registered(tmp);
    ::raise(SIGTERM);
  });
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK_FALSE(fs::exists(tmp));
}

TEST_CASE("atomic file: an unregistered file survives SIGTERM", "[atomic_file]") {
  // The registration ends with its scope: a file renamed into place is never removed later.
  const ScratchDir s;
  const fs::path kept = s.path / "kept.csv";
  std::ofstream(kept) << "kept";
  const int status = in_child(SIGTERM, [&] {
    { const hertzdash::RemoveOnSignal registered(kept); }
    ::raise(SIGTERM);
  });
  CHECK(WIFSIGNALED(status));
  CHECK(fs::exists(kept));
}

TEST_CASE("output directories: the missing ones are found outermost first and created as mkdir -p does",
          "[atomic_file]") {
  const ScratchDir s;
  const fs::path file = s.path / "a" / "b" / "out.csv";
  CHECK(hertzdash::missing_parent_directories(file) == std::vector<fs::path>{s.path / "a", s.path / "a" / "b"});
  CHECK(s.names().empty());  // looking creates nothing
  hertzdash::create_parent_directories(file);
  CHECK(fs::is_directory(s.path / "a" / "b"));
  CHECK(hertzdash::missing_parent_directories(file).empty());
  CHECK(hertzdash::missing_parent_directories("relative.csv").empty());  // the working directory exists
}

TEST_CASE("output directories: a file or a link loop in the way is an error with the system's reason",
          "[atomic_file]") {
  // std::filesystem::create_directories threw filesystem_error for these ("File exists",
  // "Too many levels of symbolic links") with a text of its own; the reason is now errno's.
  const ScratchDir s;
  std::ofstream(s.path / "file") << "x";
  fs::create_symlink("loop", s.path / "loop");
  auto message = [](const fs::path& p) {
    try {
      hertzdash::create_parent_directories(p);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message(s.path / "file" / "x" / "out.csv") ==
        "cannot create directory " + (s.path / "file" / "x").string() + ": Not a directory");
  CHECK(message(s.path / "file" / "out.csv") == "cannot write into " + (s.path / "file").string() + ": it is not a directory");
  CHECK(message(s.path / "loop" / "x" / "out.csv") ==
        "cannot create directory " + (s.path / "loop" / "x").string() + ": Too many levels of symbolic links");
  CHECK(s.names() == std::vector<std::string>{"file", "loop"});
}

TEST_CASE("atomic file: a name of NAME_MAX bytes is written, its temporary's name cut short", "[atomic_file]") {
  // NAME.tmp.PID.N is up to 20 bytes longer than NAME: with NAME at NAME_MAX (255) bytes the
  // temporary's name was too long (ENAMETOOLONG) and the write failed. Also a UTF-8 name whose
  // cut falls inside a character (2-byte 'é' repeated: 254 bytes, then 'x').
  const ScratchDir s;
  for (const std::string& name : {std::string(NAME_MAX, 'a'), [] {
                                    std::string n;
                                    while (n.size() < NAME_MAX - 1) n += "\xC3\xA9";
                                    return n + "x";
                                  }()}) {
    REQUIRE(name.size() == NAME_MAX);
    const fs::path p = s.path / name;
    CHECK(message_of(p, "x\n").empty());
    CHECK(slurp(p) == "x\n");
    CHECK(s.names() == std::vector<std::string>{name});
    fs::remove(p);
  }
}

TEST_CASE("atomic file: a replaced file keeps its permissions", "[atomic_file]") {
  // The temporary was created 0666 less the umask and renamed over the file: a private 0600
  // file became 0644, an executable 0755 lost its x bits. A new file still gets 0666 & ~umask.
  const ScratchDir s;
  const fs::path p = s.path / "out.csv";
  for (const mode_t mode : {mode_t{0600}, mode_t{0755}, mode_t{0640}}) {
    std::ofstream(p) << "previous\n";
    REQUIRE(::chmod(p.c_str(), mode) == 0);
    CHECK(message_of(p, "new\n").empty());
    CHECK((stat_of(p).st_mode & 07777) == mode);
    CHECK(slurp(p) == "new\n");
  }
  const mode_t umask_now = ::umask(022);
  ::umask(umask_now);
  const fs::path fresh = s.path / "fresh.csv";
  CHECK(message_of(fresh, "x\n").empty());
  CHECK((stat_of(fresh).st_mode & 07777) == (0666 & ~umask_now));
}

TEST_CASE("atomic file: every signal that ends the process removes a registered temporary", "[atomic_file]") {
  // Before, only SIGINT, SIGTERM and SIGHUP did: SIGQUIT, SIGUSR1, SIGALRM and the others left
  // NAME.tmp.PID.N behind, although the documentation said only SIGKILL could.
  for (const int signal : {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGXCPU, SIGVTALRM,
                           SIGPROF, SIGIO, SIGPWR, SIGRTMIN, SIGRTMAX, SIGABRT}) {
    INFO("signal " << signal << " (" << strsignal(signal) << ")");
    const ScratchDir s;
    const fs::path tmp = s.path / "big.csv.tmp.1.0";
    std::ofstream(tmp) << "half a file";
    const int status = in_child(signal, [&] {
      const hertzdash::RemoveOnSignal registered(tmp);
      ::raise(signal);
    });
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal);
    CHECK_FALSE(fs::exists(tmp));
  }
}

TEST_CASE("atomic file: beyond ulimit -f a write fails with File too large and leaves no temporary",
          "[atomic_file]") {
  // Before, SIGXFSZ killed the process in the write: no message, and the temporary stayed.
  const ScratchDir s;
  const fs::path p = s.path / "big.csv";
  const int status = in_child(SIGXFSZ, [&] {
    const struct rlimit small {4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &small);
    ::_exit(message_of(p, std::string(1 << 16, 'x')) == "cannot write " + p.string() + ": File too large" ? 3 : 4);
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 3);
  CHECK(s.names().empty());
}

TEST_CASE("atomic file: a signal while a set of files is renamed is held until every rename is done",
          "[atomic_file]") {
  // The sweep's CSV and summary are renamed under a SignalHold: SIGINT between the two renames
  // used to leave the new CSV beside the old summary. A signal raised under the hold is
  // delivered, with its default action and the temporaries removed, when the hold ends.
  const ScratchDir s;
  const fs::path tmp = s.path / "out.csv.tmp.1.0", done = s.path / "done";
  std::ofstream(tmp) << "half a file";
  const int status = in_child(SIGINT, [&] {
    const hertzdash::RemoveOnSignal registered(tmp);
    {
      const hertzdash::SignalHold hold;
      ::raise(SIGINT);
      std::ofstream(done) << "the renames went on";
    }
    ::_exit(0);  // not reached: the held SIGINT ends the process here
  });
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGINT);
  CHECK(fs::exists(done));
  CHECK_FALSE(fs::exists(tmp));
}

TEST_CASE("atomic file: a set of files is replaced together, or none of them when one fails", "[atomic_file]") {
  const ScratchDir s;
  const fs::path csv = s.path / "out.csv", summary = s.path / "out.summary.csv";
  std::ofstream(csv) << "old csv\n";
  std::ofstream(summary) << "old summary\n";
  hertzdash::write_files_atomically({{csv, "new csv\n"}, {summary, "new summary\n"}});
  CHECK(slurp(csv) == "new csv\n");
  CHECK(slurp(summary) == "new summary\n");
  // The second file too large for ulimit -f: its temporary fails, so the first is not renamed.
  const int status = in_child(SIGXFSZ, [&] {
    const struct rlimit small {4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &small);
    try {
      hertzdash::write_files_atomically({{csv, "newer csv\n"}, {summary, std::string(1 << 16, 'x')}});
    } catch (const std::runtime_error&) {
      ::_exit(3);
    }
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 3);
  CHECK(slurp(csv) == "new csv\n");
  CHECK(slurp(summary) == "new summary\n");
  CHECK(s.names() == std::vector<std::string>{"out.csv", "out.summary.csv"});
}

TEST_CASE("atomic file: check_writable finds a directory no file can be made in, and leaves nothing",
          "[atomic_file]") {
  // /sys refuses new files even to root (the tests run as root, so a mode 0500 folder would not do).
  const auto message = [](const fs::path& p) {
    try {
      hertzdash::check_writable(p);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message("/sys/hertzdash-out.csv") == "cannot write /sys/hertzdash-out.csv: Permission denied");
  CHECK(message("/proc/hertzdash-out.csv") == "cannot write /proc/hertzdash-out.csv: No such file or directory");
  const ScratchDir s;
  CHECK(message(s.path / "out.csv").empty());
  CHECK(message("/dev/null").empty());
  CHECK(s.names().empty());
}

TEST_CASE("output lock: a second writer of the same file is refused, naming the holder, through a link too",
          "[atomic_file]") {
  const ScratchDir s;
  const fs::path out = s.path / "out.csv";
  fs::create_symlink(out, s.path / "link.csv");
  {
    const hertzdash::OutputLock held(out);
    CHECK(s.names() == std::vector<std::string>{"link.csv", "out.csv.lock"});
    try {
      const hertzdash::OutputLock second(*hertzdash::replaced_file(s.path / "link.csv"));
      FAIL("a second lock was granted");
    } catch (const hertzdash::OutputBusy& e) {
      CHECK(std::string(e.what()) == out.string() + " is being written by another process (PID " +
                                         std::to_string(::getpid()) + " holds " + out.string() + ".lock)");
    }
  }
  CHECK(s.names() == std::vector<std::string>{"link.csv"});  // the lock file goes with the lock
  const hertzdash::OutputLock again(out);
}

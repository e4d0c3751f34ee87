// The CLI's output files (docs/output-files.md): /dev/stdout and pipes written through, a
// missing directory refused (exit 2, option and directory named, nothing created) unless
// --mkdir, a directory refused; for every command that writes a file.
#include "scratch_dir.hpp"
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

using hertzdash::test::run_cli;
namespace fs = std::filesystem;

using hertzdash::test::ScratchDir;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

constexpr const char* trace_header = "t_s,force_N,accel_mps2,velocity_mps,displacement_m,x_m";

// `hertzdash ARGS` refused: exit code 2, exactly "hertzdash: REFUSAL" on stderr, nothing on stdout.
void check_refusal(const std::string& args, const std::string& refusal) {
  INFO(args);
  const auto r = run_cli(args);
  CHECK(r.exit_code == 2);
  CHECK(r.err == "hertzdash: " + refusal + "\n");
  CHECK(r.out.empty());
}

}  // namespace

TEST_CASE("CLI simulate --trace /dev/stdout: the trace, then the summary, on standard output", "[cli][output]") {
  // stdout is a regular file here (run_cli redirects it): the trace is written through the
  // descriptor, so the summary printed after it follows it instead of overwriting it.
  const auto r = run_cli("simulate --rod steel --height 0.02 --trace /dev/stdout");
  REQUIRE(r.exit_code == 0);
  const std::size_t trace = r.out.find(trace_header), summary = r.out.find("hertzdash simulate: damping law");
  CHECK(trace != std::string::npos);
  CHECK(summary != std::string::npos);
  CHECK(trace < summary);
  CHECK_FALSE(contains(r.err, "error"));
}

TEST_CASE("CLI simulate --trace /dev/stdout into a pipe", "[cli][output]") {
  // The old code renamed a file over /dev/stdout (as root) or failed; through a pipe, the
  // trace's rows arrive whole (each data row has 11 fields).
  FILE* pipe = ::popen(HERTZDASH_BIN " simulate --rod steel --height 0.02 --trace /dev/stdout --json", "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  const int status = ::pclose(pipe);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(contains(out, trace_header));
  CHECK(contains(out, "\"e_effective\""));
  CHECK(fs::is_symlink("/dev/stdout"));
}

TEST_CASE("CLI: a missing output directory exits 2 naming the option and the directory, creates nothing",
          "[cli][output]") {
  const ScratchDir s;
  const std::string missing = (s.path / "new" / "sub").string();
  std::FILE* f = std::fopen((s.path / "case.toml").c_str(), "w");
  std::fputs("[base]\nrod = \"steel\"\n[grid]\nheight = [0.01, 0.02]\n", f);
  std::fclose(f);
  const std::string trace = (s.path / "trace.csv").string();
  REQUIRE(run_cli("simulate --trace-format measured --trace " + trace).exit_code == 0);
  const struct {
    std::string args, option;
  } cases[] = {
      {"simulate --trace " + missing + "/t.csv", "--trace"},
      {"simulate --trace-format measured --trace " + missing + "/t.csv", "--trace"},
      {"fit --trace " + trace + " --curves " + missing + "/c.csv", "--curves"},
      {"sweep " + (s.path / "case.toml").string() + " --quiet --out " + missing + "/s.csv", "--out"},
      {"sweep " + (s.path / "case.toml").string() + " --quiet --summary " + missing + "/s.csv", "--summary"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_cli(c.args);
    CHECK(r.exit_code == 2);
    CHECK(contains(r.err, "invalid " + c.option + " = " + missing));
    CHECK(contains(r.err, missing + " does not exist; --mkdir creates it"));
    CHECK_FALSE(fs::exists(s.path / "new"));
  }
  CHECK_FALSE(fs::exists(s.path / "case.csv"));  // the sweep wrote nothing
}

TEST_CASE("CLI --mkdir creates the missing directories of every output file", "[cli][output]") {
  const ScratchDir s;
  std::FILE* f = std::fopen((s.path / "case.toml").c_str(), "w");
  std::fputs("[base]\nrod = \"steel\"\n[grid]\nheight = [0.01, 0.02]\n", f);
  std::fclose(f);
  const fs::path trace = s.path / "a" / "b" / "trace.csv";
  REQUIRE(run_cli("simulate --trace-format measured --mkdir --trace " + trace.string()).exit_code == 0);
  CHECK(fs::is_regular_file(trace));
  const fs::path curves = s.path / "c" / "curves.csv";
  CHECK(run_cli("fit --mkdir --trace " + trace.string() + " --curves " + curves.string()).exit_code == 0);
  CHECK(fs::is_regular_file(curves));
  const fs::path out = s.path / "d" / "runs.csv", summary = s.path / "e" / "summary.csv";
  CHECK(run_cli("sweep " + (s.path / "case.toml").string() + " --quiet --mkdir --out " + out.string() + " --summary " +
                summary.string())
            .exit_code == 0);
  CHECK(fs::is_regular_file(out));
  CHECK(fs::is_regular_file(summary));
}

TEST_CASE("CLI: an output path that is a directory exits 2 and says so", "[cli][output]") {
  const ScratchDir s;
  check_refusal("simulate --trace " + s.path.string(),
                "invalid --trace = " + s.path.string() + ": must be a file, not a directory");
  CHECK(fs::is_empty(s.path));
}

TEST_CASE("CLI --mkdir: bad input or a failed run leaves no new directory", "[cli][output]") {
  // The directories are created right before the file is written, after every input was
  // validated and the run succeeded; before, --mkdir created them first, so each of these
  // refusals left S/new behind.
  const ScratchDir s;
  const std::string trace = (s.path / "trace.csv").string();
  REQUIRE(run_cli("simulate --trace-format measured --trace " + trace).exit_code == 0);
  const std::string dir = (s.path / "new" / "sub").string();
  const struct {
    std::string args;
    int exit_code;
  } cases[] = {
      {"simulate --mkdir --trace " + dir + "/t.csv --mass -1", 2},
      {"simulate --mkdir --trace " + dir + "/t.csv --gravity 1e308", 2},
      {"simulate --mkdir --trace-format measured --trace " + dir + "/t.csv --noise -1", 2},
      {"fit --mkdir --trace " + trace + " --curves " + dir + "/c.csv --fit not-a-parameter", 2},
      {"fit --mkdir --trace " + trace + " --curves " + dir + "/c.csv --ball-E -3", 2},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_cli(c.args);
    INFO(r.err);
    CHECK(r.exit_code == c.exit_code);
    CHECK_FALSE(fs::exists(s.path / "new"));
  }
}

TEST_CASE("CLI: a file or a symbolic-link loop where a directory should be exits 2 with the system's reason",
          "[cli][output]") {
  // Before, these ended in a raw std::filesystem exception (exit 1, "filesystem error: ...").
  const ScratchDir s;
  std::FILE* f = std::fopen((s.path / "file").c_str(), "w");
  std::fclose(f);
  fs::create_symlink("loop", s.path / "loop");  // a link to itself: ELOOP
  const std::string file = (s.path / "file").string(), loop = (s.path / "loop").string();
  const struct {
    std::string path, reason;
  } cases[] = {
      {file + "/t.csv", "(cannot write into " + file + ": it is not a directory)"},
      {file + "/x/t.csv", "(cannot create directory " + file + "/x: Not a directory)"},
      {loop + "/x/t.csv", "(cannot create directory " + loop + "/x: Too many levels of symbolic links)"},
  };
  for (const bool mkdir : {false, true})
    for (const auto& c : cases) {
      check_refusal(std::string("simulate ") + (mkdir ? "--mkdir " : "") + "--trace " + c.path,
                    "invalid --trace = " + c.path + ": must be a file in a directory that exists or can be created " +
                        c.reason);
    }
  CHECK(fs::is_regular_file(s.path / "file"));
  CHECK(fs::is_symlink(s.path / "loop"));
}

TEST_CASE("CLI: an empty output path exits 2 naming the option", "[cli][output]") {
  // Before, --trace '' (and the others) was taken as no output asked for: exit 0, nothing written.
  const ScratchDir s;
  std::FILE* f = std::fopen((s.path / "case.toml").c_str(), "w");
  std::fputs("[base]\nrod = \"steel\"\n[grid]\nheight = [0.01, 0.02]\n", f);
  std::fclose(f);
  const std::string trace = (s.path / "trace.csv").string(), case_file = (s.path / "case.toml").string();
  REQUIRE(run_cli("simulate --trace-format measured --trace " + trace).exit_code == 0);
  const struct {
    std::string args, option;
  } cases[] = {
      {"simulate --trace ''", "--trace"},
      {"simulate --trace-format measured --trace ''", "--trace"},
      {"fit --trace " + trace + " --curves ''", "--curves"},
      {"sweep " + case_file + " --quiet --out ''", "--out"},
      {"sweep " + case_file + " --quiet --summary ''", "--summary"},
  };
  for (const auto& c : cases) check_refusal(c.args, "invalid " + c.option + " = '': must be a file path (not empty)");
  CHECK_FALSE(fs::exists(s.path / "case.csv"));
}

TEST_CASE("CLI: an output that is the same file as an input or another output exits 2 naming both", "[cli][output]") {
  // Before, each of these replaced a file with exit 0: the measured trace, the case file, the
  // per-run table (by the summary, "wrote x.csv and x.csv"). Identity is the file's, not the
  // name's: a symbolic link, a hard link and another spelling of the path are the same file.
  const ScratchDir s;
  const std::string dir = s.path.string();
  s.write("victim.csv", "the measured trace\n");
  s.write("ok.toml", "[grid]\nheight = [0.01, 0.02]\n");
  fs::create_symlink("victim.csv", s.path / "victim-link.csv");
  fs::create_hard_link(s.path / "victim.csv", s.path / "victim-hard.csv");
  fs::create_symlink("x.csv", s.path / "x-link.csv");  // dangling: x.csv is not written yet
  const struct {
    std::string args, refusal;
  } cases[] = {
      {"fit --trace " + dir + "/victim.csv --curves " + dir + "/victim.csv",
       "invalid --curves = DIR/victim.csv: must be another file than --trace (DIR/victim.csv), which is read"},
      {"fit --trace " + dir + "/victim.csv --curves " + dir + "/victim-link.csv",
       "invalid --curves = DIR/victim-link.csv: must be another file than --trace (DIR/victim.csv), which is read"},
      {"fit --trace " + dir + "/victim.csv --curves " + dir + "/victim-hard.csv",
       "invalid --curves = DIR/victim-hard.csv: must be another file than --trace (DIR/victim.csv), which is read"},
      {"sweep " + dir + "/ok.toml --quiet --out " + dir + "/../" + s.path.filename().string() + "/ok.toml",
       "must be another file than the case file (DIR/ok.toml), which is read"},
      {"sweep " + dir + "/ok.toml --quiet --out " + dir + "/x.csv --summary " + dir + "/x.csv",
       "invalid --summary = DIR/x.csv: must be another file than --out (DIR/x.csv), which is written too"},
      {"sweep " + dir + "/ok.toml --quiet --out " + dir + "/x.csv --summary " + dir + "/x-link.csv",
       "invalid --summary = DIR/x-link.csv: must be another file than --out (DIR/x.csv), which is written too"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_cli(c.args);
    CHECK(r.exit_code == 2);
    std::string refusal = c.refusal;
    for (std::size_t at; (at = refusal.find("DIR")) != std::string::npos;) refusal.replace(at, 3, dir);
    CHECK(contains(r.err, refusal + ": they are the same file"));
    CHECK(r.out.empty());
  }
  CHECK(hertzdash::test::slurp(s.path / "victim.csv") == "the measured trace\n");
  CHECK(hertzdash::test::slurp(s.path / "ok.toml") == "[grid]\nheight = [0.01, 0.02]\n");
  CHECK_FALSE(fs::exists(s.path / "x.csv"));
  // Written through, /dev/null replaces nothing: both outputs may go there.
  CHECK(run_cli("sweep " + dir + "/ok.toml --quiet --out /dev/null --summary /dev/null").exit_code == 0);
}

TEST_CASE("CLI: an output no file can be written to exits 2 before any run", "[cli][output]") {
  // Before, the runs ran (200,000 of them in the report) and the write failed afterwards with
  // exit 1 and nothing saved. /sys and /proc refuse new files even to root, as the tests run.
  const ScratchDir s;
  s.write("ok.toml", "[grid]\nheight = [0.01, 0.02]\n");
  const std::string case_file = (s.path / "ok.toml").string();
  const struct {
    std::string args, refusal;
  } cases[] = {
      {"sweep " + case_file + " --quiet --out /sys/hertzdash-out.csv",
       "invalid --out = /sys/hertzdash-out.csv: must be a file that can be written (cannot write "
       "/sys/hertzdash-out.csv: Permission denied)"},
      {"sweep " + case_file + " --quiet --out " + (s.path / "a.csv").string() + " --summary /sys/hertzdash-out.csv",
       "invalid --summary = /sys/hertzdash-out.csv: must be a file that can be written (cannot write "
       "/sys/hertzdash-out.csv: Permission denied)"},
      {"simulate --trace /proc/hertzdash-out.csv",
       "invalid --trace = /proc/hertzdash-out.csv: must be a file that can be written (cannot write "
       "/proc/hertzdash-out.csv: No such file or directory)"},
  };
  for (const auto& c : cases) check_refusal(c.args, c.refusal);
  CHECK(s.names() == std::vector<std::string>{"ok.toml"});
}

TEST_CASE("CLI: beyond ulimit -f the write fails with File too large, exit 1, no temporary", "[cli][output]") {
  // Before, SIGXFSZ killed the program in the write: exit 153, no message, NAME.tmp.PID.N left.
  const ScratchDir s;
  const auto r = hertzdash::test::run_cli_program("cd " + s.path.string() + " && ulimit -f 1 && " HERTZDASH_BIN,
                                                  "simulate --trace trace.csv");
  CHECK(r.exit_code == 1);
  CHECK(contains(r.err, "cannot write trace.csv: File too large"));
  CHECK(s.names().empty());
}

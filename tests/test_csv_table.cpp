// The CSV table reader (io/csv_table.hpp): each column name once, each "# key: value" header key
// once, and the size limit enforced while reading, however long a line.
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using hertzdash::CsvTable;
using hertzdash::DataError;
namespace fs = std::filesystem;

using hertzdash::test::ScratchDir;

namespace {

std::string message_of(const fs::path& file) {
  try {
    (void)CsvTable::read(file);
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("CSV: a column name given twice is refused at its line and column", "[csv]") {
  // Before, the second 'e' was read and never used: column lookups found the first.
  const ScratchDir s;
  // Line 2 (after one comment line); the second 'e' starts at byte 7 of "rod,e,e".
  const fs::path f = s.write("dup.csv", "# a comment\nrod,e,e\nsteel,0.8,0.9\n");
  CHECK(message_of(f) == f.string() + ":2:7: column 'e' again (first at column 5); each column name appears once");
  const fs::path ok = s.write("ok.csv", "rod,e,e_second\nsteel,0.8,0.9\n");
  CHECK(message_of(ok).empty());
}

TEST_CASE("CSV: a header key given twice is refused at its line and column, free comments are not", "[csv]") {
  const ScratchDir s;
  // "#  height_m: 0.03" on line 3: the key starts at byte 4, after '#' and two blanks.
  const fs::path f = s.write("dup.csv", "# height_m: 0.02\n# note: a\n#  height_m: 0.03\n# note: b\nt_s\n0\n");
  const CsvTable t = CsvTable::read(f);
  CHECK_THROWS_WITH(t.comment_field("height_m"),
                    f.string() + ":3:4: header key 'height_m' again (first on line 1); each header key appears once");
  CHECK_THROWS_AS(t.comment_field("note"), DataError);  // asked for, a repeated key is refused
  CHECK_FALSE(t.comment_field("source").has_value());
  const fs::path ok = s.write("ok.csv", "# height_m :  0.02 \nt_s\n0\n");
  CHECK(CsvTable::read(ok).comment_field("height_m") == std::string("0.02"));
}

TEST_CASE("CSV: an endless line from a pipe is refused after 16 MiB, not read to its end", "[csv]") {
  // A FIFO has no size to check first. A writer sends 64 MiB without a line end, 64 KiB at a
  // time, and counts what it could write before the reader closed the pipe (EPIPE). Before,
  // std::getline read the whole line (all 64 MiB) and only then compared it with the limit.
  // Now the reader stops at 16 MiB + one chunk: the writer gets at most that plus what the
  // pipe and the stream buffer hold (64 KiB each), far below 20 MiB.
  const ScratchDir s;
  const fs::path fifo = s.path / "endless.csv";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  int count_pipe[2];
  REQUIRE(::pipe(count_pipe) == 0);
  const pid_t writer = ::fork();
  REQUIRE(writer >= 0);
  if (writer == 0) {
    std::signal(SIGPIPE, SIG_IGN);
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    const std::string chunk(1 << 16, 'x');
    unsigned long long written = 0;
    while (written < (64ull << 20)) {
      const ssize_t n = ::write(fd, chunk.data(), chunk.size());
      if (n <= 0) break;
      written += static_cast<unsigned long long>(n);
    }
    (void)!::write(count_pipe[1], &written, sizeof written);
    ::_exit(0);
  }
  ::close(count_pipe[1]);
  const std::string m = message_of(fifo);
  unsigned long long written = 0;
  REQUIRE(::read(count_pipe[0], &written, sizeof written) == sizeof written);
  ::close(count_pipe[0]);
  int status = 0;
  ::waitpid(writer, &status, 0);
  CHECK(m == fifo.string() + ": more than 16777216 bytes; a data table is at most 16 MiB (read so far)");
  CHECK(written > (16ull << 20));
  CHECK(written < (20ull << 20));
}

TEST_CASE("CSV: a directory given as a table is refused with the read's own reason", "[csv]") {
  // Opening a directory for reading succeeds on Linux; the first read fails with EISDIR, and the
  // message names that reason with the path.
  const ScratchDir s;
  const std::string m = message_of(s.path);
  CHECK_THAT(m, Catch::Contains(s.path.string() + ": cannot read: Is a directory"));
}

TEST_CASE("CSV: LF, CR LF and lone CR line ends are read alike, line numbers included", "[csv]") {
  // Before, a file with CR line ends (classic Mac OS, some loggers) was one line: "the table is
  // empty".
  const ScratchDir s;
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    const fs::path f = s.write("t.csv", "# height_m: 0.02" + end + "t_s,force_N" + end + "0,1" + end + "0.5,x" + end);
    const CsvTable t = CsvTable::read(f);
    CHECK(t.columns() == std::vector<std::string>{"t_s", "force_N"});
    CHECK(t.comment_field("height_m") == std::string("0.02"));
    CHECK(t.number(0, "force_N") == 1.0);
    CHECK_THROWS_WITH(t.number(1, "force_N"), Catch::StartsWith(f.string() + ":4:5: "));
  }
}

TEST_CASE("CSV: bytes that are not UTF-8 text are refused at their line and column when read", "[csv]") {
  // Before, a Latin-1 "été" in a recording's "# source:" was read, the fit ran, and the JSON
  // writer threw after it (exit 1, empty stdout). A table is UTF-8 text (RFC 3629), so each
  // refused sequence below names the byte where it starts; the valid ones are read.
  const ScratchDir s;
  struct Case {
    const char* name;
    std::string text;
    const char* where;  // "LINE:COL: " of the first bad byte, or "" for a table that reads
    const char* what;
  };
  const Case cases[] = {
      // "# source: " is 10 bytes, so the Latin-1 é (0xE9) is byte 11 of line 1.
      {"latin1_comment.csv", "# source: \xE9t\xE9\ndrop,impact_time_s\na,0.1\n", "1:11: ", "byte 0xE9"},
      // A Windows-1252 label in a data row: "a" then 0x92 (a curly apostrophe) at byte 2 of line 3.
      {"cp1252_label.csv", "drop,impact_time_s\nx,0.1\na\x92,0.2\n", "3:2: ", "byte 0x92"},
      // A NUL byte would end a C string: the message says so instead of stopping short.
      {"nul.csv", std::string("drop,impact_time_s\na") + '\0' + "b,0.1\n", "2:2: ", "a NUL byte"},
      // Overlong "/" (C0 AF), a UTF-16 surrogate (ED A0 80), beyond U+10FFFF (F4 90 80 80), a
      // sequence cut by the line's end (E2 82).
      {"overlong.csv", "a,b\n\xC0\xAF,1\n", "2:1: ", "byte 0xC0"},
      {"surrogate.csv", "a,b\nx\xED\xA0\x80,1\n", "2:2: ", "byte 0xED"},
      {"beyond.csv", "a,b\n\xF4\x90\x80\x80,1\n", "2:1: ", "byte 0xF4"},
      {"cut.csv", "a,b\n1,\xE2\x82\n", "2:3: ", "byte 0xE2"},
      // UTF-8 itself: é (C3 A9), € (E2 82 AC), an emoji (F0 9F 8E BE), after a byte order mark.
      {"utf8.csv", "\xEF\xBB\xBF# source: \xC3\xA9t\xC3\xA9 \xE2\x82\xAC\ndrop,impact_time_s\n\xF0\x9F\x8E\xBE,0.1\n", "", ""},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string message = message_of(s.write(c.name, c.text));
    if (std::string(c.where).empty()) {
      CHECK(message.empty());
      continue;
    }
    CHECK(message.find(std::string(c.name) + ":" + c.where + c.what + ", not UTF-8 text") != std::string::npos);
  }
}

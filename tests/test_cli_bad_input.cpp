// Bad input: every invalid parameter exits with code 2, names the parameter and its
// valid range, and writes no file (the trace is written only after a successful run,
// atomically).
#include "scratch_dir.hpp"
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

using hertzdash::test::run_cli;

using hertzdash::test::ScratchDir;

namespace {

struct BadInput {
  const char* args;
  const char* parameter;  // must appear in the message
  const char* range;      // must appear in the message
};

}  // namespace

TEST_CASE("CLI: each invalid parameter exits 2, names it and its range, writes no file", "[cli]") {
  const BadInput cases[] = {
      {"--mass 0", "--mass", "> 0"},
      {"--mass -1", "--mass", "> 0"},
      {"--mass nan", "--mass", "> 0"},
      {"--ball-radius 0", "--ball-radius", "> 0"},
      {"--ball-radius -0.01", "--ball-radius", "> 0"},
      {"--ball-E 0", "--ball-E", "> 0"},
      {"--ball-E nan", "--ball-E", "> 0"},
      {"--rod-E -1", "--rod-E", "> 0 or inf"},
      {"--restitution 0", "--restitution", "(0, 1]"},
      {"--restitution 1.5", "--restitution", "(0, 1]"},
      {"--restitution nan", "--restitution", "(0, 1]"},
      {"--ball-nu 0.5", "--ball-nu", "(-1, 0.5)"},
      {"--ball-nu -1", "--ball-nu", "(-1, 0.5)"},
      {"--rod-nu 0.7", "--rod-nu", "(-1, 0.5)"},
      {"--height -0.01", "--height", ">= 0"},
      {"--height 0", "--height", "> 0 with --gravity > 0"},
      {"--gravity -9.8", "--gravity", ">= 0"},
      {"--gravity 0", "--gravity", "> 0 with --height > 0"},  // the default --height is not to blame
      {"--impact-velocity 0", "--impact-velocity", "> 0"},
      {"--impact-velocity nan", "--impact-velocity", "> 0"},
      {"--integrator rk4 --dt 0", "--dt", "> 0"},
      {"--integrator euler --dt -1e-6", "--dt", "> 0"},
      {"--rtol 0", "--rtol", "in (0, 1)"},
      {"--atol -1", "--atol", "in (0, 1)"},
      {"--rtol nan", "--rtol", "in (0, 1)"},
      {"--rtol 10", "--rtol", "in (0, 1)"},
      {"--rtol 1", "--rtol", "in (0, 1)"},
      {"--atol 1", "--atol", "in (0, 1)"},
      {"--dt 0", "--dt", "> 0"},
      {"--dt nan", "--dt", "> 0"},
      {"--integrator rk4 --rtol 10", "--rtol", "in (0, 1)"},
      {"--max-step -1", "--max-step", ">= 0"},
      {"--integrator leapfrog", "--integrator", "euler, rk4, cvode"},
      {"--damping nonsense", "--damping", "hongo"},
      {"--rod titanium", "--rod", "steel"},
      {"--zeta approx", "--zeta", "paper, exact"},
      {"--cvode-method rk", "--cvode-method", "adams, bdf"},
      {"--rod-model flexible", "--rod-model", "rigid, elastic"},
      {"--rod-elements 10", "--rod-elements", "given only with --rod-model elastic"},
      {"--cell-stiffness 1e9", "--cell-stiffness", "given only with --rod-model elastic"},
      {"--accelerometer top", "--accelerometer", "given only with --rod-model elastic"},
      {"--damping flores --zeta exact", "--zeta", "given only with --damping hongo"},
      {"--linear-stiffness 1e6", "--linear-stiffness", "given only with --damping kelvin-voigt"},
      {"--rod-model elastic --rod-elements 0", "--rod-elements", "an integer in [1, 400]"},
      {"--rod-model elastic --rod-elements 2.5", "--rod-elements", "an integer in [1, 400]"},
      {"--rod-model elastic --rod-elements 401", "--rod-elements", "an integer in [1, 400]"},
      {"--rod-model elastic --rod-damping-ratio 1", "--rod-damping-ratio", "[0, 1)"},
      {"--rod-model elastic --rod-damping-ratio -0.1", "--rod-damping-ratio", "[0, 1)"},
      {"--rod-model elastic --cell-stiffness 0", "--cell-stiffness", "> 0 or inf"},
      {"--rod-model elastic --cell-damping-ratio nan", "--cell-damping-ratio", "[0, 1)"},
      {"--rod-model elastic --hemisphere-mass -1", "--hemisphere-mass", "> 0"},
      {"--rod-model elastic --accelerometer middle", "--accelerometer", "top, bottom"},
      {"--rod-model elastic --rod-E inf", "--rod-E", "a finite modulus"},
      {"--rod-model elastic --integrator euler", "--integrator", "resolves this elastic rod's run in at most"},
      {"--viscous-time-constant 1e-4", "--viscous-time-constant", "given only with --damping kuwabara-kono"},
      {"--reference-velocity 0.5", "--reference-velocity", "given only with --damping kuwabara-kono"},
      {"--damping kuwabara-kono --viscous-time-constant -1e-4", "--viscous-time-constant", ">= 0"},
      {"--damping kuwabara-kono --viscous-time-constant nan", "--viscous-time-constant", ">= 0"},
      {"--damping kuwabara-kono --reference-velocity 0", "--reference-velocity", "> 0"},
      {"--damping kuwabara-kono --reference-velocity 0.5 --viscous-time-constant 1e-4", "--reference-velocity",
       "omitted when --viscous-time-constant is given"},
      // Issue 30: the height was silently ignored beside an impact velocity.
      {"--height 0.05 --impact-velocity 0.5", "--height", "omitted when --impact-velocity is given"},
      {"--ball-yield-stress 0", "--ball-yield-stress", "> 0 or inf"},
      {"--ball-yield-stress nan", "--ball-yield-stress", "> 0 or inf"},
      // Issue 19: hexadecimal was read (0x10 as 16), an empty text as 0, and "1e" named no range.
      {"--mass 0x10", "--mass = '0x10'", "a decimal number"},
      {"--mass 0x10", "--mass", "> 0"},
      {"--mass 1e", "--mass = '1e'", "> 0"},
      {"--ball-nu ''", "--ball-nu = ''", "(-1, 0.5)"},
      {"--rod-nu ''", "--rod-nu = ''", "(-1, 0.5)"},
      {"--max-step ''", "--max-step = ''", ">= 0"},
      {"--height 0x1p-5", "--height = '0x1p-5'", ">= 0"},
  };
  const auto trace = std::filesystem::temp_directory_path() / ("hertzdash_bad_" + std::to_string(::getpid()) + ".csv");
  for (const BadInput& c : cases) {
    std::filesystem::remove(trace);
    const auto r = run_cli(std::string("simulate ") + c.args + " --trace " + trace.string());
    INFO("hertzdash simulate " << c.args << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.parameter) != std::string::npos);
    CHECK(r.err.find(c.range) != std::string::npos);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(trace));
  }
}

TEST_CASE("CLI: a run that would not finish ends with exit 1 and says so instead of hanging", "[cli]") {
  // Issue 19's hangs. A fixed step whose run needs more than 1e9 steps does not start (the
  // 20 mm drop and 20 t_H after it last 0.089 s: 8.9e10 steps of 1e-12 s; with 1e-308 s,
  // t + dt == t and it would never end). CVODE stepping one step per call is bounded by its
  // 1e6 steps (--max-step 1e-12 would need 8.9e10).
  // Issue 31: the elastic rod at 400 elements (804 state components) ran 190 s at rk4 --dt 1e-10
  // and exited 0, 203 s at --max-step 1e-10: its fixed-step runs are bounded by component-steps,
  // 1e10 / 806 = 1.2e7 steps (the drop, the contact and 20 t_H after it, 0.024 s, need 2.4e8 of
  // 1e-10 s), and
  // a largest step that alone needs more steps than CVODE's 1e6 is refused before any work.
  for (const char* args : {"--integrator rk4 --dt 1e-12", "--integrator euler --dt 1e-308", "--max-step 1e-12",
                           "--rod-model elastic --rod-elements 400 --integrator rk4 --dt 1e-10",
                           "--rod-model elastic --rod-elements 400 --max-step 1e-10"}) {
    const auto r = run_cli(std::string("simulate ") + args);
    INFO("hertzdash simulate " << args << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("did not finish") != std::string::npos);
    CHECK(r.out.empty());
  }
}

TEST_CASE("CLI bounce: each invalid option exits 2, names it and its range", "[cli][bounce]") {
  const BadInput cases[] = {
      {"--bounces 0", "--bounces", "an integer in [1, 1000]"},
      {"--bounces 1001", "--bounces", "an integer in [1, 1000]"},
      {"--bounces 2.5", "--bounces", "an integer in [1, 1000]"},
      {"--target-interval-restitution 0.05", "--target-interval-restitution", "jump past it"},
      {"--min-rebound-velocity -1", "--min-rebound-velocity", ">= 0"},
      {"--min-rebound-velocity nan", "--min-rebound-velocity", ">= 0"},
      {"--gravity 0 --impact-velocity 0.5", "--gravity", "> 0 for a bounce sequence"},
      {"--target-interval-restitution 1.5", "--target-interval-restitution", "(0, 1]"},
      {"--target-interval-restitution 0", "--target-interval-restitution", "(0, 1]"},
      {"--mass -1", "--mass", "> 0"},
  };
  for (const BadInput& c : cases) {
    const auto r = run_cli(std::string("bounce ") + c.args);
    INFO("hertzdash bounce " << c.args << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.parameter) != std::string::npos);
    CHECK(r.err.find(c.range) != std::string::npos);
    CHECK(r.out.empty());
  }
}

TEST_CASE("CLI restitution: an iterated --omega-n exits 2 naming the option and the valid variants", "[cli]") {
  for (const char* variant : {"self-consistent", "contact-time"}) {
    const auto r = run_cli(std::string("restitution --omega-n ") + variant);
    INFO("hertzdash restitution --omega-n " << variant << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--omega-n") != std::string::npos);
    CHECK(r.err.find("paper, impact-energy, rebound-energy or as-printed") != std::string::npos);
  }
}

TEST_CASE("CLI: an unknown or missing subcommand exits 2 and lists the subcommands", "[cli]") {
  // Issue 19: `hertzdash frobnicate` said "A subcommand is required".
  const std::string listed =
      "simulate, models, parameters, restitution, bounce, shaker, walls, oscillator, spheres, oblique, orbit, continue, lyapunov, basins, fit, "
      "export, "
      "conformance, sweep "
      "(hertzdash --help)";
  const auto unknown = run_cli("frobnicate --mass 1");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err == "hertzdash: unknown subcommand 'frobnicate': the subcommands are " + listed + "\n");
  CHECK(unknown.out.empty());
  const auto none = run_cli("");
  CHECK(none.exit_code == 2);
  CHECK(none.err == "hertzdash: a subcommand is required: " + listed + "\n");
  // A subcommand's own missing option is still named.
  const auto fit = run_cli("fit");
  CHECK(fit.exit_code == 2);
  CHECK(fit.err.find("--trace is required") != std::string::npos);
}

TEST_CASE("CLI: an option value that is not a number exits 2 naming the option", "[cli]") {
  const auto r = run_cli("simulate --mass heavy");
  CHECK(r.exit_code == 2);
  CHECK(r.err == "hertzdash: invalid --mass = 'heavy': must be a decimal number (digits with an optional sign, point "
                 "and exponent: 0.02, -1.5e-3, 2E9) and a finite number > 0 (kg)\n");
}

TEST_CASE("CLI: an option value beyond the range of a double exits 2 saying so, not 'not a decimal number'", "[cli]") {
  // 1e400 > DBL_MAX (1.8e308) and 1e-400 < the smallest subnormal (4.9e-324): both decimal
  // numbers that no double holds; before, both were "not a decimal number".
  for (const char* text : {"1e400", "1e-400"}) {
    const auto r = run_cli(std::string("simulate --mass ") + text);
    CHECK(r.exit_code == 2);
    CHECK(r.err == "hertzdash: invalid --mass = '" + std::string(text) +
                       "' (out of range of double): must be a decimal number of magnitude at most "
                       "1.7976931348623157e308 and, if nonzero, at least 4.9e-324, and a finite number > 0 (kg)\n");
  }
}

namespace {

// The subcommands `hertzdash --help` lists.
std::vector<std::string> subcommands() {
  const auto r = run_cli("--help");
  std::vector<std::string> names;
  std::istringstream lines(r.out.substr(r.out.find("Subcommands:")));
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line))
    if (std::istringstream words(line); words >> line) names.push_back(line);
  return names;
}

// The options of `hertzdash <subcommand> --help` whose value has the type `type` (FLOAT, UINT).
std::vector<std::string> options_of_type(const std::string& subcommand, const std::string& type) {
  const auto r = run_cli(subcommand + " --help");
  std::vector<std::string> flags;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string flag, value;
    if (words >> flag >> value && flag.rfind("--", 0) == 0 && (value == type || value.rfind(type + "=", 0) == 0))
      flags.push_back(flag);
  }
  return flags;
}

// A scratch directory removed afterwards.

}  // namespace

TEST_CASE("CLI: every numeric option of every subcommand refuses text that is not a decimal number", "[cli][numbers]") {
  // Issue 19: CLI11 read 0x10 as 16 and an empty text as 0. Every FLOAT and UINT option of every
  // subcommand in --help is given each text below: exit 2, a message naming the option, the
  // text and what it must be, nothing on stdout and no output file.
  const ScratchDir dir;
  const std::string trace = (dir.path / "trace.csv").string(), out = (dir.path / "out.csv").string();
  REQUIRE(run_cli("simulate --trace " + trace + " --trace-format measured").exit_code == 0);
  std::ofstream(dir.path / "case.toml") << "[grid]\nheight = [0.01]\n";
  // What each subcommand needs to run, with an output file in the scratch directory.
  const std::map<std::string, std::string> needs{
      {"simulate", "--trace " + out},
      {"fit", "--trace " + trace + " --curves " + out},
      {"sweep", (dir.path / "case.toml").string() + " --quiet --out " + out},
      {"export", "--engine lammps --out " + dir.path.string()},
      {"conformance", "--engine lammps"},
  };
  // The options that apply only with another: given with it, so that the refusal is theirs.
  const std::map<std::string, std::string> context{
      {"--rod-elements", "--rod-model elastic"},       {"--rod-damping-ratio", "--rod-model elastic"},
      {"--cell-stiffness", "--rod-model elastic"},     {"--cell-damping-ratio", "--rod-model elastic"},
      {"--hemisphere-mass", "--rod-model elastic"},    {"--viscous-time-constant", "--damping kuwabara-kono"},
      {"--reference-velocity", "--damping kuwabara-kono"}, {"--sample-rate", "--trace-format measured"},
      {"--anti-alias", "--trace-format measured"},     {"--noise", "--trace-format measured"},
      {"--seed", "--trace-format measured"},           {"--dt", "--integrator rk4"},
  };
  std::size_t tried = 0;
  for (const std::string& sub : subcommands()) {
    for (const auto& [type, expected] : {std::pair<std::string, std::string>{"FLOAT", "a decimal number"},
                                         std::pair<std::string, std::string>{"UINT", "a decimal integer in [0, "}}) {
      for (const std::string& flag : options_of_type(sub, type)) {
        for (const std::string text : {"0x10", "1e", "", " 1", "1,5", "0x1p-1", "Inf"}) {
          const std::string args = sub + " " + (needs.count(sub) ? needs.at(sub) + " " : "") +
                                   (context.count(flag) ? context.at(flag) + " " : "") + flag + " '" + text + "'";
          const auto r = run_cli(args);
          INFO("hertzdash " << args << "\n  stderr: " << r.err);
          CHECK(r.exit_code == 2);
          CHECK(r.err.find("invalid " + flag + " = '" + text + "': must be " + expected) != std::string::npos);
          // The option's own range follows the format: "... 2E9) and > 0 ...".
          if (type == "FLOAT") CHECK(r.err.find("2E9) and ") != std::string::npos);
          CHECK(r.out.empty());
          CHECK_FALSE(std::filesystem::exists(out));
          ++tried;
        }
      }
    }
  }
  // simulate alone has 30 numeric options; fit, bounce, restitution and sweep add theirs.
  CHECK(tried > 7 * 30);
}

namespace {

// A copy of data/ whose tables a test may change, removed afterwards.
struct DataCopy {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hertzdash_data_" + std::to_string(::getpid()));
  DataCopy() {
    namespace fs = std::filesystem;
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& f : fs::directory_iterator(fs::path(HERTZDASH_SOURCE_DIR) / "data"))
      if (f.is_regular_file()) fs::copy_file(f.path(), dir / f.path().filename());
  }
  ~DataCopy() { std::filesystem::remove_all(dir); }
  std::string env() const { return "HERTZDASH_DATA_DIR=" + dir.string(); }
  void append(const std::string& file, const std::string& text) const { std::ofstream(dir / file, std::ios::app) << text; }
  void write(const std::string& file, const std::string& text) const { std::ofstream(dir / file) << text; }
  // The file with every occurrence of `from` replaced by `to`, built piece by piece.
  void replace(const std::string& file, const std::string& from, const std::string& to) const {
    const std::string text = hertzdash::test::slurp(dir / file);
    std::string out;
    for (std::size_t begin = 0;;) {
      const std::size_t at = text.find(from, begin);
      out.append(text, begin, at == std::string::npos ? std::string::npos : at - begin);
      if (at == std::string::npos) break;
      out += to;
      begin = at + from.size();
    }
    write(file, out);
  }
};

}  // namespace

TEST_CASE("CLI: a malformed data table exits 2 naming the file, line and column", "[cli][data]") {
  // Lines count from 1 with the comment lines; columns are 1-based bytes where the field starts.
  const DataCopy data;
  std::vector<std::string> expected;  // every piece must appear in the message
  SECTION("a row with a missing field") {
    data.append("table1_dimensions.csv", "extra-rod,0.025,0.2\n");  // line 9 of 8
    expected = {"table1_dimensions.csv:9:", "expected 5 fields"};
  }
  SECTION("a field that is not a number") {
    data.write("table2_restitution.csv", "rod,e,e_second,zeta_printed,provenance\nsteel,zero point eight,,0.07,x\n");
    expected = {"table2_restitution.csv:2:7: column 'e': 'zero point eight' is not a decimal number"};
  }
  SECTION("a hexadecimal number (strtod read 0x1p-1 as 0.5)") {
    data.replace("table1_dimensions.csv", "steel,0.0250,0.200,0.778", "steel,0.0250,0.200,0x1p-1");
    expected = {"table1_dimensions.csv:5:20: column 'mass_kg': '0x1p-1' is not a decimal number"};
  }
  SECTION("a value out of its range is blamed on the table, not on --restitution") {
    data.replace("table2_restitution.csv", "steel,0.795", "steel,1.5");
    expected = {"table2_restitution.csv:5:7: column 'e': 1.5 is not in (0, 1]"};
  }
  SECTION("an assumed value out of its range") {
    data.replace("assumptions.csv", "nylon_nu,0.40", "nylon_nu,0.5");
    expected = {"assumptions.csv:12:10: column 'value': 0.5 is not in (-1, 0.5)"};
  }
  SECTION("a second steel row") {
    data.append("table1_dimensions.csv", "steel,0.0250,0.200,0.5,a second row\n");
    expected = {"table1_dimensions.csv:9:1: column 'body': 'steel' again (first on line 5); each body appears once"};
  }
  SECTION("a second gravity_mps2 in assumptions.csv") {
    data.append("assumptions.csv", "gravity_mps2,9.81,m/s^2,again,fixed,,,,,again\n");
    expected = {"assumptions.csv:27:1: column 'parameter': 'gravity_mps2' again (first on line 15)"};
  }
  SECTION("a column named twice (the second was read and never used)") {
    data.replace("table2_restitution.csv", "rod,e,e_second,", "rod,e,e,");
    expected = {"table2_restitution.csv:4:7: column 'e' again (first at column 5); each column name appears once"};
  }
  SECTION("a value beyond the range of a double") {
    data.replace("table2_restitution.csv", "steel,0.795", "steel,1e400");
    expected = {"table2_restitution.csv:5:7: column 'e': '1e400' is out of range of double"};
  }
  SECTION("a table with a header and no rows") {
    data.write("table2_restitution.csv", "# no rods\nrod,e,e_second,zeta_printed,provenance\n");
    expected = {"table2_restitution.csv: the table is empty (a header row and no rows below it)"};
  }
  SECTION("an empty file") {
    data.write("table3_properties.csv", "");
    expected = {"table3_properties.csv: the table is empty (no header row, no lines)"};
  }
  SECTION("a table beyond 16 MiB is refused before it is read") {
    std::filesystem::resize_file(data.dir / "assumptions.csv", (std::uintmax_t{16} << 20) + 1);  // sparse
    expected = {"assumptions.csv: 16777217 bytes; a data table is at most 16 MiB"};
  }
  const auto r = run_cli("simulate", data.env());
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  CHECK(r.err.rfind("hertzdash: bad data file: ", 0) == 0);
  CHECK(r.err.find("--") == std::string::npos);  // no command-line option is blamed
  for (const std::string& piece : expected) CHECK(r.err.find(piece) != std::string::npos);
}

TEST_CASE("CLI: data tables with a UTF-8 byte-order mark or CRLF line ends read as without", "[cli][data]") {
  const DataCopy data;
  const auto plain = run_cli("simulate --json", data.env());
  REQUIRE(plain.exit_code == 0);
  for (const char* file : {"table1_dimensions.csv", "table2_restitution.csv", "table3_properties.csv", "assumptions.csv"})
    data.write(file, "\xEF\xBB\xBF" + hertzdash::test::slurp(data.dir / file));
  data.replace("table2_restitution.csv", "\n", "\r\n");
  data.replace("assumptions.csv", "\n", "\r\n");
  const auto marked = run_cli("simulate --json", data.env());
  INFO("stderr: " << marked.err);
  CHECK(marked.exit_code == 0);
  // The results and the inputs are the same; only the data directory's path could differ, and it is not printed.
  CHECK(marked.out == plain.out);
}

TEST_CASE("CLI sweep: each bad case file exits 2 naming the key, its line and what it must be, and writes no file",
          "[cli][sweep]") {
  // The case file's rows of the bad-input matrix (tests/test_sweep.cpp holds the reader's own).
  struct BadCase {
    const char* text;
    const char* message;  // must appear in stderr
  };
  const BadCase cases[] = {
      {"[base]\nmass = 0x10\n", "invalid base.mass (case.toml line 2) = 0x10: must be a decimal number"},
      {"[base]\nmass = 0o10\n", "invalid base.mass (case.toml line 2) = 0o10: must be a decimal number"},
      {"[base]\nmass = 0b10\n", "invalid base.mass (case.toml line 2) = 0b10: must be a decimal number"},
      {"[base]\nmass = nan\n", "invalid base.mass (case.toml line 2) = nan: must be a decimal number"},
      {"[base]\nmass = \"0.5\"\n", "invalid base.mass (case.toml line 2) = \"0.5\": must be a number"},
      {"[grid]\nheight = [0.01, 0x10]\n", "invalid grid.height (case.toml line 2) = 0x10: must be a decimal number"},
      {"[grid]\nheight = { from = 0.01, to = inf, count = 3 }\n", "grid.height.to (case.toml line 2) = inf: must be a finite number"},
      {"[grid]\nheight = { from = 0.01, to = 0.02, count = 0x3 }\n", "grid.height.count (case.toml line 2) = 0x3: must be a decimal number"},
      {"[sample]\ncount = 4\nball-E = { distribution = \"uniform\", min = 0x10, max = 2e9 }\n",
       "sample.ball-E.min (case.toml line 3) = 0x10: must be a decimal number"},
      {"[base]\nmass = 1\nmass = 2\n", "case.toml:3:"},                      // TOML itself: a key twice
      {"[base]\nheight = 1\n[grid]\nheight = [1, 2]\n", "grid.height (case.toml line 4) = a second value"},
      {"[base]\nheigth = 0.01\n", "invalid base.heigth (case.toml line 2) = an unknown option"},
      {"[base\n", "case.toml:1:"},
  };
  const ScratchDir dir;
  const auto out = dir.path / "out.csv";
  for (const BadCase& c : cases) {
    std::ofstream(dir.path / "case.toml") << c.text;
    // Run in the scratch directory, so that the messages name case.toml as given.
    const auto r = run_cli("sweep case.toml --quiet --out " + out.string(), "cd " + dir.path.string() + " &&");
    INFO(c.text << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(out));
    CHECK_FALSE(std::filesystem::exists(dir.path / "case.csv"));
  }
}

TEST_CASE("CLI: each subcommand's own bad input exits 2, names the option and what it must be, writes no file",
          "[cli]") {
  // The rows of the matrix beyond simulate's and bounce's tables above and the numbers of every
  // option (the FLOAT/UINT test). In the arguments OUT is an output file that must not appear, DIR
  // the scratch directory, TRACE a measured trace in it and CASE a case file.
  const ScratchDir dir;
  const std::string out = (dir.path / "out.csv").string(), trace = (dir.path / "trace.csv").string();
  REQUIRE(run_cli("simulate --trace " + trace + " --trace-format measured").exit_code == 0);
  std::ofstream(dir.path / "case.toml") << "[grid]\nheight = [0.01]\n";
  const BadInput cases[] = {
      {"models --bogus", "--bogus", "unknown option --bogus (hertzdash models --help)"},
      {"models extra", "extra", "not expected"},
      {"simulate --mass", "--mass", "1 required FLOAT missing"},
      {"simulate --trace OUT --trace-format bogus", "--trace-format", "one of: model, measured"},
      {"simulate --trace-format measured", "--trace-format", "given with --trace FILE"},
      {"simulate --trace OUT --trace-format measured --channels colour", "--channels", "distinct channels from: force_N"},
      {"simulate --trace OUT --noise 0.1", "--noise", "given only with --trace-format measured"},
      {"simulate --rod-model elastic --accelerometer bottom", "--accelerometer", "given only where a trace is recorded"},
      {"bounce --rod-model elastic --accelerometer bottom", "--accelerometer", "given only where a trace is recorded"},
      {"simulate --trace OUT --trace-format measured --noise 2", "--noise", "in [0, 1]"},
      {"simulate --trace OUT --trace-format measured --sample-rate 0", "--sample-rate", "> 0"},
      {"simulate --trace OUT --trace-format measured --anti-alias 1e9", "--anti-alias", "0 (no filter) or a cut-off in"},
      {"restitution --restitution 0", "--restitution", "in (0, 1]"},
      {"restitution --target-restitution 0", "--target-restitution", "in (0, 1]"},
      {"restitution --target-restitution 1.5", "--target-restitution", "in (0, 1]"},
      // An option the command would replace is refused, not ignored (issue 30).
      {"restitution --target-restitution 0.8 --restitution 0.3", "--restitution", "omitted with --target-restitution"},
      {"restitution --rod-nu 0.3", "--rod-nu", "given only with --rod-E"},
      {"restitution --rod-model elastic", "--rod-model", "rigid for hertzdash restitution"},
      {"bounce --target-interval-restitution 0.8 --restitution 0.3", "--restitution",
       "omitted with --target-interval-restitution"},
      {"simulate --damping kuwabara-kono --viscous-time-constant 1e-5 --restitution 0.5", "--restitution",
       "omitted when --viscous-time-constant is given"},
      {"fit --curves OUT", "--trace", "is required"},
      {"fit --trace DIR/missing.csv --curves OUT", "missing.csv", "cannot read: No such file"},
      {"fit --trace TRACE --curves OUT --fit ball-colour", "--fit", "NAME:LOWER:UPPER with NAME one of"},
      {"fit --trace TRACE --curves OUT --fit ball-E:1e9:0x10", "--fit", "two decimal numbers"},
      {"fit --trace TRACE --curves OUT --fit ball-E:3e9:1e9", "--fit", "LOWER < UPPER"},
      {"fit --trace TRACE --curves OUT --channels colour", "--channels", "distinct channels"},
      {"fit --trace TRACE --curves OUT --resample -1", "--resample", "> 0"},
      {"fit --trace TRACE --curves OUT --rtol 1e-9", "--rtol", "unknown option --rtol"},
      {"sweep --out OUT", "case", "is required"},
      {"sweep DIR/missing.toml --out OUT", "missing.toml", "cannot read the case file"},
      {"sweep CASE --out OUT --threads -1", "--threads", "a decimal integer in [0, 4294967295]"},
      {"sweep CASE --out OUT --bogus", "--bogus", "unknown option --bogus"},
      // A misspelt option names the nearest one (issue 32), also written --name=value.
      {"simulate --heigth 0.02", "--heigth", "unknown option --heigth: did you mean --height? (hertzdash simulate --help)"},
      {"bounce --bounce=3", "--bounce", "did you mean --bounces?"},
  };
  for (const BadInput& c : cases) {
    std::string args;
    const std::pair<std::string, std::string> tokens[] = {
        {"OUT", out}, {"DIR", dir.path.string()}, {"TRACE", trace}, {"CASE", (dir.path / "case.toml").string()}};
    std::istringstream words(c.args);
    for (std::string word; words >> word;) {
      for (const auto& [token, text] : tokens)
        if (word.rfind(token, 0) == 0) word = text + word.substr(token.size());
      args += (args.empty() ? "" : " ") + word;
    }
    const auto r = run_cli(args);
    INFO("hertzdash " << args << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.parameter) != std::string::npos);
    CHECK(r.err.find(c.range) != std::string::npos);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

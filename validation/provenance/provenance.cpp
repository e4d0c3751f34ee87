// provenance: what made the figures and numbers, for the article's provenance line.
//
// Every output file already names the git revision that wrote it. The article adds
// the tool chain: the compiler that built the harness, the SUNDIALS and GSL versions
// it was compiled against (their headers' version macros), Eigen's, and the gnuplot
// that draws the figures (`gnuplot --version`, run here because run_studies.sh runs
// the same gnuplot right after the studies).
//
// What it prints
// --------------
//   OUT/provenance.csv            tool,version: one row per tool
//   GENERATED/provenance.tex      \provGitRevision, \provCompiler, \provSundials,
//                                 \provGsl, \provEigen, \provGnuplot
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/io/provenance.hpp"
#include "validation/common/study_args.hpp"

#include <Eigen/Core>
#include <gsl/gsl_version.h>
#include <sundials/sundials_config.h>

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

#if defined(__clang__)
constexpr const char* compiler = "Clang " __clang_version__;
#elif defined(__GNUC__)
constexpr const char* compiler = "GCC " __VERSION__;
#else
constexpr const char* compiler = "unknown compiler";
#endif

/// The first line `gnuplot --version` prints, e.g. "gnuplot 5.4 patchlevel 4".
std::string gnuplot_version() {
  FILE* pipe = popen("gnuplot --version 2>/dev/null", "r");
  if (!pipe) throw std::runtime_error("cannot run gnuplot --version");
  std::array<char, 256> line{};
  const bool got = std::fgets(line.data(), static_cast<int>(line.size()), pipe) != nullptr;
  const int status = pclose(pipe);
  if (!got || status != 0) throw std::runtime_error("gnuplot --version failed: is gnuplot installed?");
  std::string v = line.data();
  while (!v.empty() && (v.back() == '\n' || v.back() == '\r')) v.pop_back();
  return v;
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);

  struct Tool {
    const char* csv_name;
    const char* macro;  ///< \prov<macro>
    std::string version;
  };
  // The compiler's row first: numpy.genfromtxt guesses a column's type from its first value, and
  // a revision of hexadecimal digits that are all decimal (686273504890) made it an integer
  // column that the later names do not fit (a DeprecationWarning, an error where warnings are).
  const std::vector<Tool> tools{
      {"compiler", "Compiler", compiler},
      {"git_revision", "GitRevision", git_revision()},
      {"sundials", "Sundials", SUNDIALS_VERSION},
      {"gsl", "Gsl", GSL_VERSION},
      {"eigen", "Eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"gnuplot", "Gnuplot", gnuplot_version()},
  };

  CsvWriter csv("Tool chain that built the harness and drew the figures (validation/provenance)", {},
                {"tool", "version"});
  LatexMacros macros("Tool chain for the article's provenance line (validation/provenance)", {});
  for (const Tool& tool : tools) {
    csv.add_row({std::string(tool.csv_name), tool.version});
    macros.add_text(std::string("prov") + tool.macro, latex_escaped(tool.version));
  }
  csv.save(args.out_dir / "provenance.csv");
  macros.save(args.generated_dir / "provenance.tex");
  std::cout << "provenance: " << tools.front().version << ", " << compiler << ", SUNDIALS " << SUNDIALS_VERSION
            << ", GSL " << GSL_VERSION << ", " << tools.back().version << "\n";
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}

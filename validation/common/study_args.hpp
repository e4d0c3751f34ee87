#pragma once
// The command line every study program takes:
//   <study> --out DIR [--generated DIR] [--reduced | --full]
// --out: where CSV data (and the figures drawn from it) go, e.g. paper/figures;
// --generated: where LaTeX fragments go (default: DIR/../generated);
// --reduced: a small, fast version of the study for the pipeline test;
// --full: the full sample size of a study whose `make figures` size is cut to stay within a
//   minute (validation/uncertainty: `make uncertainty`); studies without one run as usual.
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"

#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

struct StudyArgs {
  std::filesystem::path out_dir;
  std::filesystem::path generated_dir;
  bool reduced = false;
  bool full = false;
};

/// Parses the arguments; prints usage and exits with code 2 on bad ones, with code 0 after
/// --help (-h).
StudyArgs parse_study_args(int argc, char** argv);

/// What a study's main does with an exception that ends it (`int main(...) try { ... } catch
/// (const std::exception& e) { return study_failed(argv[0], e); }`): prints
/// "<study>: error: <what>" on stderr and returns exit status 1, where an uncaught exception
/// would abort with a core dump.
int study_failed(const char* program, const std::exception& e);

/// A CSV table of a study and its file name in --out.
struct StudyCsv {
  const char* file;
  const CsvWriter& table;
};

/// What a study's main returns at its end (exit status 0) after writing its outputs, each file
/// atomically, in this order: every CSV table into --out, then into --generated its LaTeX table
/// as `<name>_table.tex` and its macros as `<name>.tex`.
int save_study_outputs(const StudyArgs& args, std::string_view name, const std::vector<StudyCsv>& csvs,
                       const std::string& latex_table, const LatexMacros& macros);

}  // namespace hertzdash

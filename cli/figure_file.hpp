#pragma once
// `--figure FILE` (issue 46): a figure drawn by gnuplot with one of the embedded scripts
// (validation/fit_figure.gp, in the house style of validation/style.gnuplot and output.gnuplot,
// embedded by cli/CMakeLists.txt so an installed program needs no source tree), in the format
// the file's extension names (png, pdf, svg): gnuplot draws in a temporary directory, and the
// figure is written to FILE as every output is (io/atomic_file.hpp), only once gnuplot has succeeded.
#include "hertzdash/io/csv_writer.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hertzdash::cli {

/// "png", "pdf" or "svg" from `path`'s extension (any case); InvalidParameter naming `option` otherwise.
std::string figure_format(const std::string& option, const std::filesystem::path& path);

/// figure_format, and gnuplot on the PATH (before any work: a figure asked for is not lost at
/// the end of a long run); InvalidParameter naming `option` and debian-packages.txt otherwise.
void require_gnuplot(const std::string& option, const std::filesystem::path& path);

/// Draw `script` (an embedded script's name) with the arguments `kind`, the output's base and
/// format, `arguments`, then the CSV files of `data` (written to a temporary directory); gnuplot's failure (it cannot be run, or exits non-zero) throws
/// std::runtime_error with its messages, and leaves no file.
void draw_figure(const std::string& script, const std::string& kind, const std::vector<const CsvWriter*>& data,
                 const std::vector<std::string>& arguments, const std::filesystem::path& path);

/// The same with data files already written (a sweep's outputs).
void draw_figure_from_files(const std::string& script, const std::string& kind, const std::vector<std::filesystem::path>& files,
                 const std::vector<std::string>& arguments, const std::filesystem::path& path);

}  // namespace hertzdash::cli

#pragma once
// What made an output file: the program version, the git revision, the parameters.
#include <string>
#include <utility>
#include <vector>

namespace hertzdash {

/// The version of hertzdash (the CMake project's version).
const char* version();

/// `git describe --always --dirty` of the source tree at build time ("unknown" outside git).
const char* git_revision();

/// Ordered name = value pairs describing a run (units in the names).
using Parameters = std::vector<std::pair<std::string, std::string>>;

/// Header comment lines, each "# key: value" (io/csv_table.hpp reads them back with
/// comment_field): contents (`what`), generator, git_revision, then one line per parameter.
/// No timestamp, so identical runs give identical files.
std::string provenance_header(const std::string& what, const Parameters& parameters);

}  // namespace hertzdash

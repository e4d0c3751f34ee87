#pragma once
// Whether two paths name one file: an output that is the same file as an input or as another
// output would destroy it (`fit --trace t.csv --curves t.csv`). Each front end words the refusal
// in its own spelling (cli/output_files.hpp, the Python module).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// An output that is the same file as an earlier path: the output's index, the other's index
/// (among the inputs, or among the outputs before it) and which.
struct SharedFile {
  std::size_t output;
  std::size_t other;
  bool other_is_input;
};

/// The first output that is the same file as an input or an earlier output: the same device and
/// inode for a file that exists, the same canonical directory and name for one that does not yet,
/// symbolic links followed and hard links found. Empty paths (none given) are skipped; outputs
/// written through (/dev/null, a FIFO, a terminal) replace nothing and may be shared.
std::optional<SharedFile> find_shared_file(const std::vector<std::string>& inputs,
                                           const std::vector<std::string>& outputs);

}  // namespace hertzdash

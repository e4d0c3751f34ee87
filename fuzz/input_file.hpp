#pragma once
// The readers under fuzz take a path: each input is written to a memory file (memfd) that the
// reader opens as /proc/self/fd/N. Nothing touches the disk (a file in /tmp made the CSV
// harness 30 times slower) and nothing is left behind.
#include "hertzdash/io/csv_table.hpp"  // DataError

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/mman.h>
#include <unistd.h>

namespace hertzdash::fuzz {

inline std::filesystem::path input_file(const std::uint8_t* data, std::size_t size) {
  static const int fd = ::memfd_create("hertzdash_fuzz_input", MFD_CLOEXEC);
  static const std::filesystem::path path = "/proc/self/fd/" + std::to_string(fd);
  if (fd < 0 || ::ftruncate(fd, 0) != 0) __builtin_trap();  // the harness is broken: no input can be tested
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::pwrite(fd, data + done, size - done, static_cast<off_t>(done));
    if (n <= 0) __builtin_trap();
    done += static_cast<std::size_t>(n);
  }
  return path;
}

/// What `read` makes of the input, or nothing when it refuses it with a DataError: the one
/// refusal a reader may give (anything else escapes to libFuzzer as a finding).
template <class Read>
auto read_or_refused(Read read, const std::uint8_t* data, std::size_t size)
    -> std::optional<decltype(read(std::filesystem::path{}))> {
  try {
    return read(input_file(data, size));
  } catch (const DataError&) {
    return std::nullopt;
  }
}

/// `text` (what a writer wrote) read again by `read`: a refusal is a finding, for what the writer
/// wrote must read.
template <class Read> auto read_again(Read read, const std::string& text) {
  auto again = read_or_refused(read, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  if (!again) __builtin_trap();
  return *again;
}

}  // namespace hertzdash::fuzz

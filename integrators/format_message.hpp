#pragma once
// Numbers into the integrators' error messages ("did not finish: ..."), printf-style: the
// layer depends on no formatting library.
#include <cstdio>
#include <string>

namespace hertzdash::detail {

/// `pattern` with `values` formatted as by std::snprintf (messages of at most 511 characters).
template <class... Numbers>
std::string format_g(const char* pattern, Numbers... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

}  // namespace hertzdash::detail

#pragma once
// SHA-256 (FIPS 180-4) of a byte string, for the provenance of inputs a file was made from
// (a sweep's case file). A few dozen lines beat a crypto library dependency for one digest.
#include <string>
#include <string_view>

namespace hertzdash {

/// The digest as 64 lower-case hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace hertzdash

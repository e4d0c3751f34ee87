#pragma once
// The one reader of numbers typed by people: command-line options, data tables, measured
// traces, case files. Decimal only: no hexadecimal (0x10, 0x1p-1), no inf or nan words, no
// spaces, the whole text or nothing.
#include <cstdint>
#include <optional>
#include <string_view>

namespace hertzdash {

/// What parse_decimal() accepts, for messages.
inline constexpr const char* decimal_number_format =
    "a decimal number (digits with an optional sign, point and exponent: 0.02, -1.5e-3, 2E9)";

/// The value of `text` if it is, as a whole, a decimal number within the range of a double:
/// [+-] (digits [. [digits]] | . digits) [(e|E) [+-] digits]. Otherwise nothing: an empty
/// text, surrounding spaces, hexadecimal, inf, nan, and a value that overflows or rounds to
/// zero from a nonzero number (1e999, 1e-999).
std::optional<double> parse_decimal(std::string_view text);

/// The value of an option as typed: a decimal number (parse_decimal) or one of the words inf,
/// -inf and nan (what Python prints for float('inf'), float('-inf'), float('nan')), which the
/// option's own validation then accepts or refuses with its range.
std::optional<double> parse_option_number(std::string_view text);

/// The value of `text` if it is, as a whole, decimal digits (no sign) of an integer at most
/// `max`; otherwise nothing.
std::optional<std::uint64_t> parse_decimal_integer(std::string_view text, std::uint64_t max);

}  // namespace hertzdash

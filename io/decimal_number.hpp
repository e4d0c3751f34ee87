#pragma once
// The one reader of numbers typed by people: command-line options, data tables, measured
// traces, case files. Decimal only: no hexadecimal (0x10, 0x1p-1), no inf or nan words, no
// spaces, the whole text or nothing.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace hertzdash {

/// What parse_decimal() accepts, for messages.
inline constexpr const char* decimal_number_format =
    "a decimal number (digits with an optional sign, point and exponent: 0.02, -1.5e-3, 2E9)";

/// The range of a double, for messages about a decimal number beyond it.
inline constexpr const char* double_range_text =
    "magnitude at most 1.7976931348623157e308 and, if nonzero, at least 4.9e-324";

/// The value of `text` if it is, as a whole, a decimal number within the range of a double:
/// [+-] (digits [. [digits]] | . digits) [(e|E) [+-] digits]. Otherwise nothing: an empty
/// text, surrounding spaces, hexadecimal, inf, nan, and a value out of the range of a double.
/// Policy at the ends of the range: a magnitude above DBL_MAX (1e400) overflows and a nonzero
/// number below the smallest subnormal, 4.9e-324, would round to zero (1e-400): both are out of
/// range; a subnormal (between 4.9e-324 and 2.2e-308, 1e-310) is read, with its fewer
/// significant digits, since it is a double; zero with any exponent (0e999) is zero.
std::optional<double> parse_decimal(std::string_view text);

/// Why parse_decimal(text) gives nothing: the text is not a decimal number at all, or it is one
/// out of the range of a double.
enum class DecimalError { not_decimal, out_of_range };
/// nullopt when parse_decimal(text) has a value.
std::optional<DecimalError> decimal_error(std::string_view text);

/// What a message says of such a text, quoted: "'0x10' is not a decimal number (digits ...)" or
/// "'1e400' is out of range of double (magnitude at most ...)".
std::string decimal_refusal(std::string_view text);

/// The value of an option as typed: a decimal number (parse_decimal) or one of the words inf,
/// -inf and nan (what Python prints for float('inf'), float('-inf'), float('nan')), which the
/// option's own validation then accepts or refuses with its range.
std::optional<double> parse_option_number(std::string_view text);

/// The value of `text` if it is, as a whole, decimal digits (no sign) of an integer at most
/// `max`; otherwise nothing.
std::optional<std::uint64_t> parse_decimal_integer(std::string_view text, std::uint64_t max);

}  // namespace hertzdash

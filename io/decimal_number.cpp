#include "hertzdash/io/decimal_number.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <system_error>

namespace hertzdash {

namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The count of digits at text[i...].
std::size_t digits_at(std::string_view text, std::size_t i) {
  std::size_t n = 0;
  while (i + n < text.size() && is_digit(text[i + n])) ++n;
  return n;
}

// Whether `text` (no leading sign) is digits with an optional point and exponent.
bool is_unsigned_decimal(std::string_view text) {
  std::size_t i = digits_at(text, 0);
  std::size_t mantissa_digits = i;
  if (i < text.size() && text[i] == '.') {
    const std::size_t fraction = digits_at(text, i + 1);
    mantissa_digits += fraction;
    i += 1 + fraction;
  }
  if (mantissa_digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    const std::size_t exponent = digits_at(text, i);
    if (exponent == 0) return false;
    i += exponent;
  }
  return i == text.size();
}

}  // namespace

namespace {

struct Parsed {
  std::optional<double> value;
  DecimalError error = DecimalError::not_decimal;  // when there is no value
};

Parsed parse(std::string_view text) {
  const bool negative = !text.empty() && text.front() == '-';
  // std::from_chars takes a minus sign but no plus sign.
  const std::string_view body = !text.empty() && (text.front() == '+' || negative) ? text.substr(1) : text;
  if (!is_unsigned_decimal(body)) return {};
  double v = 0;
  // result_out_of_range: an overflow, or a nonzero number that rounds to zero; subnormals are read.
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), v, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return {std::nullopt, DecimalError::out_of_range};
  if (ec != std::errc() || end != body.data() + body.size() || !std::isfinite(v)) return {};
  return {negative ? -v : v};
}

}  // namespace

std::optional<double> parse_decimal(std::string_view text) { return parse(text).value; }

std::optional<DecimalError> decimal_error(std::string_view text) {
  const Parsed p = parse(text);
  if (p.value) return std::nullopt;
  return p.error;
}

std::string decimal_refusal(std::string_view text) {
  std::string message = "'";  // built piece by piece: GCC 12 warns (-Wrestrict) of "'" + std::string(text)
  message += text;
  if (decimal_error(text) == DecimalError::out_of_range) {
    message += "' is out of range of double (";
    message += double_range_text;
    message += ')';
  } else {
    message += "' is not ";
    message += decimal_number_format;
  }
  return message;
}

std::optional<double> parse_option_number(std::string_view text) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
  return parse_decimal(text);
}

std::optional<std::uint64_t> parse_decimal_integer(std::string_view text, std::uint64_t max) {
  if (text.empty() || digits_at(text, 0) != text.size()) return std::nullopt;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v > max) return std::nullopt;
  return v;
}

}  // namespace hertzdash

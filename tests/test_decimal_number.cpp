// The strict decimal reader every number typed by a person goes through (issue 19: 0x10 was
// read as 16, 0x1p-1 as 0.5, an empty text as 0).
#include "hertzdash/io/decimal_number.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using hertzdash::parse_decimal;

TEST_CASE("decimal numbers are read exactly as the nearest double", "[decimal]") {
  // Each expected value is the C++ literal of the same text: the nearest double.
  CHECK(parse_decimal("0") == 0.0);
  CHECK(parse_decimal("16") == 16.0);
  CHECK(parse_decimal("0.02") == 0.02);
  CHECK(parse_decimal("+0.02") == 0.02);
  CHECK(parse_decimal("-1.5e-3") == -1.5e-3);
  CHECK(parse_decimal("2E9") == 2e9);
  CHECK(parse_decimal("204.0e9") == 204.0e9);
  CHECK(parse_decimal("1e+5") == 1e5);
  CHECK(parse_decimal(".5") == 0.5);
  CHECK(parse_decimal("5.") == 5.0);
  CHECK(parse_decimal("007") == 7.0);  // leading zeros are decimal, not octal
  // The extremes of a double: the largest finite value and the smallest subnormal.
  CHECK(parse_decimal("1.7976931348623157e308") == std::numeric_limits<double>::max());
  CHECK(parse_decimal("4.9406564584124654e-324") == std::numeric_limits<double>::denorm_min());
  CHECK(parse_decimal("1e-308") == 1e-308);
}

TEST_CASE("anything but a whole decimal number is refused", "[decimal]") {
  const char* refused[] = {
      "",       " ",     "0x10",  "0x1p-1", "0X1P-1", "1e",    "1e+",   "e5",    ".",     "-",     "+",
      "+-1",    "--1",   "1..2",  "1.2.3",  " 1",     "1 ",    "1,5",   "1_000", "inf",   "-inf",  "nan",
      "NaN",    "infinity", "1e999", "-1e999", "1e-999", "0b1",  "0o7",   "1d",    "1f",    "١",     "1e5.5",
  };
  for (const char* text : refused) {
    INFO("'" << text << "'");
    CHECK_FALSE(parse_decimal(text).has_value());
  }
}

TEST_CASE("an option's value is a decimal number or one of the words inf, -inf, nan", "[decimal]") {
  using hertzdash::parse_option_number;
  CHECK(parse_option_number("2e9") == 2e9);
  CHECK(parse_option_number("inf") == std::numeric_limits<double>::infinity());
  CHECK(parse_option_number("-inf") == -std::numeric_limits<double>::infinity());
  CHECK(std::isnan(parse_option_number("nan").value()));
  for (const char* text : {"", "0x10", "1e", "Inf", "+inf", "NAN", "infinity", " 1"}) {
    INFO("'" << text << "'");
    CHECK_FALSE(parse_option_number(text).has_value());
  }
}

TEST_CASE("an integer option is decimal digits up to its largest value", "[decimal]") {
  using hertzdash::parse_decimal_integer;
  CHECK(parse_decimal_integer("0", 10) == 0u);
  CHECK(parse_decimal_integer("010", 10) == 10u);
  CHECK(parse_decimal_integer("18446744073709551615", UINT64_MAX) == UINT64_MAX);
  for (const char* text : {"", "11", "-1", "+1", "0x1", "1e1", "1.0", " 1"}) {
    INFO("'" << text << "'");
    CHECK_FALSE(parse_decimal_integer(text, 10).has_value());
  }
  CHECK_FALSE(parse_decimal_integer("18446744073709551616", UINT64_MAX).has_value());  // 2^64
}

TEST_CASE("a decimal number beyond a double is out of range, not 'not a decimal number'", "[decimal]") {
  // DBL_MAX = 1.7976931348623157e308: 1e400 and the next decimal above DBL_MAX's rounding
  // boundary (1.7976931348623159e308) overflow; the smallest subnormal is 4.94e-324, so 2e-324
  // (below half of it) rounds to zero: out of range. 3e-324 rounds to the smallest subnormal
  // and 1e-310 is a subnormal: both are read. Zero with any exponent is zero.
  using hertzdash::DecimalError;
  using hertzdash::decimal_error;
  for (const char* text : {"1e400", "-1e400", "1.7976931348623159e308", "1e-400", "-2e-324"}) {
    INFO(text);
    CHECK_FALSE(parse_decimal(text).has_value());
    CHECK(decimal_error(text) == DecimalError::out_of_range);
    std::string expected = "'";
    expected += text;
    expected += "' is out of range of double (magnitude at most 1.7976931348623157e308 and, if nonzero, at least "
                "4.9e-324)";
    CHECK(hertzdash::decimal_refusal(text) == expected);
  }
  CHECK(parse_decimal("3e-324") == std::numeric_limits<double>::denorm_min());
  CHECK(parse_decimal("1e-310") == 1e-310);
  CHECK(parse_decimal("0e999") == 0.0);
  CHECK_FALSE(decimal_error("1e-310").has_value());
  for (const char* text : {"0x10", "1e", "", "inf"}) {
    INFO(text);
    CHECK(decimal_error(text) == DecimalError::not_decimal);
    CHECK(hertzdash::decimal_refusal(text).find("' is not a decimal number (") != std::string::npos);
  }
}

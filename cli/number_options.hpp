#pragma once
// Numeric command-line options, read through io/decimal_number: a decimal number or one of the
// words inf, -inf, nan (CLI11's own conversion took 0x10 as 16 and an empty text as 0).
// Text that is not a number reads as NaN, which the option's validation refuses with its
// valid range; the text is remembered, so that the refusal shows what was typed and the
// decimal format beside that range (refusal_message). An integer option's range is its type's:
// text that is not a decimal integer within it is refused at once.
#include "hertzdash/model/invalid_parameter.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace hertzdash::cli {

/// --flag writing a number into `value`; the help shows its default.
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, double& value, const std::string& help);
/// --flag writing a number into `value`, which stays empty unless the option is given.
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, std::optional<double>& value,
                               const std::string& help);
/// --flag calling `set` with the number given.
CLI::Option* add_number_option(CLI::App& app, const std::string& flag, std::function<void(double)> set,
                               const std::string& help);
/// --flag writing a decimal integer in [0, max of the type] into `value`; the help shows its default.
CLI::Option* add_integer_option(CLI::App& app, const std::string& flag, std::uint64_t& value, const std::string& help);
CLI::Option* add_integer_option(CLI::App& app, const std::string& flag, unsigned& value, const std::string& help);

/// The message of the refusal `e` in the command line's spelling (--ball-E); for an option whose
/// text was no number, the text and the decimal format beside the range `e` gives.
std::string refusal_message(const InvalidParameter& e);

}  // namespace hertzdash::cli

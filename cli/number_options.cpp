#include "cli/number_options.hpp"

#include "hertzdash/io/decimal_number.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

namespace hertzdash::cli {

namespace {

// The options given a text that is no number: flag -> the text, as typed.
std::map<std::string, std::string>& not_numbers() {
  static std::map<std::string, std::string> texts;
  return texts;
}

double option_number(const std::string& flag, const std::string& text) {
  if (const std::optional<double> v = parse_option_number(text)) {
    not_numbers().erase(flag);
    return *v;
  }
  not_numbers()[flag] = text;
  return NAN;
}

std::uint64_t option_integer(const std::string& flag, const std::string& text, std::uint64_t max) {
  if (const std::optional<std::uint64_t> v = parse_decimal_integer(text, max)) return *v;
  throw InvalidParameter(flag, "'" + text + "'", fmt::format("a decimal integer in [0, {}]", max));
}

template <class T>
CLI::Option* add_integer(CLI::App& app, const std::string& flag, T& value, const std::string& help) {
  return app
      .add_option_function<std::string>(
          flag,
          [&value, flag](const std::string& text) {
            value = static_cast<T>(option_integer(flag, text, std::numeric_limits<T>::max()));
          },
          help)
      ->type_name("UINT")
      ->default_str(std::to_string(value));
}

}  // namespace

CLI::Option* add_number_option(CLI::App& app, const std::string& flag, double& value, const std::string& help) {
  return app
      .add_option_function<std::string>(
          flag, [&value, flag](const std::string& text) { value = option_number(flag, text); }, help)
      ->type_name("FLOAT")
      ->default_str(fmt::format("{}", value));
}

CLI::Option* add_number_option(CLI::App& app, const std::string& flag, std::optional<double>& value,
                               const std::string& help) {
  return app
      .add_option_function<std::string>(
          flag, [&value, flag](const std::string& text) { value = option_number(flag, text); }, help)
      ->type_name("FLOAT");
}

CLI::Option* add_number_option(CLI::App& app, const std::string& flag, std::function<void(double)> set,
                               const std::string& help) {
  return app
      .add_option_function<std::string>(
          flag, [set = std::move(set), flag](const std::string& text) { set(option_number(flag, text)); }, help)
      ->type_name("FLOAT");
}

CLI::Option* add_integer_option(CLI::App& app, const std::string& flag, std::uint64_t& value, const std::string& help) {
  return add_integer(app, flag, value, help);
}

CLI::Option* add_integer_option(CLI::App& app, const std::string& flag, unsigned& value, const std::string& help) {
  return add_integer(app, flag, value, help);
}

std::string refusal_message(const InvalidParameter& e) {
  constexpr KeySpelling cli = KeySpelling::command_line;
  const auto it = not_numbers().find(spell_key(e.key, cli));
  if (it == not_numbers().end()) return e.message(cli);
  const std::string quoted = "'" + it->second + "'";
  if (decimal_error(it->second) == DecimalError::out_of_range)
    return InvalidParameter(e.key, quoted + " (out of range of double)",
                            std::string("a decimal number of ") + double_range_text + ", and " + e.valid_range)
        .message(cli);
  return InvalidParameter(e.key, quoted, std::string(decimal_number_format) + " and " + e.valid_range).message(cli);
}

}  // namespace hertzdash::cli

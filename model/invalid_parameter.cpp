#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace hertzdash {

bool is_parameter_key(std::string_view text) {
  if (text.empty() || !std::isalpha(static_cast<unsigned char>(text.front()))) return false;
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; });
}

namespace {
/// Python's reserved words (keyword.kwlist of Python 3.11) that a key could be: a keyword argument
/// cannot be spelled so, and takes a trailing '_' (`continue`'s `from` is from_=).
constexpr std::string_view python_reserved[] = {"and", "as", "assert", "async", "await", "break", "class", "continue",
                                                "def", "del", "elif", "else", "except", "finally", "for", "from",
                                                "global", "if", "import", "in", "is", "lambda", "nonlocal", "not", "or",
                                                "pass", "raise", "return", "try", "while", "with", "yield"};
}  // namespace

std::string spell_key(std::string_view key, KeySpelling spelling) {
  std::string s(key);
  if (!is_parameter_key(key)) return s;
  switch (spelling) {
    case KeySpelling::key: return s;
    case KeySpelling::command_line: return "--" + s;
    case KeySpelling::python:
      std::replace(s.begin(), s.end(), '-', '_');
      if (std::ranges::find(python_reserved, s) != std::end(python_reserved)) s += '_';
      return s;
  }
  return s;
}

std::string key_reference(std::string_view key) {
  std::string s(1, '`');
  s.append(key);
  s.push_back('`');
  return s;
}

std::string spell_key_references(std::string_view text, KeySpelling spelling) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('`', i);
    const std::size_t close = open == std::string_view::npos ? open : text.find('`', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view inner = text.substr(open + 1, close - open - 1);
    out.append(text.substr(i, open - i));
    // Only a key is respelled; any other quoted text (a command, `hertzdash models`) keeps its quotes.
    out += is_parameter_key(inner) ? spell_key(inner, spelling) : std::string(text.substr(open, close - open + 1));
    i = close + 1;
  }
  out.append(text.substr(std::min(i, text.size())));
  return out;
}

InvalidParameter::InvalidParameter(const std::string& key_, const std::string& value_, const std::string& range)
    : std::invalid_argument("invalid " + key_ + " = " + value_ + ": must be " +
                            spell_key_references(range, KeySpelling::key)),
      key(key_),
      value(value_),
      valid_range(range) {}

std::string InvalidParameter::message(KeySpelling spelling) const {
  return "invalid " + spell_key(key, spelling) + " = " + spell_key_references(value, spelling) +
         ": must be " + spell_key_references(valid_range, spelling);
}

std::string format_value(double v) { return fmt::format("{}", v); }

void require_positive(const std::string& key, double v, const std::string& unit) {
  if (!(std::isfinite(v) && v > 0)) throw InvalidParameter(key, format_value(v), "a finite number > 0 (" + unit + ")");
}

void require_non_negative(const std::string& key, double v, const std::string& unit) {
  if (!(std::isfinite(v) && v >= 0)) throw InvalidParameter(key, format_value(v), "a finite number >= 0 (" + unit + ")");
}

void require_in_open_closed(const std::string& key, double v, double lo, double hi) {
  if (!(v > lo && v <= hi)) throw InvalidParameter(key, format_value(v), fmt::format("in ({}, {}]", lo, hi));
}

void require_in_open(const std::string& key, double v, double lo, double hi) {
  if (!(v > lo && v < hi)) throw InvalidParameter(key, format_value(v), fmt::format("in ({}, {})", lo, hi));
}

}  // namespace hertzdash

#include "validation/common/latex_macros.hpp"

#include "hertzdash/io/atomic_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hertzdash {

LatexMacros::LatexMacros(std::string what, Parameters parameters)
    : what_(std::move(what)), parameters_(std::move(parameters)) {}

void LatexMacros::add(const std::string& name, double value, const std::string& fmt_spec) {
  add_text(name, fmt::format(fmt::runtime(fmt_spec), value));
}

void LatexMacros::add_text(const std::string& name, const std::string& text) {
  if (name.empty() || !std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalpha(c); })) {
    throw std::invalid_argument("LatexMacros: macro name must be letters only: " + name);
  }
  body_ += "\\newcommand{\\" + name + "}{" + text + "}\n";
}

std::string LatexMacros::str() const {
  std::string header = provenance_header(what_, parameters_);
  std::replace(header.begin(), header.end(), '#', '%');
  return header + body_;
}

void LatexMacros::save(const std::filesystem::path& path) const { write_file_atomically(path, str()); }

std::string latex_scientific(double v) {
  if (v == 0) return "$0$";
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(v))));
  const double mantissa = v / std::pow(10.0, exponent);
  if (std::abs(mantissa) >= 9.95) return latex_scientific(std::copysign(std::pow(10.0, exponent + 1), v));
  return fmt::format("${:.1f}\\times 10^{{{}}}$", mantissa, exponent);
}

std::string latex_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '_': case '%': case '&': case '#': case '$': case '{': case '}': out += '\\'; out += c; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '\\': out += "\\textbackslash{}"; break;
      default: out += c;
    }
  }
  return out;
}

std::string number_in_words(int n) {
  static constexpr const char* words[] = {"zero", "one", "two",   "three",  "four",   "five",  "six",
                                          "seven", "eight", "nine", "ten", "eleven", "twelve"};
  if (n < 0) throw std::invalid_argument("number_in_words: negative count " + std::to_string(n));
  return n <= 12 ? words[n] : std::to_string(n);
}

std::string count_of_total_in_words(int count, int total) {
  if (count < 0 || count > total) {
    throw std::invalid_argument(fmt::format("count_of_total_in_words: {} of {} is not a count", count, total));
  }
  if (count == 0) return "none";
  if (count == total) return total == 2 ? "both" : "all";
  return number_in_words(count);
}

std::string latex_macro_part(std::string_view name) {
  std::string out;
  bool upper = true;
  for (const char c : name) {
    if (c == '-') upper = true;
    else out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c, upper = false;
  }
  return out;
}

}  // namespace hertzdash

#pragma once
// Numbers for the paper: a study writes paper/generated/<study>.tex holding
// \newcommand definitions, and the paper \input's it. No hand-typed results.
#include "hertzdash/io/provenance.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace hertzdash {

class LatexMacros {
 public:
  /// `what` and `parameters` go into a comment header with the git revision.
  LatexMacros(std::string what, Parameters parameters);

  /// \newcommand{\<name>}{<value formatted with fmt spec, e.g. "{:.3f}">}; name must be letters only.
  void add(const std::string& name, double value, const std::string& fmt_spec = "{:.4g}");
  /// \newcommand{\<name>}{<text>} (text inserted verbatim).
  void add_text(const std::string& name, const std::string& text);

  std::string str() const;
  void save(const std::filesystem::path& path) const;

 private:
  std::string what_;
  Parameters parameters_;
  std::string body_;
};

/// v as LaTeX math in scientific notation with two significant digits: $5.2\times 10^{-6}$
/// ($0$ for zero).
std::string latex_scientific(double v);

/// A registered name as a part of a macro's name, letters only: "mindlin-no-slip" -> "MindlinNoSlip".
std::string latex_macro_part(std::string_view name);

/// `text` safe as LaTeX text (inside a macro argument or a table cell): the ten characters
/// LaTeX treats specially are escaped, _ % & # $ { } with a backslash, ~ ^ \ as
/// \textasciitilde{}, \textasciicircum{}, \textbackslash{}; every other byte is kept.
std::string latex_escaped(std::string_view text);

/// n >= 0 in words as prose writes it: "zero" to "twelve", digits from 13 on.
std::string number_in_words(int n);

/// How many of `total` things, as the quantifier before "of the ...", worded so that the
/// sentence reads right for every count: "none", "all" ("both" when total is 2), else the
/// number in words. "in \macro{} of the paper's four drops" reads "in none of", "in three of",
/// "in all of". Throws std::invalid_argument unless 0 <= count <= total.
std::string count_of_total_in_words(int count, int total);

}  // namespace hertzdash

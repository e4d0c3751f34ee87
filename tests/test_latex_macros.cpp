// The LaTeX text helpers of validation/common/latex_macros.hpp, which every generated number of the
// article passes through: numbers in scientific notation, and free text escaped.
#include "validation/common/latex_macros.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

using hertzdash::latex_escaped;
using hertzdash::latex_scientific;

TEST_CASE("latex_scientific: two significant digits as math, the mantissa at least 1 and below 10", "[io][latex]") {
  CHECK(latex_scientific(6.4e-14) == "$6.4\\times 10^{-14}$");
  CHECK(latex_scientific(-2.5e3) == "$-2.5\\times 10^{3}$");
  CHECK(latex_scientific(0.0) == "$0$");
  // A mantissa that rounds to 10.0 moves to the next decade: 9.96e-7 reads 1.0e-6, not 10.0e-7.
  CHECK(latex_scientific(9.96e-7) == "$1.0\\times 10^{-6}$");
}

TEST_CASE("latex_escaped: each of LaTeX's ten special characters, and nothing else", "[io][latex]") {
  // The ten characters with a special meaning in LaTeX text:
  // seven are printed by a backslash before them, three need a text command.
  const std::vector<std::pair<std::string, std::string>> special{
      {"_", "\\_"}, {"%", "\\%"}, {"&", "\\&"}, {"#", "\\#"}, {"$", "\\$"}, {"{", "\\{"}, {"}", "\\}"},
      {"~", "\\textasciitilde{}"}, {"^", "\\textasciicircum{}"}, {"\\", "\\textbackslash{}"}};
  for (const auto& [raw, escaped] : special) {
    INFO("character " << raw);
    CHECK(latex_escaped(raw) == escaped);
    CHECK(latex_escaped("a" + raw + "b") == "a" + escaped + "b");
  }
  CHECK(latex_escaped("gnuplot 5.4 patchlevel 4 (m/s, +-1 |x|)") == "gnuplot 5.4 patchlevel 4 (m/s, +-1 |x|)");
  CHECK(latex_escaped("m/s^2, 1_000 {~$5}") ==
        "m/s\\textasciicircum{}2, 1\\_000 \\{\\textasciitilde{}\\$5\\}");
  CHECK(latex_escaped("").empty());
}

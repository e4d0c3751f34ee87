// The LaTeX text helpers of io/latex_macros.hpp, which every generated number of the
// article passes through: numbers in scientific notation, and free text escaped.
#include "hertzdash/io/latex_macros.hpp"

#include <catch2/catch.hpp>

using hertzdash::latex_scientific;

TEST_CASE("latex_scientific: two significant digits as math, the mantissa in [1, 10)", "[io][latex]") {
  CHECK(latex_scientific(6.4e-14) == "$6.4\\times 10^{-14}$");
  CHECK(latex_scientific(-2.5e3) == "$-2.5\\times 10^{3}$");
  CHECK(latex_scientific(0.0) == "$0$");
  // A mantissa that rounds to 10.0 moves to the next decade: 9.96e-7 reads 1.0e-6, not 10.0e-7.
  CHECK(latex_scientific(9.96e-7) == "$1.0\\times 10^{-6}$");
}

// Counts in the article's prose: a generated count goes into a sentence as words that read
// right for every value it can take ("in none of the paper's four drops", "in three of ...",
// "in all of ..."), never as a digit dropped into a sentence written for one value.
#include "validation/common/latex_macros.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

using hertzdash::count_of_total_in_words;
using hertzdash::number_in_words;

TEST_CASE("count_of_total_in_words: every count of four reads right before \"of the paper's four drops\"",
          "[io][latex]") {
  const char* expected[] = {"none", "one", "two", "three", "all"};
  for (int count = 0; count <= 4; ++count) {
    INFO("count " << count);
    CHECK(count_of_total_in_words(count, 4) == expected[count]);
  }
  // The sentence the yield study's macro goes into, for every value.
  const auto sentence = [](int count) { return "in " + count_of_total_in_words(count, 4) + " of the paper's four drops"; };
  CHECK(sentence(0) == "in none of the paper's four drops");
  CHECK(sentence(3) == "in three of the paper's four drops");
  CHECK(sentence(4) == "in all of the paper's four drops");
}

TEST_CASE("count_of_total_in_words: two of two are both, and a count outside 0..total is refused", "[io][latex]") {
  CHECK(count_of_total_in_words(2, 2) == "both");
  CHECK(count_of_total_in_words(1, 2) == "one");
  CHECK(count_of_total_in_words(0, 2) == "none");
  CHECK_THROWS_AS(count_of_total_in_words(5, 4), std::invalid_argument);
  CHECK_THROWS_AS(count_of_total_in_words(-1, 4), std::invalid_argument);
}

TEST_CASE("number_in_words: words to twelve, digits above, as prose writes numbers", "[io][latex]") {
  CHECK(number_in_words(0) == "zero");
  CHECK(number_in_words(4) == "four");
  CHECK(number_in_words(12) == "twelve");
  CHECK(number_in_words(13) == "13");
  CHECK_THROWS_AS(number_in_words(-1), std::invalid_argument);
}

// The case-file keys are the option table's (simulation/options/run_options.hpp): every option, set in
// a case file's [base] under its key, is given with the value written, or refused by its key
// where a sweep cannot read it (built with TOML only; tests/CMakeLists.txt).
#include "hertzdash/simulation/sweep/sweep_case.hpp"
#include "tests/parameter_samples.hpp"

#include <catch2/catch.hpp>

using namespace hertzdash;

using test::is_selection;

TEST_CASE("a case file takes every option under its key", "[parameters][sweep]") {
  for (const RunOption& o : run_options()) {
    if (is_selection(o)) continue;
    RunOptions expected;
    test::set_sample(expected, o);
    const std::string value = given_text(expected, o);
    const std::string toml = o.decl.type == ParameterType::text ? "\"" + value + "\"" : value;
    INFO(o.name << " = " << toml);
    const std::string text = "[base]\n" + o.name + " = " + toml + "\n";
    if (o.readers.trace_only || o.readers.flights_only) {  // a sweep records no trace, follows no flight: refused
      CHECK_THROWS_WITH(parse_sweep_case(text, "case.toml"), Catch::StartsWith("invalid base." + o.name + " "));
      continue;
    }
    const SweepCase c = parse_sweep_case(text, "case.toml");
    CHECK(is_given(c.base, o));
    CHECK(given_text(c.base, o) == value);
  }
}


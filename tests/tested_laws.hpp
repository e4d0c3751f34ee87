#pragma once
// The laws every standard check runs on: every registered law (model/damping/registered_laws.cmake)
// plus the worked example of model/README.md (tests/example_law.hpp), and HERTZDASH_LAW_TEST_CASE,
// which registers a check once per law, named after it. A newly registered law is checked without
// touching the tests.
#include "example_law.hpp"
#include "hertzdash/model/damping/registered_law_types.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <tuple>
#include <type_traits>

namespace hertzdash::test {

template <class List, class Extra> struct AppendLaw;
template <class... L, class Extra> struct AppendLaw<LawList<L...>, Extra> {
  using type = std::tuple<L..., Extra>;
};

/// Every registered law, then the guide's example: a newly registered law is checked
/// without touching the tests.
using TestedLaws = AppendLaw<RegisteredLaws, ExactHertzDashpot>::type;

/// Registers `check<Law>` as the Catch test case "NAME - LAW" (LAW the law's registered name,
/// `info.name`) for every Law of the tuple `Laws`: each law's failures are reported and
/// selectable by name (Catch's TEMPLATE_LIST_TEST_CASE would number them "NAME - 15"). Used
/// through HERTZDASH_LAW_TEST_CASE.
template <class Laws, template <class> class Check> bool register_law_tests(const char* name, const char* tags,
                                                                            const char* file, std::size_t line) {
  [&]<class... L>(std::type_identity<std::tuple<L...>>) {
    (Catch::AutoReg(Catch::makeTestInvoker(&Check<L>::run), Catch::SourceLineInfo(file, line), Catch::StringRef(),
                    Catch::NameAndTags{Catch::StringRef(std::string(name) + " - " + std::string(L::info.name)),
                                       Catch::StringRef(tags)}),
     ...);
  }(std::type_identity<Laws>{});
  return true;
}

/// A check run for each law of `Laws`, one test case per law named after it:
///   HERTZDASH_LAW_TEST_CASE(NoEnergyGain, TestedLaws, "Every law: no energy gain", "[damping]") {
///     ... TestType is the law ...
///   }
#define HERTZDASH_LAW_TEST_CASE(Check, Laws, name, tags)                                                              \
  template <class TestType> struct Check {                                                                          \
    static void run();                                                                                              \
  };                                                                                                                \
  [[maybe_unused]] static const bool Check##_registered =                                                           \
      hertzdash::test::register_law_tests<Laws, Check>(name, tags, __FILE__, static_cast<std::size_t>(__LINE__)); \
  template <class TestType> void Check<TestType>::run()

}  // namespace hertzdash::test

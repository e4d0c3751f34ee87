#pragma once
// A valid sample value of every option, for the tests that walk the option table
// (tests/test_parameter_schema.cpp, tests/test_sweep_case_keys.cpp).
#include "hertzdash/simulation/options/run_options.hpp"
#include "tests/elastic_rod_support.hpp"  // test::paper()

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace hertzdash::test {

// The options that choose what runs; every run reads them, and the matrix varies them.
inline bool is_selection(const RunOption& o) {
  return o.name == "rod" || o.name == "damping" || o.name == "rod-model" || o.name == "integrator";
}

// A valid value of option o that differs from its default, set into `options`:
// - a fittable number: 1.1 times its default in the run, where that is finite and not zero (a
//   10 % change keeps every default impact of the paper's rods inside the Hertz model's domain:
//   X stays far below R);
// - the other numbers, by their meaning: a yield stress of 1e8 Pa, 2 elements, a reference speed
//   of 1 m/s, a step of 1e-7 s (below t_H / 1000 of every default impact, ~1.2e-3 s), tolerances
//   of 1e-6 and 1e-10, a largest step of 1e-5 s, a time constant of 1 us, a damping rate of 100/s
//   (lee-herrmann's: the steel rod's impact at 20 mm has v0/X ~ 2600/s, so light damping), a linear contact
//   stiffness of 1e6 N/m (the matched one, m v0^2 / X^2, is ~7e5 N/m for the steel rod at 20 mm),
//   air of 1.2 kg/m^3 and a drag coefficient of 0.5;
// - a text: a choice other than the default; a flag: on.
inline void set_sample(RunOptions& options, const RunOption& o) {
  switch (o.decl.type) {
    case ParameterType::flag: set_flag(options, o, true); return;
    case ParameterType::text: {
      const std::vector<std::string> choices = split_option_list(std::string(o.decl.choices));
      for (std::string c : choices) {
        c.erase(0, c.find_first_not_of(' '));
        if (c != o.decl.default_value && c != "self-consistent" && c != "contact-time") {
          set_text(options, o, c);
          return;
        }
      }
      FAIL("no second choice for " << o.name);
      return;
    }
    case ParameterType::number: break;
  }
  if (o.value_in_setup) {
    RunOptions reading = options;
    reading.rod_model = "elastic";  // the elastic rod's inputs have their defaults only there
    if (!o.readers.laws.empty()) reading.damping = o.readers.laws.front();
    const std::optional<double> v = o.value_in_setup(resolve_setup(reading, paper()));
    if (v && std::isfinite(*v) && *v != 0) {
      set_number(options, o, std::min(1.1 * *v, std::nextafter(o.decl.range.hi, 0.0)));
      return;
    }
  }
  const std::map<std::string, double> by_meaning{{"ball-yield-stress", 1e8}, {"rod-elements", 2},
                                                 {"reference-velocity", 1.0}, {"dt", 1e-7},
                                                 {"rtol", 1e-6},              {"atol", 1e-10},
                                                 {"max-step", 1e-5},          {"viscous-time-constant", 1e-6},
                                                 {"damping-rate", 100},
                                                 {"linear-stiffness", 1e6},   {"rod-damping-ratio", 0.01},
                                                 {"cell-damping-ratio", 0.05}, {"air-density", 1.2},
                                                 {"drag-coefficient", 0.5}, {"density", 7800}};
  const auto it = by_meaning.find(o.name);
  if (it == by_meaning.end()) FAIL("no sample value for " << o.name);
  set_number(options, o, it->second);
}

}  // namespace hertzdash::test

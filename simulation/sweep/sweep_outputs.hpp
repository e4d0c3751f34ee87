#pragma once
// The quantities a sweep can record per run (the `columns` of a case file's [output]): the result
// fields a sweep reports (simulation/run/result_fields.hpp), in the table's order, each read from the
// run's ImpactSummary and set-up. A quantity a run does not have (the elastic rod's energies in a
// rigid-rod run) is NaN, left empty in the CSV.
#include "hertzdash/simulation/run/result_fields.hpp"

#include <algorithm>
#include <string_view>

namespace hertzdash {

using SweepOutput = ResultField;

inline constexpr auto sweep_output_table = result_fields_reported<&ResultReports::sweep>();
// By type, not by `value != nullptr`: GCC does not take a function's address compared with null
// as a constant expression under -fsanitize (make sanitize).
static_assert(std::ranges::all_of(sweep_output_table,
                                  [](const SweepOutput& o) {
                                    return o.type == ResultType::number || o.type == ResultType::number_or_null ||
                                           o.type == ResultType::integer || o.type == ResultType::boolean;
                                  }),
              "a sweep column is a number");

/// The output called `name`, or nullptr.
inline const SweepOutput* find_sweep_output(std::string_view name) {
  for (const SweepOutput& o : sweep_output_table)
    if (o.name == name) return &o;
  return nullptr;
}

}  // namespace hertzdash

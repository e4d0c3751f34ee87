#pragma once
// The ranges of the values the data tables hold (data/*.csv, data/external/), checked where a
// table is read so that a bad value is blamed on its file, line and column, not on the
// command-line option it is the default of.
#include "hertzdash/io/csv_table.hpp"

namespace hertzdash::table_ranges {

inline constexpr ValueRange positive{[](double v) { return v > 0; }, "> 0"};
inline constexpr ValueRange non_negative{[](double v) { return v >= 0; }, ">= 0"};
inline constexpr ValueRange restitution{[](double v) { return v > 0 && v <= 1; }, "in (0, 1]"};
inline constexpr ValueRange poisson_ratio{[](double v) { return v > -1 && v < 0.5; }, "in (-1, 0.5)"};
inline constexpr ValueRange damping_ratio{[](double v) { return v >= 0 && v < 1; }, "in [0, 1)"};

}  // namespace hertzdash::table_ranges

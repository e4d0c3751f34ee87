#pragma once
// The distributions of the paper's unstated and measured inputs, read from the columns
// distribution, location, scale, lower, upper, distribution_reason of data/assumptions.csv:
//
//   distribution  location  scale        lower, upper      the input is
//   fixed         -         -            -                 its `value`, not varied (the reason says why)
//   uniform       -         -            min, max          uniform on [min, max]
//   normal        mean      sd           optional bounds   normal, truncated to [lower, upper] if given
//   lognormal     median    sd of ln X   optional bounds   lognormal (log_mean = ln median), truncated likewise
//
// Every row states its reason in distribution_reason, and the assumed `value` lies within the
// distribution's support. A row that breaks any of this is a DataError naming the file, the line
// and the parameter.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/uncertainty/input_distribution.hpp"

#include <string>
#include <vector>

namespace hertzdash {

/// One varied input of data/assumptions.csv.
struct UncertainInput {
  std::string parameter;            ///< the row's name, e.g. nylon_E_Pa
  std::string unit;                 ///< SI unit or "-"
  double value = 0;                 ///< the value every other study assumes
  InputDistribution distribution;   ///< the joint study's draw (inputs are independent)
  std::string reason;               ///< why this distribution
};

/// The rows of `assumptions` (data/assumptions.csv) that are not `fixed`, in file order.
/// Throws DataError naming the file, line and parameter of a malformed row.
std::vector<UncertainInput> read_uncertain_inputs(const CsvTable& assumptions);

}  // namespace hertzdash

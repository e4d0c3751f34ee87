#pragma once
// Restitution tables: the coefficient of restitution measured against the impact speed (issue
// 33), the format of data/measurements/README.md ("Restitution tables"): the columns
// impact_speed_m_per_s and e, optionally e_sd (the standard deviation of one e) and
// contact_time_s; header lines "# source: ..." (required: provenance) and "# synthetic:
// true|false" (default false), above or below the column names (io/csv_table.hpp); one row per
// trial, a speed repeated for repeated trials. No measured table ships (none was found with a
// source and a licence); the tests write synthetic ones.
#include "hertzdash/io/provenance.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hertzdash {

/// One restitution table, in SI. e_sd is empty when the file has no e_sd column (one common
/// scatter is then estimated by a fit), else one value per row; contact_time_s is empty without
/// its column, else one value per row, NaN where a row's field is empty.
struct RestitutionTable {
  std::filesystem::path path;
  std::string source;      ///< provenance: who measured it, where it was published
  bool synthetic = false;  ///< true for a made-up table (tests, demonstrations)
  std::vector<double> impact_speed_mps, e, e_sd, contact_time_s;

  std::size_t rows() const { return e.size(); }
  bool has_sd() const { return !e_sd.empty(); }
};

/// The columns of the format: the two required, then the optional ones.
const std::vector<std::string>& restitution_table_columns();

/// Read and check one file; throws DataError naming the file (and FILE:LINE:COL of a bad field):
/// a missing `source`, a `synthetic` other than true or false, an unknown or missing column, a
/// field that is not a decimal number or outside its range (impact_speed_m_per_s > 0, e in
/// (0, 1], e_sd > 0, contact_time_s > 0; e_sd in every row, contact_time_s may be empty), fewer
/// than two rows.
RestitutionTable read_restitution_table(const std::filesystem::path& path);

/// The file of `t` in the format: the column names (the optional ones where `t` has them), the
/// source and synthetic lines, provenance_header(what, parameters) without those keys, the rows.
std::string restitution_table_text(const RestitutionTable& t, const std::string& what, const Parameters& parameters);

/// restitution_table_text written atomically to `path`.
void write_restitution_table(const std::filesystem::path& path, const RestitutionTable& t, const std::string& what,
                             const Parameters& parameters);

}  // namespace hertzdash

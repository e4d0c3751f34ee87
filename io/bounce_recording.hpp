#pragma once
// Bounce recordings: the times of the successive impacts of a dropped body (issue 33), as an
// acoustic stopwatch or a phone app detects them; the format of data/measurements/README.md
// ("Bounce recordings"): the columns impact_time_s (or impact_time_ms, read into seconds),
// optionally drop (without it the file is one drop, labelled "1") and drop_height_m; header
// lines "# source: ..." (required: provenance) and "# synthetic: true|false" (default false),
// above or below the column names (io/csv_table.hpp); one row per detected impact. A file may
// hold many drops (heights, trials), each named by its `drop` label, each on a clock of its own
// (any origin). The reader keeps the rows as given: a time that goes backwards, a doubled or a
// missed detection are the data's, found and named by simulation/fit/bounce_recording_check.hpp,
// not refused here. No measured recording ships; the tests write synthetic ones.
#include "hertzdash/io/provenance.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hertzdash {

/// One drop of a recording: its detected impacts in the file's order.
struct RecordedDrop {
  std::string label;                  ///< the `drop` field, trimmed (plain_label)
  std::vector<double> impact_time_s;  ///< the detected impact times [s], in the file's order
  std::vector<std::string> where;     ///< "FILE:LINE" of each time's row, for messages
  double drop_height_m = 0;           ///< the drop height [m] where given, else 0 (unknown)
};

/// One bounce recording, in SI.
struct BounceRecording {
  std::filesystem::path path;
  std::string source;      ///< provenance: who recorded it, how, where published
  bool synthetic = false;  ///< true for a made-up recording (tests, demonstrations)
  std::vector<RecordedDrop> drops;  ///< in the order of their first row

  std::size_t impacts() const;  ///< rows, over every drop
};

/// Whether `label` may label a drop: non-empty, without commas, double quotes, '#' or control
/// characters (written as it is, every CSV reader reads it back the same).
bool plain_label(const std::string& label);

/// The columns of the format: drop, the two time columns (one of them required), the height.
const std::vector<std::string>& bounce_recording_columns();

/// Read and check one file; throws DataError naming the file (and FILE:LINE:COL of a bad field):
/// a missing `source`, a `synthetic` other than true or false, an unknown or missing column (no
/// time column, or both), a
/// `drop` label that is empty or not plain_label (after trimming blanks), an impact time that is not a finite decimal number, a drop_height_m that
/// is not a finite number > 0 or differs between two rows of one drop (an empty field is
/// allowed: not given), no rows.
BounceRecording read_bounce_recording(const std::filesystem::path& path);

/// The file of `r` in the format: the column names (drop_height_m where a drop has one), the
/// source and synthetic lines, provenance_header(what, parameters) without those keys, the rows
/// drop by drop.
std::string bounce_recording_text(const BounceRecording& r, const std::string& what, const Parameters& parameters);

/// bounce_recording_text written atomically to `path`.
void write_bounce_recording(const std::filesystem::path& path, const BounceRecording& r, const std::string& what,
                            const Parameters& parameters);

}  // namespace hertzdash

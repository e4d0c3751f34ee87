#pragma once
// What every front end prints of a rig's run (simulation/rigs/rig.hpp), made from the rig's
// schemas alone: the JSON object (`hertzdash RIG --json`, Python's hertzdash.run), the text
// report, and the per-impact table as CSV below its provenance.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash {

/// "schema_version", the scalars present before the table (a field "group.key" as the member key
/// of the object group), the table's columns as arrays (a labelled column as its labels), the
/// scalars after the table, "end_reason", "warnings", "work" {steps, rhs_evaluations} where the
/// run integrated, "inputs", "git_revision".
nlohmann::ordered_json to_json(const Rig& rig, const RigResult& result);

/// "hertzdash RIG: heading", a line per scalar marked `text` that the run has, the table (a row per
/// impact, "n" first), "ended: reason" and the integrators' work.
std::string rig_text(const Rig& rig, const RigResult& result);

/// The table as CSV: its columns "n" and the rig's table columns (a labelled column as its index),
/// below the provenance (the run's inputs) and a comment "name: value" per scalar the run has and
/// per warning ("warning: ...").
CsvWriter rig_table_csv(const Rig& rig, const RigResult& result);

}  // namespace hertzdash

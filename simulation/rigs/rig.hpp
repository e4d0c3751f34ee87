#pragma once
// A rig: an experiment every front end runs by name (`hertzdash RIG`, Python's
// hertzdash.run("RIG", ...) and hertzdash.RIG(...), a case file's `rig = "RIG"`). It is declared
// once: a name, a one-line summary, an input schema (its own ParameterDecls, model/parameter.hpp,
// and the options of a run, simulation/options/run_options.hpp, that it does not read), a result
// schema (scalar fields: name with unit, unit, meaning, accessor, like simulation/run/
// result_fields.hpp), a per-impact table schema (columns with units and accessors) and a run
// function (validated inputs -> the rig's own result). make_rig() turns that into a Rig, whose
// run gives the generic RigResult every front end prints (simulation/reports/rig_report.hpp).
// The registered rigs are listed in simulation/rigs/rig_table.cpp, one line each.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hertzdash {

/// A rig's own inputs as given, by declared key ("gamma", "impact-model"); unset: the default.
struct RigInputs {
  std::map<std::string, double, std::less<>> numbers;
  std::map<std::string, std::string, std::less<>> texts;
  std::optional<double> number(std::string_view key) const;
  std::optional<std::string> text(std::string_view key) const;
  /// The number given for `d`, else its default_number.
  double number_or_default(const ParameterDecl& d) const;
};

/// A scalar result: absent (this run has none: left out everywhere), a number (NaN: JSON null),
/// a count, or a text.
using RigValue = std::variant<std::monostate, double, long, std::string>;

/// One scalar field of a rig's result. A name "group.key" is the member `key` of the JSON
/// object `group` (written "group_key" where a flat name is needed: a CSV column, a comment).
struct RigField {
  std::string_view name;     ///< the key, its unit in it ("amplitude_m")
  std::string_view unit;     ///< SI unit; "1" dimensionless; empty for a text or a count
  std::string_view meaning;  ///< one sentence (docs, Python's help)
  bool text = true;          ///< a line of the text report
  bool after_table = false;  ///< in the JSON after the per-impact arrays, not before
  bool number = true;        ///< a number or a count (a column of a sweep's rows), not a text
};

/// A field's name where a flat name is needed: "energy_J.initial" -> "energy_J_initial".
std::string flat_name(std::string_view name);

/// One column of a rig's per-impact table. A column with labels holds an index into them: the
/// JSON and the text show the label, the CSV the index.
struct RigColumn {
  std::string_view name, unit, meaning;
  std::string_view labels = {};  ///< "floor, ceiling"; empty: a number
  bool integer = false;          ///< a count or index: written without a fraction
};

/// What every front end prints of one run.
struct RigResult {
  std::string heading;                    ///< the text report's first line after "hertzdash RIG: "
  std::vector<RigValue> scalars;          ///< one per field of Rig::results
  std::vector<std::vector<double>> rows;  ///< the per-impact table, one cell per column of Rig::table
  std::vector<std::string> warnings;
  std::string end_reason;
  std::optional<IntegrationStats> work;   ///< the integrators' work, where the run integrated
  Parameters inputs;                      ///< the run's resolved inputs (provenance, "inputs")
};

/// What an option of a run (run_options()) means in a rig, where that differs from its own help.
struct RigOptionNote {
  std::string_view key, help;
};

/// The column of a rig's input: its Python keyword and unit ("stiffness_N_per_m", "gamma").
std::string input_column(const ParameterDecl& d);

/// A rig's run's recorded inputs: describe_run() without the options it does not read
/// (`not_read`: its run_options_not_read), to which the rig appends its own by input_column().
Parameters describe_rig_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                            std::span<const std::string_view> not_read);

/// A rig's impact sequence as its run would start it, for its periodic orbits
/// (simulation/rigs/rig_orbit.hpp): the sequence, the text report's heading and the run's inputs.
struct RigSequence {
  SequenceSetUp sequence;
  std::string heading;
  Parameters inputs;
};
using RigSequenceMaker = RigSequence (*)(const RunOptions&, const PaperParameters&, const RigInputs&);

/// A registered rig, its schemas and its run, as every front end sees it.
struct Rig {
  std::string_view name, summary;
  ParameterDecls inputs;  ///< its own inputs, in the order of the options
  /// The options of a run (run_options()) it does not read, refused with `not_read_because`.
  std::span<const std::string_view> run_options_not_read;
  std::string_view not_read_because;
  std::span<const RigOptionNote> run_option_notes;
  std::string_view default_integrator;  ///< empty: RunOptions' own
  /// The options of a run its instantaneous impacts read (the rest are refused with them; the
  /// help of `orbit RIG` lists these alone); empty: the rig has no instantaneous impacts.
  std::span<const std::string_view> instantaneous_reads;
  /// The rig's refusals of inputs given together (`gamma` with `amplitude`), read before any run;
  /// null: none. Throws InvalidParameter naming the key.
  void (*refuse)(const RunOptions&, const RigInputs&) = nullptr;
  std::vector<RigField> results;
  std::string_view table_description;  ///< what a row of the table is (the CSV's first line)
  std::vector<RigColumn> table;
  /// Validated inputs -> result: refuses bad input with InvalidParameter naming the key.
  std::function<RigResult(const RunOptions&, const PaperParameters&, const RigInputs&)> run;
  /// Its impact sequence from validated inputs, a box in prescribed motion (null: the rig has none
  /// to analyse; a variant with a box of its own is refused by the maker, naming its input).
  RigSequenceMaker sequence = nullptr;
  /// Its contacts are the rigid rod's in regularising variables (the impact-sequence rigs): its
  /// help leaves out the tension clamp and the options only other integrators read. False for a
  /// rig that runs one impact as `simulate` does, with any integrator.
  bool regularized_contacts = true;
};

/// Every registered rig (simulation/rigs/rig_table.cpp), in the order of the CLI's commands.
std::span<const Rig> rigs();
/// The rig called `name`, or nullptr.
const Rig* find_rig(std::string_view name);

/// A rig's declared input called `key`, or nullptr.
const ParameterDecl* find_rig_input(const Rig& rig, std::string_view key);

/// For a rig whose sphere meets its counterpart at `impact-velocity` in free space (no drop, no
/// preset body): the options given checked, then the speed and the sphere's mass (or density)
/// required, refused naming `impact-velocity` (`speed_is`: what it is here) or `mass`
/// (`whose_mass`: "the first sphere's").
void require_free_sphere(const RunOptions& options, std::string_view speed_is, std::string_view whose_mass);

/// Checks `inputs` against `rig`'s declarations (a key it does not declare, a number outside its
/// range, a text not among its choices), `options` against run_options_not_read, then the rig's
/// own refusals (Rig::refuse). Reads no file and runs nothing: a case file checks it when read.
void check_rig_inputs(const Rig& rig, const RunOptions& options, const RigInputs& inputs);
/// check_rig_inputs(), then the rig's run.
RigResult run_rig(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs);

/// A scalar field with its accessor into the rig's own result type `Run`.
template <class Run>
struct RigFieldOf {
  RigField field;
  RigValue (*value)(const Run&);
};

/// A table column with its accessor into the rig's own impact type `Impact`.
template <class Impact>
struct RigColumnOf {
  RigColumn column;
  double (*value)(const Impact&);
};

/// A rig as its file declares it: schemas with accessors into its own result type `Run`, whose
/// kept impacts (`run.run.impacts`, the driver's) are of type `Impact`, and `outcome(run)` gives
/// the rest of the generic result (heading, warnings, end reason, work, inputs; not scalars and rows).
template <class Run, class Impact>
struct RigDefinition {
  std::string_view name, summary;
  ParameterDecls inputs;
  std::span<const std::string_view> run_options_not_read;
  std::string_view not_read_because;
  std::span<const RigOptionNote> run_option_notes;
  std::string_view default_integrator;
  std::span<const std::string_view> instantaneous_reads = {};
  void (*refuse)(const RunOptions&, const RigInputs&);
  std::span<const RigFieldOf<Run>> results;
  std::string_view table_description;
  std::span<const RigColumnOf<Impact>> table;
  Run (*run)(const RunOptions&, const PaperParameters&, const RigInputs&);
  RigResult (*outcome)(const Run&);
  RigSequenceMaker sequence = nullptr;
  bool regularized_contacts = true;
};

/// The Rig of a definition: its schemas without accessors, its run tabulated through them.
template <class Run, class Impact>
Rig make_rig(const RigDefinition<Run, Impact>& d) {
  Rig rig{.name = d.name, .summary = d.summary, .inputs = d.inputs, .run_options_not_read = d.run_options_not_read,
          .not_read_because = d.not_read_because, .run_option_notes = d.run_option_notes,
          .default_integrator = d.default_integrator, .instantaneous_reads = d.instantaneous_reads, .refuse = d.refuse, .results = {}, .table_description = d.table_description,
          .table = {}, .run = {}, .sequence = d.sequence, .regularized_contacts = d.regularized_contacts};
  for (const auto& f : d.results) rig.results.push_back(f.field);
  for (const auto& c : d.table) rig.table.push_back(c.column);
  rig.run = [d](const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs) {
    const Run run = d.run(options, paper, inputs);
    RigResult r = d.outcome(run);
    for (const auto& f : d.results) r.scalars.push_back(f.value(run));
    for (const Impact& i : run.run.impacts) {
      std::vector<double>& row = r.rows.emplace_back();
      for (const auto& c : d.table) row.push_back(c.value(i));
    }
    return r;
  };
  return rig;
}

}  // namespace hertzdash

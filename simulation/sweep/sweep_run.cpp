#include "hertzdash/simulation/sweep/sweep_run.hpp"

#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/io/sha256.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/sweep/sweep_outputs.hpp"

#include <gsl/gsl_statistics_double.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

namespace hertzdash {

namespace {

// One simulator per distinct solver setting a thread meets (a case may vary the integrator).
struct SimulatorCache {
  std::vector<std::pair<SolverSettings, std::unique_ptr<ImpactSimulator>>> simulators;

  ImpactSimulator& operator()(const SolverSettings& s) {
    for (auto& [settings, sim] : simulators)
      if (settings == s) return *sim;
    simulators.emplace_back(s, std::make_unique<ImpactSimulator>(s));
    return *simulators.back().second;
  }
};

CsvWriter::Cell cell(const SweepValue& v) {
  if (const double* d = std::get_if<double>(&v)) return *d;
  if (const bool* b = std::get_if<bool>(&v)) return std::string(*b ? "true" : "false");
  return std::get<std::string>(v);
}

std::string text(const SweepValue& v) {
  if (const double* d = std::get_if<double>(&v)) return fmt::format("{}", *d);
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  return std::get<std::string>(v);
}

Parameters case_parameters(const SweepCase& c) {
  return {{"case_file", c.source}, {"case_sha256", sha256_hex(c.text)}, {"runs", std::to_string(c.size())}};
}

void add_case_text(CsvWriter& csv, const SweepCase& c) {
  csv.add_comment("case file as read:");
  std::size_t begin = 0;
  while (begin < c.text.size()) {
    std::size_t end = c.text.find('\n', begin);
    if (end == std::string::npos) end = c.text.size();
    std::string line = c.text.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    csv.add_comment("| " + line);
    begin = end + 1;
  }
}

// The grid axes that group the summary: the text and true/false ones (laws, rods, integrators).
std::vector<std::size_t> group_axes(const SweepCase& c) {
  std::vector<std::size_t> axes;
  for (std::size_t k = 0; k < c.grid.size(); ++k)
    if (!std::holds_alternative<double>(c.grid[k].values.front())) axes.push_back(k);
  return axes;
}

struct SummaryRow {
  std::vector<std::string> group;  ///< the values of the group axes
  std::string output;
  std::size_t runs = 0, failed = 0;
  double mean = NAN, sd = NAN, min = NAN, q05 = NAN, q25 = NAN, median = NAN, q75 = NAN, q95 = NAN, max = NAN;
};

std::vector<SummaryRow> summarise(const SweepCase& c, const SweepResults& r) {
  const std::vector<std::size_t> axes = group_axes(c);
  // Groups in order of first appearance.
  std::vector<std::vector<std::string>> groups;
  std::vector<std::size_t> group_of(c.size());
  for (std::size_t run = 0; run < c.size(); ++run) {
    const std::vector<SweepValue> p = c.parameters(run);
    std::vector<std::string> key;
    for (std::size_t k : axes) key.push_back(text(p[k]));
    auto it = std::find(groups.begin(), groups.end(), key);
    if (it == groups.end()) it = groups.insert(groups.end(), key);
    group_of[run] = static_cast<std::size_t>(it - groups.begin());
  }
  std::vector<SummaryRow> rows;
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t k = 0; k < r.outputs; ++k) {
      SummaryRow row{.group = groups[g], .output = c.outputs[k]};
      std::vector<double> v;
      for (std::size_t run = 0; run < c.size(); ++run) {
        if (group_of[run] != g) continue;
        ++row.runs;
        const double x = r.values[run * r.outputs + k];
        if (std::isnan(x)) ++row.failed;
        else v.push_back(x);
      }
      if (!v.empty()) {
        std::sort(v.begin(), v.end());
        row.mean = gsl_stats_mean(v.data(), 1, v.size());
        row.sd = v.size() > 1 ? gsl_stats_sd_m(v.data(), 1, v.size(), row.mean) : 0.0;
        row.min = v.front();
        row.max = v.back();
        row.q05 = gsl_stats_quantile_from_sorted_data(v.data(), 1, v.size(), 0.05);
        row.q25 = gsl_stats_quantile_from_sorted_data(v.data(), 1, v.size(), 0.25);
        row.median = gsl_stats_quantile_from_sorted_data(v.data(), 1, v.size(), 0.50);
        row.q75 = gsl_stats_quantile_from_sorted_data(v.data(), 1, v.size(), 0.75);
        row.q95 = gsl_stats_quantile_from_sorted_data(v.data(), 1, v.size(), 0.95);
      }
      rows.push_back(std::move(row));
    }
  return rows;
}

constexpr const char* statistic_columns[] = {"mean", "sd", "min", "q05", "q25", "median", "q75", "q95", "max"};

std::array<double, 9> statistics(const SummaryRow& s) {
  return {s.mean, s.sd, s.min, s.q05, s.q25, s.median, s.q75, s.q95, s.max};
}

/// The runs of a rig's case: its numeric results that the case records, and its per-impact table.
void run_rig_sweep(const SweepCase& c, const std::vector<std::size_t>& runs, const PaperParameters& paper,
                   const SweepOptions& options, SweepResults& r) {
  std::vector<std::size_t> fields;
  for (const std::string& name : c.outputs)
    fields.push_back(static_cast<std::size_t>(
        std::find_if(c.rig->results.begin(), c.rig->results.end(), [&](const RigField& f) { return flat_name(f.name) == name; }) -
        c.rig->results.begin()));
  parallel_for_chunks(
      runs.size(), [] { return 0; },
      [&](int, std::size_t j) {
        try {
          const RigResult result = run_rig(*c.rig, c.options(runs[j]), paper, c.rig_inputs(runs[j]));
          for (std::size_t k = 0; k < fields.size(); ++k) {
            const RigValue& v = result.scalars[fields[k]];
            if (const double* x = std::get_if<double>(&v)) r.values[j * r.outputs + k] = *x;
            if (const long* n = std::get_if<long>(&v)) r.values[j * r.outputs + k] = static_cast<double>(*n);
          }
          for (const std::vector<double>& row : result.rows) r.impacts[j].insert(r.impacts[j].end(), row.begin(), row.end());
          if (!result.warnings.empty()) r.diagnostics[j].add(Diagnostic::rig_warning);
          r.errors[j].clear();
        } catch (const std::exception& e) {
          r.errors[j] = spell_key_references(e.what(), KeySpelling::key);
        }
      },
      options);
}

}  // namespace

void write_sweep_impacts(const SweepCase& c, const SweepResults& results,
                         const std::function<void(std::string_view)>& write) {
  std::vector<std::string> columns{"run"};
  for (const std::string& p : c.parameter_columns()) columns.push_back(p);
  columns.emplace_back("n");
  for (const RigColumn& col : c.rig->table) columns.emplace_back(col.name);
  CsvWriter csv(fmt::format("hertzdash sweep: one row per kept impact of every run of the case file, rig {}: {}",
                            c.rig->name, c.rig->table_description),
                case_parameters(c), columns);
  write(csv.head());
  const std::size_t cells = c.rig->table.size();
  for (std::size_t run = 0; run < c.size(); ++run) {
    const std::vector<SweepValue> parameters = c.parameters(run);
    const std::vector<double>& table = results.impacts[run];
    for (std::size_t n = 0; n * cells < table.size(); ++n) {
      std::vector<CsvWriter::Cell> row{static_cast<long>(run)};
      for (const SweepValue& v : parameters) row.push_back(cell(v));
      row.emplace_back(static_cast<long>(n));
      for (std::size_t k = 0; k < cells; ++k) {
        const double v = table[n * cells + k];
        if (c.rig->table[k].integer) row.emplace_back(static_cast<long>(v));
        else row.emplace_back(v);
      }
      csv.add_row(row);
    }
    write(csv.take_rows());
  }
}

SweepResults run_sweep(const SweepCase& c, const std::vector<std::size_t>& runs, const PaperParameters& paper,
                       const SweepOptions& options) {
  SweepResults r;
  r.outputs = c.outputs.size();
  r.values.assign(runs.size() * r.outputs, NAN);
  r.errors.assign(runs.size(), "not run");
  r.diagnostics.assign(runs.size(), DiagnosticSet{});
  r.impacts.assign(runs.size(), {});
  if (c.rig) {
    run_rig_sweep(c, runs, paper, options, r);
    return r;
  }
  std::vector<const SweepOutput*> outputs;
  for (const std::string& name : c.outputs) outputs.push_back(find_sweep_output(name));
  parallel_for_chunks(
      runs.size(), [] { return SimulatorCache{}; },
      [&](SimulatorCache& simulators, std::size_t j) {
        try {
          const RunOptions run = c.options(runs[j]);
          const DropTestSetup setup = resolve_setup(run, paper);
          const ImpactSummary s = simulators(resolve_solver(run)).run(setup, run.damping);
          for (std::size_t k = 0; k < outputs.size(); ++k) r.values[j * r.outputs + k] = outputs[k]->value(s, setup);
          r.diagnostics[j] = s.diagnostics;
          r.errors[j].clear();
        } catch (const std::exception& e) {
          r.errors[j] = spell_key_references(e.what(), KeySpelling::key);  // as the case file writes keys
        }
      },
      options);
  return r;
}

std::array<std::size_t, diagnostic_table.size()> diagnostic_counts(const SweepResults& results) {
  std::array<std::size_t, diagnostic_table.size()> counts{};
  for (const DiagnosticSet d : results.diagnostics)
    for (std::size_t k = 0; k < diagnostic_table.size(); ++k) counts[k] += d.has(diagnostic_table[k].code) ? 1 : 0;
  return counts;
}

std::string diagnostic_counts_text(const SweepResults& results) {
  const auto counts = diagnostic_counts(results);
  std::string out;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    if (counts[k] == 0) continue;
    if (!out.empty()) out += ", ";
    out += fmt::format("{} {}", diagnostic_table[k].name, counts[k]);
  }
  return out;
}

void write_sweep_table(const SweepCase& c, const SweepResults& results, const std::string& timing_line,
                       const std::function<void(std::string_view)>& write) {
  constexpr std::size_t rows_per_piece = 4096;
  std::vector<std::string> columns{"run"};
  for (const std::string& p : c.parameter_columns()) columns.push_back(p);
  for (const std::string& o : c.outputs) columns.push_back(o);
  columns.emplace_back("warnings");
  columns.emplace_back("error");
  CsvWriter csv("hertzdash sweep: one row per run of the case file (SI units; an empty cell: no value)",
                case_parameters(c), columns);
  add_case_text(csv, c);
  csv.add_comment(timing_line);
  write(csv.head());
  for (std::size_t run = 0; run < c.size(); ++run) {
    std::vector<CsvWriter::Cell> row{static_cast<long>(run)};
    for (const SweepValue& v : c.parameters(run)) row.push_back(cell(v));
    for (std::size_t k = 0; k < results.outputs; ++k) {
      const double v = results.values[run * results.outputs + k];
      row.emplace_back(std::isnan(v) ? CsvWriter::Cell(std::string()) : CsvWriter::Cell(v));
    }
    row.emplace_back(diagnostic_names(results.diagnostics[run]));
    row.emplace_back(results.errors[run]);
    csv.add_row(row);
    if ((run + 1) % rows_per_piece == 0) write(csv.take_rows());
  }
  write(csv.take_rows());
}

std::string sweep_table(const SweepCase& c, const SweepResults& results, const std::string& timing_line) {
  std::string table;
  write_sweep_table(c, results, timing_line, [&table](std::string_view piece) { table += piece; });
  return table;
}

std::string sweep_summary_table(const SweepCase& c, const SweepResults& results) {
  std::vector<std::string> columns;
  for (std::size_t k : group_axes(c)) columns.push_back(c.grid[k].column());
  for (const char* name : {"output", "runs", "failed"}) columns.emplace_back(name);
  for (const char* name : statistic_columns) columns.emplace_back(name);
  CsvWriter csv("hertzdash sweep: summary of every output over the runs that gave a value (SI units; quantiles "
                "interpolate between order statistics, Hyndman & Fan type 7)",
                case_parameters(c), columns);
  const std::string counts = diagnostic_counts_text(results);
  csv.add_comment(fmt::format("warnings, runs per code (of {}): {} (the rows' warnings column says which)",
                              results.errors.size(), counts.empty() ? "none" : counts));
  for (const SummaryRow& s : summarise(c, results)) {
    std::vector<CsvWriter::Cell> row(s.group.begin(), s.group.end());
    row.emplace_back(s.output);
    row.emplace_back(static_cast<long>(s.runs));
    row.emplace_back(static_cast<long>(s.failed));
    for (double v : statistics(s)) row.emplace_back(std::isnan(v) ? CsvWriter::Cell(std::string()) : CsvWriter::Cell(v));
    csv.add_row(row);
  }
  return csv.str();
}

std::string sweep_summary_text(const SweepCase& c, const SweepResults& results) {
  std::string out;
  std::vector<std::string> groups;
  for (std::size_t k : group_axes(c)) groups.push_back(c.grid[k].column());
  std::string head;
  for (const std::string& g : groups) head += fmt::format("{:<18} ", g);
  out += head + fmt::format("{:<26} {:>7} {:>6} {:>13} {:>11} {:>13} {:>13} {:>13}\n", "output", "runs", "failed", "mean",
                            "sd", "q05", "median", "q95");
  for (const SummaryRow& s : summarise(c, results)) {
    for (const std::string& g : s.group) out += fmt::format("{:<18} ", g);
    out += fmt::format("{:<26} {:>7} {:>6} {:>13.6g} {:>11.3g} {:>13.6g} {:>13.6g} {:>13.6g}\n", s.output, s.runs, s.failed,
                       s.mean, s.sd, s.q05, s.median, s.q95);
  }
  return out;
}

}  // namespace hertzdash

// Bifurcation diagrams of the shaker (simulation/reports/shaker_sweep_report.hpp).
#include "hertzdash/simulation/reports/shaker_sweep_report.hpp"

#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/model/shaker_sweep_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace hertzdash {

namespace {

const ParameterDecl& axis_decl(const std::string& key) {
  namespace p = shaker_parameters;
  if (key == "gamma") return p::gamma;
  if (key == "amplitude") return p::amplitude;
  return p::frequency;
}

// The value of `key` in `inputs`, or empty.
std::string parameter_value(const Parameters& inputs, const std::string& key) {
  for (const auto& [k, v] : inputs)
    if (k == key) return v;
  return {};
}

}  // namespace

double ShakerSweepAxis::value(int i) const {
  if (i == count - 1) return to;
  return from + (to - from) * static_cast<double>(i) / static_cast<double>(count - 1);
}

std::string ShakerSweepAxis::column() const {
  if (key == "amplitude") return "amplitude_m";
  if (key == "frequency") return "frequency_Hz";
  return key;
}

ShakerSweepAxis parse_shaker_sweep(std::string_view text) {
  const std::string valid = "KEY:FROM:TO:COUNT with KEY gamma, amplitude or frequency, FROM and TO decimal numbers "
                            "in KEY's range, FROM != TO, COUNT a whole number from 2 to 100000";
  std::vector<std::string_view> parts;
  for (std::size_t begin = 0;;) {
    const std::size_t end = text.find(':', begin);
    parts.push_back(text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
    if (end == std::string_view::npos) break;
    begin = end + 1;
  }
  const std::string given(text);
  if (parts.size() != 4 || (parts[0] != "gamma" && parts[0] != "amplitude" && parts[0] != "frequency"))
    throw InvalidParameter("sweep", given, valid);
  const std::optional<double> from = parse_decimal(parts[1]), to = parse_decimal(parts[2]),
                              count = parse_decimal(parts[3]);
  if (!from || !to || !count || *from == *to || !(*count >= 2 && *count <= 100000) || std::floor(*count) != *count)
    throw InvalidParameter("sweep", given, valid);
  ShakerSweepAxis axis{.key = std::string(parts[0]), .from = *from, .to = *to, .count = static_cast<int>(*count)};
  require_in_range(axis_decl(axis.key), axis.from);
  require_in_range(axis_decl(axis.key), axis.to);
  return axis;
}

ShakerSweep resolve_shaker_sweep(const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                                 const ShakerSweepAxis& axis) {
  const std::string sweep_text = fmt::format("{}:{}:{}:{}", axis.key, axis.from, axis.to, axis.count);
  auto refuse = [&](const std::string& key, double v) {
    throw InvalidParameter(key, format_value(v), "not given with `sweep` = " + sweep_text + " (the sweep sets it)");
  };
  for (const char* key : {"frequency", "gamma", "amplitude"})
    if (inputs.number(key) && (axis.key == key || (axis.key != "frequency" && key != std::string("frequency"))))
      refuse(key, *inputs.number(key));
  ShakerSweep sweep{.axis = axis, .runs = {}};
  sweep.runs.reserve(static_cast<std::size_t>(axis.count));
  for (int i = 0; i < axis.count; ++i) {
    RigInputs in = inputs;
    in.numbers[axis.key] = axis.value(i);
    sweep.runs.push_back(resolve_shaker_command(options, paper, in));
  }
  return sweep;
}

void run_shaker_sweep(ShakerSweep& sweep, const std::vector<std::size_t>& values, const SweepOptions& sweep_options) {
  parallel_for_chunks(
      values.size(), [] { return 0; },
      [&](int, std::size_t k) {
        ShakerCommandRun& r = sweep.runs.at(values[k]);
        r.run = run_shaker(r.setup, r.law, r.solver, r.options);
      },
      sweep_options);
}

// Per value: gamma, period, impacts per period, e_effective, impacts run, sticking episodes, the
// number of kept impacts, then 6 numbers per kept impact (ShakerImpact's fields in order).
std::vector<double> pack_shaker_runs(const ShakerSweep& sweep, const std::vector<std::size_t>& values) {
  std::vector<double> out;
  for (const std::size_t v : values) {
    const ShakerRun& s = sweep.runs.at(v).run;
    for (double x : {s.gamma, static_cast<double>(s.pattern.period), static_cast<double>(s.pattern.impacts_per_period),
                     s.e_effective, static_cast<double>(s.impacts_run), static_cast<double>(s.sticking_episodes),
                     static_cast<double>(s.impacts.size())})
      out.push_back(x);
    for (const ShakerImpact& i : s.impacts)
      for (double x : {i.time_s, i.phase, i.impact_speed_mps, i.rebound_speed_mps, i.contact_time_s, i.peak_force_N})
        out.push_back(x);
  }
  return out;
}

// Per value its warnings, each ended by '\n' (a warning holds no line break), the value ended by '\0'.
std::string pack_shaker_warnings(const ShakerSweep& sweep, const std::vector<std::size_t>& values) {
  std::string out;
  for (const std::size_t v : values) {
    for (const std::string& w : sweep.runs.at(v).run.warnings) out += w + '\n';
    out += '\0';
  }
  return out;
}

void unpack_shaker_runs(ShakerSweep& sweep, const std::vector<std::size_t>& values, const std::vector<double>& numbers,
                        const std::string& warnings) {
  std::size_t at = 0, text = 0;
  auto next = [&] { return numbers.at(at++); };
  for (const std::size_t v : values) {
    ShakerRun& s = sweep.runs.at(v).run;
    s.impact_model = sweep.runs.at(v).options.impact_model;
    s.gamma = next();
    s.pattern.period = static_cast<int>(next());
    s.pattern.impacts_per_period = static_cast<int>(next());
    s.e_effective = next();
    s.impacts_run = static_cast<long>(next());
    s.sticking_episodes = static_cast<long>(next());
    s.impacts.resize(static_cast<std::size_t>(next()));
    for (ShakerImpact& i : s.impacts)
      for (double* x : {&i.time_s, &i.phase, &i.impact_speed_mps, &i.rebound_speed_mps, &i.contact_time_s, &i.peak_force_N})
        *x = next();
    const std::size_t end = warnings.find('\0', text);
    s.warnings.clear();
    for (std::size_t b = text; b < end;) {
      const std::size_t e = warnings.find('\n', b);
      s.warnings.push_back(warnings.substr(b, e - b));
      b = e + 1;
    }
    text = end + 1;
  }
}

CsvWriter shaker_sweep_csv(const ShakerSweep& sweep) {
  const ShakerSweepAxis& axis = sweep.axis;
  const bool gamma_axis = axis.key == "gamma";
  std::vector<std::string> columns{"run", axis.column()};
  if (!gamma_axis) columns.emplace_back("gamma");
  for (const char* c : {"n", "impact_phase", "impact_speed_mps", "rebound_speed_mps", "contact_time_s", "period",
                        "impacts_per_period"})
    columns.emplace_back(c);
  // The inputs every run shares; those that vary along the sweep (the amplitude, the start) are
  // left out: the rows hold the value and gamma.
  Parameters shared;
  for (const auto& [key, value] : sweep.runs.front().inputs) {
    const bool same = std::all_of(sweep.runs.begin(), sweep.runs.end(), [&key = key, &value = value](const ShakerCommandRun& r) {
      return parameter_value(r.inputs, key) == value;
    });
    if (same) shared.emplace_back(key, value);
  }
  shared.emplace_back("sweep", fmt::format("{}:{}:{}:{}", axis.key, axis.from, axis.to, axis.count));
  CsvWriter csv("hertzdash shaker --sweep: a bifurcation diagram, one row per kept impact of each swept value (run: "
                "the value's index; phase of s(t) = A sin(2 pi f t) in [0,1); speeds relative to the wall; period in "
                "table cycles, 0: none found)",
                shared, columns);
  for (std::size_t j = 0; j < sweep.runs.size(); ++j) {
    const ShakerCommandRun& r = sweep.runs[j];
    for (const std::string& w : r.run.warnings) csv.add_comment(fmt::format("warning, run {}: {}", j, w));
  }
  for (std::size_t j = 0; j < sweep.runs.size(); ++j) {
    const ShakerRun& s = sweep.runs[j].run;
    const double value = axis.value(static_cast<int>(j));
    for (std::size_t n = 0; n < s.impacts.size(); ++n) {
      const ShakerImpact& i = s.impacts[n];
      std::vector<CsvWriter::Cell> row{static_cast<long>(j), value};
      if (!gamma_axis) row.emplace_back(s.gamma);
      row.emplace_back(static_cast<long>(n));
      for (double x : {i.phase, i.impact_speed_mps, i.rebound_speed_mps, i.contact_time_s}) row.emplace_back(x);
      row.emplace_back(static_cast<long>(s.pattern.period));
      row.emplace_back(static_cast<long>(s.pattern.impacts_per_period));
      csv.add_row(row);
    }
  }
  return csv;
}

}  // namespace hertzdash

// `fit`'s option table and the request it reads (simulation/reports/fit_request.hpp).
#include "hertzdash/simulation/reports/fit_request.hpp"

#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/virtual_measurement.hpp"

#include <fmt/format.h>

namespace hertzdash {

namespace {

constexpr unsigned trace = 1u << static_cast<int>(FitDataKind::trace);
constexpr unsigned table = 1u << static_cast<int>(FitDataKind::restitution_table);
constexpr unsigned bounce = 1u << static_cast<int>(FitDataKind::bounce_times);
constexpr unsigned every = trace | table | bounce;

constexpr ParameterDecl text(std::string_view key, std::string_view default_value, std::string_view help) {
  return {.key = key, .type = ParameterType::text, .default_value = default_value, .help = help};
}
constexpr ParameterDecl flag(std::string_view key, std::string_view help) {
  return {.key = key, .type = ParameterType::flag, .default_value = "off", .help = help};
}

const FitOption options[] = {
    {text("trace", "", "Measured trace, CSV (data/measurements/README.md); or --restitution-table, --bounce-times"), trace},
    {text("restitution-table", "",
          "Restitution table, CSV: e against the impact speed (data/measurements/README.md); fits the law's own "
          "parameters (docs/fit.md); or --trace"),
     table},
    {text("bounce-times", "",
          "Bounce recording, CSV: the detected impact times of one or more drops (data/measurements/README.md); flags "
          "doubled, missed and out-of-order detections, fits the law's own parameters and each drop's first impact "
          "speed and clock offset (docs/fit.md); or --trace"),
     bounce},
    {text("fit", "ball-E,restitution (a trace); the law's own (restitution, or viscous-time-constant) otherwise",
          "Parameters to fit besides the nuisances (a trace's onset time, a drop's first impact speed and clock "
          "offset): NAME or NAME:LOWER:UPPER, comma-separated, NAME a fittable set-up option (docs/parameters.md); "
          "the starting values are the run options (or the paper's)"),
     every},
    {{.key = "timing-sd", .unit = "s", .range = NumberRange::positive(), .default_value = "unknown (fitted)",
      .help = "The detector's timing precision, 1 sigma [s]: weighs the times, and a fit whose scatter is far above it "
              "is a poor fit (docs/fit.md); unknown, one common scatter is fitted"},
     bounce},
    {text("channels", "all the trace has", "Channels of the trace to fit, comma-separated"), trace},
    {{.key = "resample", .unit = "Hz", .range = NumberRange::non_negative(), .default_value = "0",
      .help = "Average the trace into bins of 1/RATE first [Hz]; 0 = as sampled"},
     trace},
    {flag("compare-laws", "Fit every registered damping law and rank them by AIC"), every},
    {flag("cross-validate",
          "Leave out each fold in turn (a table's distinct speeds, a recording's drops, a trace's five interleaved "
          "sets of samples), fit the rest, predict it; rank by the prediction error too (docs/fit.md)"),
     every},
    {flag("profile-intervals",
          "Each fitted parameter's profile-likelihood 1-sigma interval too (a re-fit per point; docs/fit.md)"),
     every},
    {text("curves", "",
          "Write the data, the fitted model and the residuals to this CSV file, a row per sample, table row or "
          "impact (docs/fit.md)"),
     every},
    {text("figure", "",
          "Draw the fit to this PNG, PDF or SVG file (by its extension): e against the impact speed with the fitted "
          "law and its band, or a trace's overlay, and the residuals (docs/fit.md)"),
     every},
    {flag("json", "Print the result as one JSON object"), every},
    {flag("mkdir", "Create the missing directories of --curves and --figure"), every},
};

constexpr const char* kind_option[] = {"trace", "restitution-table", "bounce-times"};

}  // namespace

std::string_view fit_kind_option(FitDataKind kind) { return kind_option[static_cast<int>(kind)]; }

std::span<const FitOption> fit_command_options() { return options; }

FitRequest fit_request(const std::map<std::string, std::string>& values, const RunOptions& run) {
  FitRequest r;
  r.options = run;
  int named = -1;
  for (int k = 0; k < 3; ++k)
    if (values.contains(kind_option[k])) {
      if (named >= 0)
        throw InvalidParameter(kind_option[k], values.at(kind_option[k]),
                               fmt::format("omitted with `{}` (one input per fit)", kind_option[named]));
      named = k;
    }
  if (named < 0) throw InvalidParameter("trace", "", "given: a trace, a restitution table or a bounce recording to fit");
  r.kind = static_cast<FitDataKind>(named);
  r.path = values.at(kind_option[named]);
  for (const FitOption& o : options) {
    const auto it = values.find(std::string(o.decl.key));
    if (it == values.end()) continue;
    if (!(o.kinds & (1u << named))) {
      std::string readers;
      for (int k = 0; k < 3; ++k)
        if (o.kinds & (1u << k)) readers += fmt::format("{}`{}`", readers.empty() ? "" : " or ", kind_option[k]);
      throw InvalidParameter(std::string(o.decl.key), it->second,
                             fmt::format("omitted with `{}` (it is read with {} only)", kind_option[named], readers));
    }
    const std::string& v = it->second;
    if (o.decl.key == "fit") r.fit = v;
    else if (o.decl.key == "channels") r.settings.channels = parse_channels(v, "channels");
    else if (o.decl.key == "resample") {
      const std::optional<double> x = parse_option_number(v);  // its range is checked with the trace (prepare_trace)
      if (!x) throw InvalidParameter("resample", v, o.decl.range.text(o.decl.unit));
      r.settings.resample_Hz = *x;
    } else if (o.decl.key == "timing-sd") {
      const std::optional<double> x = parse_option_number(v);
      if (!x) throw InvalidParameter("timing-sd", v, o.decl.range.text(o.decl.unit));
      require_in_range(o.decl, *x);
      r.timing_sd_s = *x;
    } else if (o.decl.key == "compare-laws") r.compare_laws = v == "true";
    else if (o.decl.key == "cross-validate") r.settings.cross_validate = v == "true";
    else if (o.decl.key == "profile-intervals") r.settings.profile_intervals = v == "true";
  }
  return r;
}

}  // namespace hertzdash

// The Python module `hertzdash`: the library's front-end API (simulation/options/run_options.hpp,
// simulation/reports/run_reports.hpp) with Python keywords for the command line's options, so
//   hertzdash.simulate(rod="steel", height=0.02, ball_E=3e9)
// returns, as a dict, exactly what `hertzdash simulate --rod steel --height 0.02 --ball-E 3e9
// --json` prints (bounce(), restitution() and calibrate_restitution() likewise for their
// commands). Bad input raises ValueError with the command line's message, the option
// named by its keyword (ball_E, not --ball-E), and its valid range; the notes and warnings the command line writes to stderr are
// UserWarnings. Every call releases the GIL while it integrates; simulate_many() runs its
// impacts on all cores.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/file_identity.hpp"
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/simulation/reports/export_report.hpp"
#include "hertzdash/simulation/reports/fit_curves.hpp"
#include "hertzdash/simulation/reports/fit_request.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/reports/orbit_report.hpp"
#include "hertzdash/simulation/reports/rig_report.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/result_fields.hpp"
#include "hertzdash/simulation/run/distinct_time_samples.hpp"
#include "hertzdash/simulation/run/uniform_trace.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace py = pybind11;
using namespace hertzdash;

namespace {

// ---- options: Python keywords -> RunOptions, through the library's option table ----

std::string option_list() {
  std::string names;
  for (const RunOption& o : run_options()) names += (names.empty() ? "" : ", ") + python_keyword(o.name);
  return names;
}

// `own_inputs`: a rig's inputs, listed before the options.
const RunOption& option_named(const std::string& keyword, const char* function, const std::string& own_inputs = {}) {
  const RunOption* o = find_run_option(keyword);
  if (!o || python_keyword(o->name) != keyword)
    throw py::type_error(fmt::format("{}() got an unexpected keyword argument '{}'; {}options: {}", function, keyword,
                                     own_inputs.empty() ? "" : "inputs: " + own_inputs + "; ", option_list()));
  return *o;
}

// Sets one option from a Python value; a value of the wrong type raises TypeError naming it.
void set_option(RunOptions& options, const RunOption& o, py::handle value) {
  const std::string keyword = python_keyword(o.name);
  if (o.decl.type == ParameterType::flag) {
    if (!py::isinstance<py::bool_>(value)) throw py::type_error(keyword + ": expected True or False");
    set_flag(options, o, value.cast<bool>());
    return;
  }
  if (value.is_none()) {  // None: the default
    clear_option(options, o);
    return;
  }
  if (o.decl.type == ParameterType::text) {
    if (!py::isinstance<py::str>(value)) throw py::type_error(keyword + ": expected a string");
    set_text(options, o, value.cast<std::string>());
    return;
  }
  if (py::isinstance<py::bool_>(value) ||
      !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) || py::hasattr(value, "__float__")))
    throw py::type_error(keyword + ": expected a number");
  try {
    set_number(options, o, value.cast<double>());
  } catch (const py::cast_error&) {  // an integer beyond the range of a double
    throw InvalidParameter(o.name, py::str(value).cast<std::string>(), "a number within the range of a double");
  }
}

RunOptions run_options_from(const py::kwargs& kwargs, const char* function) {
  RunOptions options;
  for (const auto& [key, value] : kwargs) set_option(options, option_named(key.cast<std::string>(), function), value);
  return options;
}

// ---- results: JSON reports -> Python objects ----

py::object to_python(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float: {  // the program's JSON writes inf and NaN as null
      const double v = j.get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    }
    case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& v : j) list.append(to_python(v));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [k, v] : j.items()) dict[py::str(k)] = to_python(v);
      return dict;
    }
    default: throw std::logic_error("unexpected JSON value");
  }
}

// The tables, read once, and the directory they were read from.
struct PaperData {
  std::filesystem::path dir = default_data_dir();
  PaperParameters tables = load_paper_parameters(dir);
};

const PaperData& paper_data() {
  static const PaperData data;
  return data;
}

const PaperParameters& paper() { return paper_data().tables; }

// The front ends' notes and warnings (simulation/reports/run_reports.hpp) as Python warnings.
void warn(const std::string& message) {
  if (!message.empty() && PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 2) != 0) throw py::error_already_set();
}

void warn_about(const std::vector<RunDiagnostic>& diagnostics) {
  for (const RunDiagnostic& d : diagnostics) warn(spell_key_references(d.message, KeySpelling::python));
}

// ---- the functions ----

// A command's run `run_command(options)` on the options of `kwargs`, with the GIL released; its
// notes and warnings as UserWarnings; its JSON as a dict.
template <class RunCommand>
py::dict run_command(const char* function, const py::kwargs& kwargs, RunCommand run_command) {
  const RunOptions options = run_options_from(kwargs, function);
  decltype(run_command(options)) run;
  {
    py::gil_scoped_release release;
    run = run_command(options);
  }
  warn_about(run_diagnostics(run));
  return to_python(to_json(run));
}

py::dict py_simulate(const py::kwargs& kwargs) {
  return run_command("simulate", kwargs, [](const RunOptions& o) { return run_simulate(o, paper()); });
}

py::dict py_trace(std::optional<double> grid_step, const py::kwargs& kwargs) {
  if (grid_step && !(std::isfinite(*grid_step) && *grid_step > 0))
    throw InvalidParameter("grid_step", fmt::format("{}", *grid_step), "a finite time step > 0 [s], or None");
  const RunOptions options = run_options_from(kwargs, "trace");
  std::vector<TraceSample> samples;
  SimulateRun run;
  {
    py::gil_scoped_release release;
    run = run_simulate(options, paper(), true);
    if (grid_step && !run.trace.empty()) {
      constexpr double max_samples = 1e7;
      const double count = (run.trace.back().t_s - run.trace.front().t_s) / *grid_step;
      if (count > max_samples)
        throw InvalidParameter("grid_step", fmt::format("{}", *grid_step),
                               fmt::format("a step giving at most {:g} samples of the {:.6g} s contact", max_samples,
                                           run.trace.back().t_s - run.trace.front().t_s));
    }
    samples = grid_step ? uniform_trace(run.trace, *grid_step) : distinct_time_samples(run.trace);
  }
  warn_about(run_diagnostics(run));
  py::dict out;
  for (const TraceColumn& c : trace_column_table) {
    py::array_t<double> column(static_cast<py::ssize_t>(samples.size()));
    auto a = column.mutable_unchecked<1>();
    for (std::size_t i = 0; i < samples.size(); ++i)
      a(static_cast<py::ssize_t>(i)) = c.value(samples[i], run.trace.front());
    out[py::str(c.name)] = column;
  }
  return out;
}

py::dict py_restitution(const py::kwargs& kwargs) {
  return run_command("restitution", kwargs, [](const RunOptions& o) { return run_restitution(o, paper()); });
}

py::dict calibrate(double target, const py::kwargs& kwargs) {
  return run_command("calibrate_restitution", kwargs,
                     [target](const RunOptions& o) { return run_restitution(o, paper(), target); });
}

// bounce: `hertzdash bounce`'s own options are keywords of their own; the rest are the run's.
py::dict py_bounce(double bounces, double min_rebound_velocity, std::optional<double> target_interval_restitution,
                   const py::kwargs& kwargs) {
  const RunOptions options = run_options_from(kwargs, "bounce");
  const BounceOptions bounce{.impacts = parse_bounces(bounces), .min_rebound_velocity_mps = min_rebound_velocity};
  BounceRun run;
  {
    py::gil_scoped_release release;
    run = run_bounce(options, paper(), bounce, target_interval_restitution);
  }
  warn_about(run_diagnostics(run));
  return to_python(to_json(run));
}

// The discrete-element engines (docs/engines.md): `hertzdash export` and `hertzdash conformance`.
py::dict py_export_decks(const std::string& engine, const std::string& out, const std::string& engine_model,
                         std::optional<double> steps_per_contact, const py::kwargs& kwargs) {
  const RunOptions options = run_options_from(kwargs, "export_decks");
  const Engine e = parse_engine(engine);
  const int steps = steps_per_contact_option("export", steps_per_contact);
  const std::filesystem::path dir(out);
  if (!std::filesystem::is_directory(dir)) throw InvalidParameter("out", out, "an existing directory");
  EngineExport run;
  {
    py::gil_scoped_release release;
    run = export_engine_decks(options, paper(), e, engine_model, steps);
    std::vector<std::pair<std::filesystem::path, std::string>> files;
    for (const auto& [name, text] : run.files()) files.emplace_back(dir / name, text);
    write_files_atomically(files);
  }
  return to_python(to_json(run));
}

py::dict py_conformance(const std::string& engine, std::optional<double> steps_per_contact, const py::kwargs& kwargs) {
  const RunOptions options = run_options_from(kwargs, "conformance");
  const Engine e = parse_engine(engine);
  const int steps = steps_per_contact_option("conformance", steps_per_contact);
  EngineConformance run;
  {
    py::gil_scoped_release release;
    run = run_engine_conformance(options, paper(), e, steps);
  }
  return to_python(to_json(run));
}

// A file name with a NUL in it is refused as open() refuses it: C++ would cut it at the NUL.
void require_path(const std::string& path, const char* keyword) {
  if (path.find('\0') != std::string::npos) throw py::value_error(fmt::format("{}: embedded null byte", keyword));
}

// virtual_measurement: `hertzdash simulate --trace PATH --trace-format measured`; the chain's
// settings are keywords of their own, the rest are the run's.
py::dict py_virtual_measurement(const std::string& path, double sample_rate, double anti_alias, double noise,
                                std::uint64_t seed, const std::string& channels, const py::kwargs& kwargs) {
  require_path(path, "path");
  const RunOptions options = run_options_from(kwargs, "virtual_measurement");
  MeasurementChain chain{.sample_rate_Hz = sample_rate, .anti_alias_cutoff_Hz = anti_alias, .noise_fraction = noise,
                         .seed = seed};
  chain.channels = parse_channels(channels, "channels");
  validate(chain);
  SimulateRun run;
  {
    py::gil_scoped_release release;
    run = run_simulate(options, paper(), true);
    write_measured_trace(path, virtual_measurement(run, options.rod, chain),
                         "hertzdash simulate: a SYNTHETIC virtual measurement of the model (not a measurement)",
                         virtual_measurement_parameters(run, chain));
  }
  const std::string note = virtual_measurement_note(run, chain);
  warn_about(run_diagnostics(run, note));
  return to_python(to_json(run, note));
}

// The fit functions, one per kind of data, generated from `fit`'s option table
// (simulation/reports/fit_request.cpp): `hertzdash fit --KIND PATH --json`, the fit's own options
// of that kind as keywords, the set-up's options as the rest (the fit integrates its model
// itself: a solver option is refused).
struct FitFunction {
  const char* name;
  FitDataKind kind;
  const char* path;     ///< the first argument's name
  const char* summary;  ///< what it does and returns
};

constexpr FitFunction fit_functions[] = {
    {"fit", FitDataKind::trace, "trace",
     "Identify parameters from a measured trace by weighted least squares, exactly `hertzdash fit --trace TRACE "
     "--json` (docs/fit.md): trace, fits (parameters with estimate, standard_error, bounds; correlation; channels "
     "with noise_sigma and residual_rms; reduced_chi_square, condition_number, identifiable, aic, bic, "
     "fitted_inputs), failures. Warnings (not identifiable, a bound reached, a poor fit, a synthetic trace) are "
     "UserWarnings."},
    {"fit_restitution_table", FitDataKind::restitution_table, "path",
     "Fit a damping law's own parameters to a restitution table (e against the impact speed, "
     "data/measurements/README.md), exactly `hertzdash fit --restitution-table PATH --json` (docs/fit.md): table, "
     "fits (parameters with estimate, standard_error, profile_interval; correlation; sigma; reduced_chi_square; "
     "aic, bic; e_effective; points; cross_validation), failures. Warnings (a synthetic table, sigma "
     "estimated, a failed fit) are UserWarnings."},
    {"fit_bounce_times", FitDataKind::bounce_times, "path",
     "Fit a damping law's own parameters, and each drop's first impact speed and clock offset, to a bounce "
     "recording (the detected impact times of one or more drops, data/measurements/README.md), exactly `hertzdash "
     "fit --bounce-times PATH --json` (docs/fit.md): recording, flagged (the doubled, missed, out-of-order and "
     "non-shrinking detections left out, by drop and index), fits (parameters, drops, sigma_s, aic, bic, "
     "e_effective, points, cross_validation, profile_interval), failures. air_density and drag_coefficient "
     "add air drag to the model's flights. Warnings (each flag, a synthetic recording) are UserWarnings."},
};

// The fit's own options that `f` takes as keywords: those its kind reads, but the one naming the
// data (its first argument) and the command line's output flags.
std::vector<const ParameterDecl*> fit_keywords(const FitFunction& f) {
  std::vector<const ParameterDecl*> keywords;
  for (const FitOption& o : fit_command_options())
    // Not "figure": the program draws with gnuplot (cli/figure_file.hpp); from Python, curves=
    // writes the same data for matplotlib.
    if ((o.kinds & (1u << static_cast<int>(f.kind))) && o.decl.key != fit_kind_option(f.kind) &&
        o.decl.key != "json" && o.decl.key != "mkdir" && o.decl.key != "figure")
      keywords.push_back(&o.decl);
  return keywords;
}

// The fit's own option `d` from a Python value, as the command line's text ("" for off or None).
std::string fit_option_text(const ParameterDecl& d, py::handle value) {
  const std::string keyword = python_keyword(d.key);
  if (value.is_none()) return "";
  if (d.type == ParameterType::flag) {
    if (!py::isinstance<py::bool_>(value)) throw py::type_error(keyword + ": expected True or False");
    return value.cast<bool>() ? "true" : "";
  }
  if (d.type == ParameterType::text) {
    if (!py::isinstance<py::str>(value)) throw py::type_error(keyword + ": expected a string");
    return value.cast<std::string>();
  }
  if (py::isinstance<py::bool_>(value) || !py::hasattr(value, "__float__")) throw py::type_error(keyword + ": expected a number");
  return fmt::format("{}", value.cast<double>());
}

// Runs `work` with the GIL released on a thread of its own while this thread checks for signals
// ten times a second: Python handles a signal (Ctrl-C) only between its own bytecodes, so a
// sweep of minutes ignored it until done. On a signal whose handler raises, sets `cancel` (the
// sweep stops handing out work), waits for `work` to return and returns false with the Python
// error set. Rethrows what `work` threw.
template <class Work>
bool run_watching_signals(Work& work, std::atomic<bool>& cancel) {
  std::mutex mutex;
  std::condition_variable finished_cv;
  bool finished = false, interrupted = false;
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    std::thread runner;
    try {
      runner = std::thread([&] {
        try {
          work();
        } catch (...) {
          failure = std::current_exception();
        }
        std::lock_guard lock(mutex);
        finished = true;
        finished_cv.notify_one();
      });
    } catch (const std::system_error&) {  // no thread to spare: run here, without the checks
      work();
      return true;
    }
    std::unique_lock lock(mutex);
    while (!finished_cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; })) {
      if (interrupted) continue;  // the error is set; wait for the sweep to stop
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        interrupted = PyErr_CheckSignals() != 0;
      }
      if (interrupted) cancel = true;
      lock.lock();
    }
    lock.unlock();
    runner.join();
  }
  if (interrupted) return false;
  if (failure) std::rethrow_exception(failure);
  return true;
}

py::dict py_fit_kind(const FitFunction& f, const std::string& path, const py::kwargs& kwargs) {
  const std::vector<const ParameterDecl*> own = fit_keywords(f);
  std::map<std::string, std::string> values{{std::string(fit_kind_option(f.kind)), path}};
  RunOptions options;
  std::vector<std::string> given;  // even at a default value (rod="steel"): a trace may not contradict it
  std::string names;  // the own keywords, as an unknown keyword's refusal lists them
  for (const ParameterDecl* p : own) names += (names.empty() ? "" : ", ") + python_keyword(p->key);
  for (const auto& [key, value] : kwargs) {
    const std::string keyword = key.cast<std::string>();
    const auto d = std::ranges::find_if(own, [&](const ParameterDecl* p) { return python_keyword(p->key) == keyword; });
    if (d != own.end()) {
      if (std::string text = fit_option_text(**d, value); !text.empty()) values[std::string((*d)->key)] = text;
      continue;
    }
    const RunOption& o = option_named(keyword, f.name, names);
    given.push_back(o.name);
    if (o.group != RunOption::Group::setup)
      throw py::type_error(fmt::format("{}() got the solver option '{}': the fit integrates its model itself "
                                       "(simulation/fit/fit_engine.hpp)",
                                       f.name, python_keyword(o.name)));
    set_option(options, o, value);
  }
  FitRequest request = fit_request(values, options);
  request.given = given;
  const std::string curves = values.contains("curves") ? values.at("curves") : "";
  require_path(path, "path");
  require_path(curves, "curves");
  if (find_shared_file({request.path}, {curves}))  // curves= would replace the trace it fits (issue 31)
    throw InvalidParameter("curves", curves, "another file than " + python_keyword(fit_kind_option(f.kind)) + " (" + request.path + "), which is read: they are the same file");
  FitRun run;
  std::atomic<bool> cancel = false;
  request.settings.cancel = &cancel;  // Ctrl-C stops the fit at its next model run
  auto fit_all = [&] {
    run = run_fit(request, paper());
    if (curves.empty() || run.fits.empty()) return;
    if (run.kind == FitDataKind::trace) write_fit_curves(run.fits.front(), run.trace, curves);
    else restitution_curves_csv(run, run.fits.front(), paper()).save(curves);
  };
  if (!run_watching_signals(fit_all, cancel)) throw py::error_already_set();  // KeyboardInterrupt (Ctrl-C)
  warn_about(fit_diagnostics(run, paper()));
  return to_python(to_json(run, paper()));
}

std::string fit_doc(const FitFunction& f) {
  std::string doc = fmt::format("{}({}, **options) -> dict\n\n{}\n\nIts own options:\n", f.name, f.path, f.summary);
  for (const ParameterDecl* d : fit_keywords(f))
    doc += fmt::format("  {}: {}\n", python_keyword(d->key), help_text(*d, KeySpelling::python));
  return doc;
}

py::object py_paper_parameters() {
  using json = nlohmann::ordered_json;
  const PaperParameters& p = paper();
  json rods = json::array(), uncertain = json::array();
  for (const RodData& r : p.rods)
    rods.push_back({{"name", r.name}, {"diameter_m", r.diameter_m}, {"length_m", r.length_m}, {"mass_kg", r.mass_kg},
                    {"restitution", r.restitution}, {"zeta_printed", r.zeta_printed},
                    {"natural_frequency_hz", r.natural_frequency_hz}, {"E_Pa", r.E_Pa}, {"nu", r.nu}});
  const json ball = {{"diameter_m", p.ball.diameter_m}, {"height_m", p.ball.height_m}, {"mass_kg", p.ball.mass_kg},
                     {"E_Pa", p.ball.E_Pa}, {"E_min_Pa", p.ball.E_min_Pa}, {"E_max_Pa", p.ball.E_max_Pa},
                     {"nu", p.ball.nu}, {"radius_m", p.ball.radius_m}};
  // The joint uncertainty study's inputs, each distribution in the terms of data/assumptions.csv.
  for (const UncertainInput& u : p.uncertain_inputs) {
    const InputDistribution& q = u.distribution;
    json d = {{"parameter", u.parameter}, {"unit", u.unit}, {"value", u.value}, {"distribution", to_string(q.kind)}};
    switch (q.kind) {
      case DistributionKind::uniform: break;
      case DistributionKind::normal: d["mean"] = q.p1, d["sd"] = q.p2; break;
      case DistributionKind::lognormal: d["median"] = std::exp(q.p1), d["log_sd"] = q.p2; break;
    }
    d["lower"] = q.kind == DistributionKind::uniform ? q.p1 : q.lower;
    d["upper"] = q.kind == DistributionKind::uniform ? q.p2 : q.upper;
    d["reason"] = u.reason;
    uncertain.push_back(d);
  }
  return to_python({{"rods", rods}, {"ball", ball}, {"uncertain_inputs", uncertain}, {"gravity_mps2", p.gravity_mps2},
                    {"data_dir", paper_data().dir.string()}});
}

py::object py_integrators() {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const IntegratorTraits& r : all_integrator_traits)
    rows.push_back({{"name", r.name},
                    {"step_control", r.step_control == StepControl::fixed_step ? "fixed-step" : "adaptive"},
                    {"variables", r.variables == Variables::physical ? "physical" : "regularized"},
                    {"method", method_traits(r.method).name},
                    {"needs_root_polynomial_law", r.needs_root_polynomial},
                    {"fallback_for_other_laws", to_string(r.fallback_for_other_laws)},
                    {"physical_counterpart", to_string(r.physical_counterpart)}});
  return to_python(rows);
}

// simulate_many: numeric set-up options may be 1-D arrays (broadcast against scalars);
// the solver options are one setting for the whole sweep. Its outputs are the result fields
// Python's simulate_many() reports (simulation/run/result_fields.hpp).
constexpr auto many_outputs = result_fields_reported<&ResultReports::python_many>();
static_assert(std::ranges::all_of(many_outputs,
                                  [](const ResultField& f) {
                                    return f.type == ResultType::number || f.type == ResultType::boolean ||
                                           f.type == ResultType::warnings;
                                  }),
              "simulate_many() returns numbers, booleans and the warnings' codes");

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Each point's codes (the "code"s of simulate()'s "warnings"), and one warning per code.
py::list warning_codes(const std::vector<ImpactSummary>& results) {
  py::list codes;
  DiagnosticSet any;
  for (const ImpactSummary& r : results) {
    py::list point;
    for (const DiagnosticInfo& d : diagnostic_table)
      if (r.diagnostics.has(d.code)) {
        point.append(std::string(d.name));
        any.add(d.code);
      }
    codes.append(point);
  }
  for (const DiagnosticInfo& d : diagnostic_table) {
    if (!any.has(d.code)) continue;
    const auto count = std::count_if(results.begin(), results.end(),
                                     [&](const ImpactSummary& r) { return r.diagnostics.has(d.code); });
    warn(fmt::format("{} of {} points: {} (the point's entry of 'warnings' says which; "
                     "hertzdash.simulate() at a point gives the message)",
                     count, results.size(), d.name));
  }
  return codes;
}

py::dict py_simulate_many(unsigned threads, const py::kwargs& kwargs) {
  RunOptions base;
  std::vector<std::pair<const RunOption*, DoubleArray>> arrays;
  std::size_t n = 1;
  for (const auto& [key, value] : kwargs) {
    const RunOption& o = option_named(key.cast<std::string>(), "simulate_many");
    const bool sequence = py::isinstance<py::array>(value) || py::isinstance<py::list>(value) ||
                          py::isinstance<py::tuple>(value);
    if (!sequence) {
      set_option(base, o, value);
      continue;
    }
    const std::string keyword = python_keyword(o.name);
    if (o.decl.type != ParameterType::number || o.group != RunOption::Group::setup)
      throw InvalidParameter(keyword, "an array", "a single value (arrays are taken for the numeric set-up options only)");
    const py::array given = py::array::ensure(value);
    if (!given || std::string("iuf").find(given.dtype().kind()) == std::string::npos)
      throw py::type_error(keyword + ": expected numbers");
    if (given.ndim() == 0) {  // a 0-d array is a scalar
      set_option(base, o, given.attr("item")());
      continue;
    }
    if (given.ndim() != 1) throw InvalidParameter(keyword, "an array", "a 1-D array of numbers");
    const auto len = static_cast<std::size_t>(given.shape(0));
    if (len != 1) {
      if (n != 1 && len != n)
        throw InvalidParameter(keyword, fmt::format("an array of length {}", len),
                               fmt::format("length {} like the other arrays, or 1", n));
      n = len;
    }
    arrays.emplace_back(&o, DoubleArray::ensure(given));
  }
  // Resolve every point first (validation raises here, naming the option and the point), then run.
  const SolverSettings solver = resolve_solver(base);
  refuse_trace_only_options(base, "simulate_many()");
  std::vector<DropTestSetup> setups;
  setups.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    RunOptions o = base;
    for (const auto& [option, a] : arrays) {
      set_number(o, *option, a.shape(0) == 1 ? a.at(0) : a.at(static_cast<py::ssize_t>(i)));
    }
    try {
      setups.push_back(resolve_setup(o, paper()));
    } catch (const InvalidParameter& e) {
      throw py::value_error(fmt::format("point {}: {}", i, e.message(KeySpelling::python)));
    }
  }
  std::vector<ImpactSummary> results(n);
  std::atomic<bool> cancel{false};
  const SweepOptions sweep{.threads = threads, .label = "hertzdash.simulate_many", .progress = false, .cancel = &cancel};
  const auto run_all = [&] {
    parallel_sweep(
        n, solver, [&](ImpactSimulator& sim, std::size_t i) { results[i] = sim.run(setups[i], base.damping); }, sweep);
  };
  if (!run_watching_signals(run_all, cancel)) throw py::error_already_set();  // KeyboardInterrupt (Ctrl-C)
  py::dict out;
  const auto points = static_cast<py::ssize_t>(n);
  for (const ResultField& output : many_outputs) {
    const std::string name(output.name);
    if (output.type == ResultType::number) {
      py::array_t<double> a(points);
      for (std::size_t i = 0; i < n; ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = output.value(results[i], setups[i]);
      out[name.c_str()] = a;
    } else if (output.type == ResultType::boolean) {
      py::array_t<bool> a(points);
      for (std::size_t i = 0; i < n; ++i)
        a.mutable_at(static_cast<py::ssize_t>(i)) = output.value(results[i], setups[i]) != 0;
      out[name.c_str()] = a;
    } else {
      out[name.c_str()] = warning_codes(results);
    }
  }
  return out;
}

py::object py_result_fields() {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const ResultField& f : result_fields)
    rows.push_back({{"name", f.name}, {"group", f.group}, {"type", json_type_name(f.type)}, {"unit", f.unit},
                    {"meaning", f.meaning}, {"json", f.in.json}, {"sweep", f.in.sweep},
                    {"simulate_many", f.in.python_many}});
  return to_python(rows);
}

// The names of the top-level fields `report` marks, comma-separated, in table order.
std::string result_names(bool ResultReports::*report) {
  std::string names;
  for (const ResultField& f : result_fields)
    if (f.in.*report && f.group.empty()) names += (names.empty() ? "" : ", ") + std::string(f.name);
  return names;
}

// ---- rigs: run("RIG", **options) and one function per registered rig (simulation/rigs/rig.hpp) ----

// The keywords of a rig's run into its options and inputs: its own inputs (and `extra`'s, the
// orbit's, into `extra_inputs`), else an option of a run; an unknown one is refused naming
// `function`.
void read_rig_keywords(const Rig& rig, const char* function, const py::kwargs& kwargs, RunOptions& options,
                       RigInputs& inputs, ParameterDecls extra = {}, RigInputs* extra_inputs = nullptr) {
  if (!rig.default_integrator.empty()) options.integrator = rig.default_integrator;
  auto named = [](ParameterDecls decls, const std::string& keyword) {
    return std::find_if(decls.begin(), decls.end(), [&](const ParameterDecl& d) { return python_keyword(d.key) == keyword; });
  };
  for (const auto& [key, value] : kwargs) {
    const std::string keyword = key.cast<std::string>();
    auto own = named(rig.inputs, keyword);
    RigInputs* target = &inputs;
    if (own == rig.inputs.end() && named(extra, keyword) != extra.end()) own = named(extra, keyword), target = extra_inputs;
    if (own == rig.inputs.end()) {
      std::string names;
      for (const ParameterDecls decls : {rig.inputs, extra})
        for (const ParameterDecl& d : decls) names += (names.empty() ? "" : ", ") + python_keyword(d.key);
      set_option(options, option_named(keyword, function, names), value);
    }
    else if (value.is_none()) continue;  // None: the default
    else if (own->type == ParameterType::text) target->texts[std::string(own->key)] = py::str(value).cast<std::string>();
    else if (py::isinstance<py::bool_>(value) || !py::hasattr(value, "__float__")) throw py::type_error(keyword + ": expected a number");
    else target->numbers[std::string(own->key)] = value.cast<double>();
  }
}

py::dict py_run_rig(const Rig& rig, const py::kwargs& kwargs) {
  RunOptions options;
  RigInputs inputs;
  read_rig_keywords(rig, rig.name.data(), kwargs, options, inputs);
  RigResult r;
  {
    py::gil_scoped_release release;
    r = run_rig(rig, options, paper(), inputs);
  }
  for (const std::string& w : r.warnings) warn(w);
  return to_python(to_json(rig, r));
}

// The options of `hertzdash orbit` or `continue` a Python call takes: numbers and texts (its
// --json, --csv and --mkdir aside: the dict is the JSON).
std::vector<ParameterDecl> analysis_options(std::string_view command) {
  std::vector<ParameterDecl> decls;
  for (const ParameterDecl& d : options_of_command(command))
    if (d.type != ParameterType::flag && d.key != "csv") decls.push_back(d);
  return decls;
}

// A rig `orbit` and `continue` take, by name.
const Rig& analysed_rig(const std::string& name) {
  const Rig* rig = find_rig(name);
  if (rig && rig->sequence) return *rig;
  std::string names;
  for (const Rig& r : rigs())
    if (r.sequence) names += (names.empty() ? "" : ", ") + std::string(r.name);
  throw InvalidParameter("rig", name, "one of: " + names);
}

// A call of `hertzdash COMMAND RIG --json` (orbit, continue, lyapunov, basins): the rig's keywords
// (impact_model instantaneous unless given) and the command's, then `run` (rig, options, inputs,
// the command's given options) -> (its result's JSON, a warning or empty), without the GIL.
template <class Run>
py::dict py_analysis(const std::string& name, std::string_view command, const char* function, const py::kwargs& kwargs,
                     Run&& run) {
  const Rig& rig = analysed_rig(name);
  RunOptions options;
  RigInputs inputs, given;
  inputs.texts[std::string(orbit_impact_model_note.key)] = std::string(orbit_impact_model);
  read_rig_keywords(rig, function, kwargs, options, inputs, analysis_options(command), &given);
  std::pair<nlohmann::ordered_json, std::string> out;
  {
    py::gil_scoped_release release;
    out = run(rig, options, inputs, given);
  }
  if (!out.second.empty()) warn(out.second);
  return to_python(out.first);
}

py::dict py_orbit(const std::string& name, const py::kwargs& kwargs) {
  return py_analysis(name, "orbit", "orbit", kwargs, [](const Rig& rig, const RunOptions& o, const RigInputs& in, const RigInputs& given) {
    const OrbitResult r = run_orbit(rig, o, paper(), in, orbit_request(given));
    return std::pair{to_json(rig, r), r.orbit.converged ? "" : "no periodic orbit found: " + r.orbit.failure};
  });
}

py::dict py_continuation(const std::string& name, const py::kwargs& kwargs) {
  return py_analysis(name, "continue", "continuation", kwargs,
                     [](const Rig& rig, const RunOptions& o, const RigInputs& in, const RigInputs& given) {
                       const ContinuationResult r = run_continuation(rig, o, paper(), in, continuation_request(given));
                       return std::pair{to_json(rig, r), r.failure.empty() ? "" : "no branch followed: " + r.failure};
                     });
}

py::dict py_basins(const std::string& name, const py::kwargs& kwargs) {
  return py_analysis(name, "basins", "basins", kwargs,
                     [](const Rig& rig, const RunOptions& o, const RigInputs& in, const RigInputs& given) {
                       const BasinsResult r = run_basins(rig, o, paper(), in, basins_request(given));
                       return std::pair{to_json(rig, r), r.failure.empty() ? "" : "no basins: " + r.failure};
                     });
}

py::dict py_lyapunov(const std::string& name, const py::kwargs& kwargs) {
  return py_analysis(name, "lyapunov", "lyapunov", kwargs,
                     [](const Rig& rig, const RunOptions& o, const RigInputs& in, const RigInputs& given) {
                       const LyapunovResult r = run_lyapunov(rig, o, paper(), in, lyapunov_request(given));
                       const LyapunovSpectrum& s = r.spectrum;
                       return std::pair{to_json(rig, r),
                                        s.converged ? std::string() : "the exponents did not converge: " +
                                                                          (s.failure.empty() ? "the run's halves disagree" : s.failure)};
                     });
}

// The docstring of orbit(), continuation() or lyapunov(): what it returns, then its own keywords.
std::string analysis_doc(std::string_view command, const std::string& head) {
  std::string doc = head;
  for (const ParameterDecl& d : analysis_options(command))
    doc += fmt::format("  {}: {}\n", python_keyword(d.key), help_text(d, KeySpelling::python));
  return doc;
}

std::string rig_doc(const Rig& rig) {
  std::string doc = fmt::format("{}(**options) -> dict\n\n{}, exactly `hertzdash {} --json`: ", rig.name, rig.summary, rig.name);
  for (const RigField& f : rig.results) doc += std::string(f.name) + ", ";
  for (const RigColumn& c : rig.table) doc += std::string(c.name) + " (a list: one per kept impact), ";
  doc += "end_reason, warnings, work, inputs, git_revision. Its own options:\n";
  for (const ParameterDecl& d : rig.inputs) doc += fmt::format("  {}: {}\n", python_keyword(d.key), help_text(d, KeySpelling::python));
  return doc + "and the options of simulate() but " + fmt::format("{}", fmt::join(rig.run_options_not_read, ", ")) + ".\n";
}

std::string options_doc() {
  std::string doc = "Options (keywords; each is the command line's --option, '-' written '_'):\n";
  for (const RunOption& o : run_options())
    doc += fmt::format("  {}: {}\n", python_keyword(o.name), help_text(o.decl, KeySpelling::python));
  return doc;
}

}  // namespace

PYBIND11_MODULE(hertzdash, m) {
  m.doc() =
      "hertzdash: Hertz spring + nonlinear dashpot impact models (Hongo et al.), the library behind the "
      "`hertzdash` program. SI units throughout; every key carries its unit (peak_force_N, contact_time_s).";
  m.attr("__version__") = version();
  m.attr("git_revision") = git_revision();
  m.attr("schema_version") = json_schema_version;

  // A refusal is a ValueError naming the Python keyword (ball_E, not --ball-E); a RuntimeError
  // names keys the same way.
  py::register_local_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidParameter& e) {
      PyErr_SetString(PyExc_ValueError, e.message(KeySpelling::python).c_str());
    } catch (const DataError& e) {
      PyErr_SetString(PyExc_ValueError, (std::string("bad data file: ") + e.what()).c_str());
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (StopIteration, ValueError, ...): its translator maps them
    } catch (const std::runtime_error& e) {  // a result that contradicts the model; keys as keywords: dt
      PyErr_SetString(PyExc_RuntimeError, spell_key_references(e.what(), KeySpelling::python).c_str());
    }
  });

  const std::string options = options_doc();
  m.def("simulate", &py_simulate,
        ("simulate(**options) -> dict\n\nOne drop test of the paper's set-up (a rod falling onto the nylon "
         "hemisphere), exactly `hertzdash simulate --json`: schema_version, " +
         result_names(&ResultReports::json) +
         ", inputs, git_revision (docs/json-output.md, result_fields(); yield_onset_pressure_Pa is None without a "
         "check, omega_n_fixed_point only for the iterated omega_n variants, elastic_rod only with "
         "rod_model='elastic'). Values are SI, units in the keys. Bad values raise ValueError with the program's "
         "message, naming the keyword. A fall-back of the integrator, an under-resolved fixed step, a step shortened "
         "for stability and a Hertz peak pressure above the onset of yield (ball_yield_stress times a factor of "
         "ball_nu, Johnson) are "
         "reported as UserWarnings, as the program reports them on stderr.\n\n" +
         options)
            .c_str());
  m.def("trace", &py_trace, py::arg("grid_step") = py::none(),
        ("trace(grid_step=None, **options) -> dict of NumPy arrays\n\nThe contact phase of `simulate`, the columns of "
         "`hertzdash simulate --trace` (data/measurements/README.md): t_s since contact onset; force_N and accel_mps2, "
         "what the load cell and the accelerometer read; velocity_mps and displacement_m (since onset) of the rod, "
         "downward positive; the model's own x_m (deformation), xdot_mps, contact_force_N (compressive positive) and "
         "rod_accel_mps2. Samples at the integrator's "
         "steps, or, with grid_step [s], on a uniform grid from contact onset (cubic Hermite interpolation of the "
         "positions and velocities, linear of force and acceleration).\n\n" +
         options)
            .c_str());
  m.def("restitution", &py_restitution,
        ("restitution(**options) -> dict\n\nThe law's effective restitution in the rigid-wall contact phase (no "
         "gravity), exactly `hertzdash restitution --json`.\n\n" +
         options)
            .c_str());
  m.def("calibrate_restitution", &calibrate, py::arg("target"),
        ("calibrate_restitution(target, **options) -> dict\n\nThe input e whose effective restitution is `target` "
         "(in (0, 1]), exactly `hertzdash restitution --target-restitution TARGET --json`.\n\n" +
         options)
            .c_str());
  m.def("bounce", &py_bounce, py::arg("bounces") = static_cast<double>(BounceOptions{}.impacts),
        py::arg("min_rebound_velocity") = BounceOptions{}.min_rebound_velocity_mps,
        py::arg("target_interval_restitution") = py::none(),
        ("bounce(bounces=5, min_rebound_velocity=1e-3, target_interval_restitution=None, **options) -> dict\n\n"
         "A drop and the impacts after it, exactly `hertzdash bounce --bounces N --min-rebound-velocity V "
         "[--target-interval-restitution E] --json` (docs/bounce.md): per impact the onset, separation and "
         "contact times, approach and rebound speeds, peak force and deformation (impacts), onset_times_s, "
         "e_from_intervals (the paper's measurement: (t_on[n+2] - t_on[n+1]) / (t_on[n+1] - t_on[n])), "
         "e_velocity_ratio, flights, end_reason, steps, rhs_evaluations, integrator_used, inputs, "
         "schema_version, git_revision; viscous_time_constant_s for kuwabara-kono, and interval_calibration "
         "when target_interval_restitution (in (0, 1]) asks for the input e whose first interval ratio is it. "
         "bounces: impacts followed, the first included, in [1, 1000]; min_rebound_velocity [m/s] >= 0 ends the "
         "sequence after a slower rebound. Bad values raise ValueError naming bounces, "
         "min_rebound_velocity, target_interval_restitution or the option.\n\n" +
         options)
            .c_str());
  m.def("virtual_measurement", &py_virtual_measurement, py::arg("path"), py::arg("sample_rate") = MeasurementChain{}.sample_rate_Hz,
        py::arg("anti_alias") = 0.0, py::arg("noise") = 0.0, py::arg("seed") = std::uint64_t{1},
        py::arg("channels") = "force_N,accel_mps2,displacement_m",
        ("virtual_measurement(path, sample_rate=1e6, anti_alias=0, noise=0, seed=1, "
         "channels='force_N,accel_mps2,displacement_m', **options) -> dict\n\nA SYNTHETIC trace: the drop test "
         "recorded as a measurement would be (anti-alias filter [Hz, 0 = none], sampling [Hz], white noise as a "
         "fraction of each channel's peak, seeded), written to `path` in the measured-trace format "
         "(data/measurements/README.md) with `synthetic: true`; exactly `hertzdash simulate --trace PATH "
         "--trace-format measured ...`. Returns simulate()'s dict.\n\n" +
         options)
            .c_str());
  for (const FitFunction& f : fit_functions)
    m.def(f.name, [&f](const std::string& path, const py::kwargs& kwargs) { return py_fit_kind(f, path, kwargs); },
          py::arg(f.path), (fit_doc(f) + "\n" + options).c_str());
  m.def("laws", [] { return to_python(registered_laws_json()); },
        "laws() -> list of dict\n\nThe registered damping laws: name, citation, formula, coefficients, validity, "
        "force_continuous_at_onset, dissipative (`hertzdash models --json`).");
  m.def("paper_parameters", &py_paper_parameters,
        "paper_parameters() -> dict\n\nThe paper's Tables 1-3 and the stated assumptions as the library reads them "
        "(data/*.csv): rods (name, diameter_m, length_m, mass_kg, restitution, zeta_printed, natural_frequency_hz, "
        "E_Pa, nu), ball (diameter_m, height_m, mass_kg, E_Pa, E_min_Pa, E_max_Pa, nu, radius_m), gravity_mps2, "
        "uncertain_inputs (the inputs the joint uncertainty study varies: parameter, unit, value, distribution "
        "uniform|normal|lognormal with lower and upper (the truncation, +-inf if none), mean and sd (normal), median "
        "and log_sd (lognormal), and reason), and data_dir, the directory they were read from.");
  m.def("integrators", &py_integrators,
        "integrators() -> list of dict\n\nThe integrator table: name, step_control, method, variables, "
        "needs_root_polynomial_law and the fall-backs.");
  m.def("result_fields", &py_result_fields,
        "result_fields() -> list of dict\n\nThe result fields of an impact, declared once "
        "(simulation/run/result_fields.hpp), in the order of simulate()'s keys: name (units in it), group (the key of "
        "the object it sits in, e.g. elastic_rod; empty at the top level), type (as docs/json-output.md names it), "
        "unit (SI; '1' dimensionless, empty for no quantity), meaning, and where each is reported: json "
        "(simulate()), sweep (a column of `hertzdash sweep`), simulate_many.");
  m.def("simulate_many", &py_simulate_many, py::arg("threads") = 0,
        ("simulate_many(threads=0, **options) -> dict of NumPy arrays\n\nMany drop tests in parallel in C++ (the "
         "GIL released; threads=0: all cores). Numeric set-up options may be 1-D arrays of one common length "
         "(scalars and length-1 arrays broadcast); the solver options are one setting for all. Returns " +
         result_names(&ResultReports::python_many) +
         ": NumPy arrays (bool for separated), element i equal to simulate() of point i, except warnings (a list "
         "per point of the codes of simulate()'s warnings; one UserWarning per code says how many points carry "
         "it). A bad value "
         "raises ValueError naming the option and the point; a result that contradicts the model, RuntimeError.\n\n" +
         options)
            .c_str());
  for (const Rig& rig : rigs())
    m.def(std::string(rig.name).c_str(), [&rig](const py::kwargs& kwargs) { return py_run_rig(rig, kwargs); },
          rig_doc(rig).c_str());
  m.def(
      "run",
      [](const std::string& name, const py::kwargs& kwargs) {
        const Rig* rig = find_rig(name);
        if (!rig) throw InvalidParameter("rig", name, "a registered rig (hertzdash.rigs())");
        return py_run_rig(*rig, kwargs);
      },
      py::arg("name"), py::pos_only(),
      "run(name, /, **options) -> dict\n\nThe registered rig `name` (see rigs()), as hertzdash.NAME(**options).");
  m.def("orbit", &py_orbit, py::arg("name"), py::pos_only(),
        analysis_doc("orbit", "orbit(name, /, **options) -> dict\n\nA rig's periodic orbit by shooting, exactly "
                              "`hertzdash orbit RIG --json` (docs/orbits.md): converged, period, section_phase, "
                              "section_state, multipliers ([re, im] pairs), multiplier_moduli, stable, "
                              "newton_residual, the orbit's impacts, inputs. Not converged: converged False, failure, "
                              "and a UserWarning. The rig's options (impact_model instantaneous unless given), and:\n")
            .c_str());
  m.def("continuation", &py_continuation, py::arg("name"), py::pos_only(),
        analysis_doc("continue", "continuation(name, /, **options) -> dict\n\nThe branches of a rig's periodic orbits "
                                 "in a parameter, exactly `hertzdash continue RIG --json` (docs/orbits.md): branch (a "
                                 "dict per point), events (fold, period-doubling, neimark-sacker, grazing), ends, "
                                 "start, inputs. No orbit at the start: failure, and a UserWarning. The rig's options "
                                 "(impact_model instantaneous unless given), and:\n")
            .c_str());
  m.def("lyapunov", &py_lyapunov, py::arg("name"), py::pos_only(),
        analysis_doc("lyapunov", "lyapunov(name, /, **options) -> dict\n\nThe Lyapunov exponents of a rig's attractor, "
                                 "exactly `hertzdash lyapunov RIG --json` (docs/orbits.md): exponents_per_period, "
                                 "exponents_per_impact (largest first), sum_per_impact, expected_sum_per_impact, "
                                 "converged, running, inputs. Not converged: a UserWarning. The rig's options "
                                 "(impact_model instantaneous unless given), and:\n")
            .c_str());
  m.def("basins", &py_basins, py::arg("name"), py::pos_only(),
        analysis_doc("basins", "basins(name, /, **options) -> dict\n\nThe basins of attraction of a rig's section, "
                               "exactly `hertzdash basins RIG --json` (docs/orbits.md): position_m and velocity_mps "
                               "(the grid's axes), attractors (kind, period, impact_phase, cells, fraction), cell (one "
                               "list per velocity row of attractor indices, -1 inside a wall), inputs. The rig's "
                               "options (impact_model instantaneous unless given), and:\n")
            .c_str());
  m.def("export_decks", &py_export_decks, py::arg("engine"), py::arg("out"), py::arg("engine_model") = "",
        py::arg("steps_per_contact") = py::none(),
        ("export_decks(engine, out, engine_model='', steps_per_contact=None, **options) -> dict\n\nA contact's "
         "input decks for LAMMPS, LIGGGHTS or YADE (engine " + engine_names() + ") written into the existing "
         "directory out (sphere_sphere.in, sphere_wall.in, contact_lines.in; .py for yade), for the engine model "
         "equal to the law `damping` "
         "names, exactly `hertzdash export --engine E --out DIR --json` (docs/engines.md): hertzdash's prediction "
         "of each impact under impacts.\n\n" +
         options)
            .c_str());
  m.def("conformance", &py_conformance, py::arg("engine"), py::arg("steps_per_contact") = py::none(),
        ("conformance(engine, steps_per_contact=None, **options) -> dict\n\nThe installed engine run on every "
         "contact model it has at three speeds beside the law each equals, exactly `hertzdash conformance --engine E "
         "--json` (docs/engines.md): rows of engine_model, hertzdash_law, impact, speed_mps, e_asked, e_hertzdash, "
         "e_engine, ...\n\n" +
         options)
            .c_str());
  m.def(
      "rigs",
      [] {
        py::list names;
        for (const Rig& rig : rigs()) names.append(std::string(rig.name));
        return names;
      },
      "rigs() -> list of str\n\nThe registered rigs, each a function of this module and `hertzdash RIG`.");
}

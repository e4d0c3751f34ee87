#include "hertzdash/simulation/trace_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/gsl_root.hpp"
#include "hertzdash/simulation/impact_history.hpp"
#include "hertzdash/simulation/impact_simulator.hpp"

#include <fmt/format.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <tuple>
#include <type_traits>

namespace hertzdash {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// ---- Which options may be fitted: those declared fittable (simulation/run_options.hpp), within
// their declared ranges, starting from their values in the resolved set-up.

const RunOption* find_fittable(const std::string& name) {
  const RunOption* o = find_run_option(name);
  return o && o->decl.fittable ? o : nullptr;
}

void set_option(RunOptions& o, const std::string& name, double value) { set_number(o, *find_run_option(name), value); }

// ---- Unbounded fitting variables.

struct Transform {
  double lo, hi;
  bool two_sided() const { return std::isfinite(hi); }
  double p(double z) const { return two_sided() ? lo + (hi - lo) / (1.0 + std::exp(-z)) : lo + std::exp(z); }
  double z(double p) const { return two_sided() ? std::log((p - lo) / (hi - p)) : std::log(p - lo); }
  double dp_dz(double z) const {
    if (!two_sided()) return std::exp(z);
    const double s = 1.0 / (1.0 + std::exp(-z));
    return (hi - lo) * s * (1.0 - s);
  }
};

// ---- The model: the run options with the fitted values, from onset, by RK4 at a fixed step.

class TraceModel {
 public:
  TraceModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names, int steps_per_contact)
      : base_(std::move(base)), paper_(&paper), names_(std::move(names)) {
    const DropTestSetup s = onset_setup(base_);
    time_scale_s_ = undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, approach_speed(s)).contact_time_s;
    solver_.integrator = IntegratorKind::rk4;
    solver_.dt_s = time_scale_s_ / steps_per_contact;
    simulator_.emplace(solver_);
  }

  /// t_H at the initial parameters [s]: the unit of the onset variable and of the step.
  double time_scale_s() const { return time_scale_s_; }
  int runs() const { return runs_; }
  const SolverSettings& solver() const { return solver_; }

  RunOptions options_at(const std::vector<double>& values) const {
    RunOptions o = base_;
    for (std::size_t j = 0; j < names_.size(); ++j) set_option(o, names_[j], values[j]);
    return o;
  }

  /// The impact at these parameter values (the last one is kept), or nullptr where they leave
  /// the model's domain: values the set-up rejects, or an undamped Hertz contact longer than
  /// max_contact_growth times the starting one (the fixed step would take that many more steps).
  const ImpactHistory* history(const std::vector<double>& values) {
    if (values_valid_ && values == values_) return history_ ? &*history_ : nullptr;
    values_ = values;
    values_valid_ = true;
    history_.reset();
    DropTestSetup s;
    try {
      s = onset_setup(options_at(values));
    } catch (const InvalidParameter&) {
      return nullptr;
    }
    if (undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, approach_speed(s)).contact_time_s >
        max_contact_growth * time_scale_s_)
      return nullptr;
    std::vector<TraceSample> trace;
    const ImpactSummary summary = simulator_->run(s, base_.damping, &trace);
    ++runs_;
    history_.emplace(std::move(trace), s.gravity_mps2);
    summary_ = summary;
    return &*history_;
  }
  double contact_time_s() const { return summary_.contact_time_s; }
  const ImpactSummary& summary() const { return summary_; }

 private:
  DropTestSetup onset_setup(const RunOptions& o) const {
    DropTestSetup s = resolve_setup(o, *paper_);
    s.impact_velocity_mps = approach_speed(s);  // start at contact onset: the drop before it is exact
    return s;
  }

  RunOptions base_;
  const PaperParameters* paper_;
  std::vector<std::string> names_;
  double time_scale_s_ = 0;
  SolverSettings solver_;
  std::optional<ImpactSimulator> simulator_;
  static constexpr double max_contact_growth = 50;
  std::vector<double> values_;
  bool values_valid_ = false;
  std::optional<ImpactHistory> history_;
  ImpactSummary summary_;  // of the last run
  int runs_ = 0;
};

// ---- Trace checks and the channels' noise.

struct Observation {
  std::size_t channel;
  double t_s, y, inv_sigma;
};

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// sigma of the channel `name` from the second differences of consecutive samples with values
// (see the header), at least the rounding of a recorder whose step is the smallest change
// between samples (q / sqrt(12)) and 1e-6 of the largest magnitude (a noise-free virtual
// experiment). A channel that never changes carries no information: DataError.
double noise_sigma(const std::vector<double>& y, const std::string& file, const std::string& name) {
  std::vector<double> d2;
  for (std::size_t i = 1; i + 1 < y.size(); ++i)
    if (std::isfinite(y[i - 1]) && std::isfinite(y[i]) && std::isfinite(y[i + 1]))
      d2.push_back(y[i + 1] - 2.0 * y[i] + y[i - 1]);
  const double m = median(d2);
  for (double& d : d2) d = std::abs(d - m);
  double largest = 0, step = inf;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i])) continue;
    largest = std::max(largest, std::abs(y[i]));
    if (i > 0 && std::isfinite(y[i - 1]) && y[i] != y[i - 1]) step = std::min(step, std::abs(y[i] - y[i - 1]));
  }
  if (!std::isfinite(step))
    throw DataError(fmt::format("{}: the {} column never changes: it carries nothing to fit", file, name));
  const double mad = d2.empty() ? 0.0 : 1.4826 * median(d2) / std::sqrt(6.0);
  return std::max({mad, step / std::sqrt(12.0), 1e-6 * largest});
}

std::vector<std::string> channels_to_fit(const MeasuredTrace& trace, const TraceFitSettings& settings) {
  std::vector<std::string> out;
  for (const std::string& c : measured_quantity_columns()) {
    const bool asked = settings.channels.empty() ||
                       std::find(settings.channels.begin(), settings.channels.end(), c) != settings.channels.end();
    if (!asked) continue;
    const std::vector<double>& y = *quantity(trace, c);
    if (y.empty()) {
      if (settings.channels.empty()) continue;
      throw DataError(fmt::format("{}: no {} column to fit (--channels)", trace.path.string(), c));
    }
    if (std::none_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); })) {
      if (settings.channels.empty()) continue;
      throw DataError(fmt::format("{}: the {} column has no values (--channels)", trace.path.string(), c));
    }
    out.push_back(c);
  }
  if (out.empty()) throw DataError(trace.path.string() + ": no channel to fit");
  return out;
}

MeasuredTrace resampled(const MeasuredTrace& in, double rate_Hz) {
  MeasuredTrace out = in;
  out.t_s.clear();
  const double bin = 1.0 / rate_Hz, t0 = in.t_s.front();
  std::vector<std::string> present;
  for (const std::string& c : measured_quantity_columns())
    if (!quantity(in, c)->empty()) present.push_back(c), quantity(out, c)->clear();
  std::size_t i = 0;
  while (i < in.t_s.size()) {
    const auto k = std::floor((in.t_s[i] - t0) / bin);
    std::size_t j = i;
    double t_sum = 0;
    while (j < in.t_s.size() && std::floor((in.t_s[j] - t0) / bin) == k) t_sum += in.t_s[j++];
    out.t_s.push_back(t_sum / static_cast<double>(j - i));
    for (const std::string& c : present) {
      const std::vector<double>& y = *quantity(in, c);
      double sum = 0;
      int count = 0;
      for (std::size_t r = i; r < j; ++r)
        if (std::isfinite(y[r])) sum += y[r], ++count;
      quantity(out, c)->push_back(count ? sum / count : NAN);
    }
    i = j;
  }
  return out;
}

double median_interval_s(const std::vector<double>& t) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
  return median(dt);
}

std::vector<double> initial_values(const RunOptions& base, const PaperParameters& paper,
                                   const std::vector<FitParameter>& parameters) {
  const DropTestSetup s = resolve_setup(base, paper);
  std::vector<double> v;
  for (const FitParameter& p : parameters) {
    const std::optional<double> x = find_fittable(p.option)->value_in_setup(s);
    if (!x)
      throw InvalidParameter("fit", p.option,
                             fmt::format("given a starting value: {} is unset and has no default for this run",
                                         key_reference(p.option)));
    if (!(*x > p.lower && *x < p.upper))
      throw InvalidParameter("fit", fmt::format("{}:{}:{}", p.option, format_value(p.lower), format_value(p.upper)),
                             fmt::format("bounds around the starting value {} {} (set it inside them)",
                                         key_reference(p.option), format_value(*x)));
    v.push_back(*x);
  }
  return v;
}

// Where the contact starts to show: the first time the force exceeds, or the acceleration falls
// below g by, ten noise levels. Empty without such a channel or crossing.
std::optional<double> first_departure(const std::vector<std::string>& names, const std::vector<double>& sigma, double g,
                                      const std::function<double(std::size_t, std::size_t)>& value, std::size_t count,
                                      const std::function<double(std::size_t)>& time) {
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t c = 0; c < names.size(); ++c) {
      const double v = value(c, i);
      if ((names[c] == "force_N" && v > 10 * sigma[c]) || (names[c] == "accel_mps2" && g - v > 10 * sigma[c]))
        return time(i);
    }
  return std::nullopt;
}

// The onset on the trace's clock that makes the model's departure coincide with the trace's
// (0 when either has none).
double onset_guess_s(const MeasuredTrace& trace, const std::vector<ChannelFit>& channels, const ImpactHistory& model,
                     double g, double dt_s) {
  std::vector<std::string> names;
  std::vector<double> sigma;
  for (const ChannelFit& c : channels) names.push_back(c.name), sigma.push_back(c.noise_sigma);
  const auto in_trace = first_departure(
      names, sigma, g,
      [&](std::size_t c, std::size_t i) {
        const double v = (*quantity(trace, names[c]))[i];
        return std::isfinite(v) ? v : (names[c] == "accel_mps2" ? g : 0.0);
      },
      trace.t_s.size(), [&](std::size_t i) { return trace.t_s[i]; });
  const auto steps = static_cast<std::size_t>(model.contact_time_s() / dt_s) + 1;
  const auto in_model = first_departure(
      names, sigma, g,
      [&](std::size_t c, std::size_t i) {
        return instrument_channel(model.instruments_at(static_cast<double>(i) * dt_s), names[c]);
      },
      steps, [&](std::size_t i) { return static_cast<double>(i) * dt_s; });
  return in_trace && in_model ? *in_trace - *in_model : 0.0;
}

// ---- The least-squares problem in the unbounded variables z = (transformed parameters, t0 / t_H).

class FitProblem {
 public:
  FitProblem(std::vector<Observation> obs, TraceModel& model, std::vector<Transform> transforms,
             std::vector<std::string> channels)
      : obs_(std::move(obs)), model_(&model), transforms_(std::move(transforms)), channels_(std::move(channels)) {}

  std::size_t n() const { return obs_.size(); }
  std::size_t p() const { return transforms_.size() + 1; }

  std::vector<double> physical(const double* z) const {
    std::vector<double> v;
    for (std::size_t j = 0; j < transforms_.size(); ++j) v.push_back(transforms_[j].p(z[j]));
    return v;
  }
  double onset_s(const double* z) const { return z[transforms_.size()] * model_->time_scale_s(); }

  /// The model's value of each observation's channel at z; empty outside the model's domain.
  std::vector<double> model_values(const double* z) {
    const ImpactHistory* h = model_->history(physical(z));
    if (!h) return {};
    const double t0 = onset_s(z);
    std::vector<double> m(obs_.size());
    for (std::size_t i = 0; i < obs_.size(); ++i)
      m[i] = instrument_channel(h->instruments_at(obs_[i].t_s - t0), channels_[obs_[i].channel]);
    return m;
  }

  /// Outside the model's domain every residual is `outside` (1e30): the trust region rejects the
  /// step and shrinks, as it does for any step that raises the cost.
  void residuals(const double* z, double* r) {
    const std::vector<double> m = model_values(z);
    for (std::size_t i = 0; i < obs_.size(); ++i) r[i] = m.empty() ? outside : (obs_[i].y - m[i]) * obs_[i].inv_sigma;
  }
  static constexpr double outside = 1e30;

  /// Central differences, step 1e-6 in every z (relative 1e-6 of p - lower; 1e-6 t_H for the onset).
  void jacobian(const double* z, gsl_matrix* J) {
    std::vector<double> zz(z, z + p()), plus(n()), minus(n());
    for (std::size_t j = 0; j < p(); ++j) {
      const double h = 1e-6;
      zz[j] = z[j] + h;
      residuals(zz.data(), plus.data());
      zz[j] = z[j] - h;
      residuals(zz.data(), minus.data());
      zz[j] = z[j];
      for (std::size_t i = 0; i < n(); ++i) gsl_matrix_set(J, i, j, (plus[i] - minus[i]) / (2.0 * h));
    }
  }

  const std::vector<Observation>& observations() const { return obs_; }
  const std::vector<Transform>& transforms() const { return transforms_; }
  std::exception_ptr error;

 private:
  std::vector<Observation> obs_;
  TraceModel* model_;
  std::vector<Transform> transforms_;
  std::vector<std::string> channels_;
};

int residuals_thunk(const gsl_vector* z, void* params, gsl_vector* f) {
  auto* problem = static_cast<FitProblem*>(params);
  try {
    problem->residuals(z->data, f->data);
    return GSL_SUCCESS;
  } catch (...) {
    problem->error = std::current_exception();
    return GSL_EBADFUNC;
  }
}

int jacobian_thunk(const gsl_vector* z, void* params, gsl_matrix* J) {
  auto* problem = static_cast<FitProblem*>(params);
  try {
    problem->jacobian(z->data, J);
    return GSL_SUCCESS;
  } catch (...) {
    problem->error = std::current_exception();
    return GSL_EBADFUNC;
  }
}

// Condition number of J with columns scaled to relative changes of the parameters.
double scaled_condition_number(const gsl_matrix* J, const FitProblem& problem, const double* z) {
  const std::size_t n = J->size1, p = J->size2;
  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> A(gsl_matrix_alloc(n, p), &gsl_matrix_free);
  gsl_matrix_memcpy(A.get(), J);
  for (std::size_t j = 0; j + 1 < p; ++j) {
    const Transform& t = problem.transforms()[j];
    const double value = t.p(z[j]), scale = value != 0 ? std::abs(value) : 1.0;
    gsl_vector_view column = gsl_matrix_column(A.get(), j);
    gsl_vector_scale(&column.vector, scale / t.dp_dz(z[j]));
  }
  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> V(gsl_matrix_alloc(p, p), &gsl_matrix_free);
  const std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> S(gsl_vector_alloc(p), &gsl_vector_free),
      work(gsl_vector_alloc(p), &gsl_vector_free);
  if (const int status = gsl_linalg_SV_decomp(A.get(), V.get(), S.get(), work.get()); status != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_linalg_SV_decomp failed: ") + gsl_strerror(status));
  const double smallest = gsl_vector_min(S.get()), largest = gsl_vector_max(S.get());
  return smallest > 0 ? largest / smallest : inf;
}

std::string stop_reason(int status, int info) {
  if (status == GSL_EMAXITER) return "maximum number of iterations reached";
  if (status == GSL_ENOPROG) return "no further decrease of the cost within its resolution";
  return info == 1 ? "small step (xtol)" : "small gradient (gtol)";
}

// The trace as fitted, and its channels with their noise (ChannelFit's name and noise_sigma).
struct PreparedTrace {
  MeasuredTrace trace;
  std::vector<ChannelFit> channels;
};

// Resample if asked, and check the trace: a channel to fit, a sampling interval that resolves
// the model's contact at the starting values (`contact_time_s`: min_samples_per_contact samples;
// the message says the least rate), a contact the noise does not hide, enough samples. Throws
// DataError naming the file.
PreparedTrace prepare_trace(const MeasuredTrace& trace, const TraceFitSettings& settings, double contact_time_s,
                            double g) {
  const std::string file = trace.path.string();
  MeasuredTrace t = trace;
  if (settings.resample_Hz != 0) {
    require_positive("resample", settings.resample_Hz, "Hz");
    const double rate = 1.0 / median_interval_s(trace.t_s);
    if (!(settings.resample_Hz < rate))
      throw InvalidParameter("resample", format_value(settings.resample_Hz),
                             fmt::format("below the trace's sampling rate, {:.6g} Hz", rate));
    t = resampled(trace, settings.resample_Hz);
  }
  const double tc = contact_time_s, dt = median_interval_s(t.t_s);
  if (!(tc / dt >= min_samples_per_contact))
    throw DataError(fmt::format("{}: sampled every {:.3g} s ({:.4g} Hz), too coarse: the model's contact lasts {:.3g} s "
                                "and needs at least {:g} samples, a sampling rate of at least {:.4g} Hz",
                                file, dt, 1.0 / dt, tc, min_samples_per_contact, min_samples_per_contact / tc));

  // A contact must stand out of the noise by ten noise levels in some channel: the force above
  // zero, the deceleration below g, the velocity reversed (a rebound), or the displacement
  // returning from its largest value (the rod coming back up).
  PreparedTrace prepared;
  bool contact = false;
  std::string seen;
  for (const std::string& name : channels_to_fit(t, settings)) {
    const std::vector<double>& y = *quantity(t, name);
    const double sigma = noise_sigma(y, file, name);
    ChannelFit channel;
    channel.name = name;
    channel.noise_sigma = sigma;
    prepared.channels.push_back(channel);
    double signature = 0, last = NAN, peak = -inf;
    for (double v : y) {
      if (!std::isfinite(v)) continue;
      if (name == "force_N") signature = std::max(signature, v);
      else if (name == "accel_mps2") signature = std::max(signature, g - v);
      else if (name == "velocity_mps") signature = std::max(signature, -v);
      else peak = std::max(peak, v), last = v;
    }
    if (name == "displacement_m") signature = peak - last;
    contact = contact || signature > 10.0 * sigma;
    seen += fmt::format("{}{} {:.3g} against a noise of {:.3g}", seen.empty() ? "" : "; ", name, signature, sigma);
  }
  if (!contact)
    throw DataError(fmt::format("{}: no contact in the trace: no channel departs from free fall by ten noise levels "
                                "(force above 0, g minus acceleration, upward velocity, displacement's return: {})",
                                file, seen));
  if (t.t_s.size() <= settings.parameters.size() + 1)
    throw DataError(fmt::format("{}: {} samples cannot determine {} parameters", file, t.t_s.size(), settings.parameters.size() + 1));
  prepared.trace = std::move(t);
  return prepared;
}

}  // namespace

const FittedParameter& TraceFit::parameter(const std::string& name) const {
  for (const FittedParameter& p : parameters)
    if (p.name == name) return p;
  throw std::out_of_range("fit: no fitted parameter " + name);
}

std::string fittable_option_names() {
  std::string s;
  for (const RunOption* o : fittable_options()) s += (s.empty() ? "" : ", ") + o->name;
  return s;
}

std::vector<FitParameter> parse_fit_parameters(const std::string& list) {
  std::vector<FitParameter> out;
  for (const std::string& item : split_option_list(list)) {
    const std::size_t colon = item.find(':');
    const RunOption* f = find_fittable(item.substr(0, colon));
    if (!f)
      throw InvalidParameter("fit", list,
                             "a comma-separated list of NAME or NAME:LOWER:UPPER with NAME one of: " + fittable_option_names());
    const double lower = f->decl.range.lo, upper = f->decl.range.hi;
    FitParameter p{f->name, lower, upper};
    if (colon != std::string::npos) {
      const std::string bounds = item.substr(colon + 1);
      const std::size_t mid = bounds.find(':');
      auto number = [&](const std::string& text) {
        const std::optional<double> v = parse_option_number(text);
        if (!v) throw InvalidParameter("fit", item, "NAME:LOWER:UPPER with two decimal numbers, LOWER < UPPER");
        return *v;
      };
      if (mid == std::string::npos) throw InvalidParameter("fit", item, "NAME:LOWER:UPPER with two numbers, LOWER < UPPER");
      p.lower = number(bounds.substr(0, mid));
      p.upper = number(bounds.substr(mid + 1));
      if (!(p.lower < p.upper) || !std::isfinite(p.lower) || p.lower < lower || p.upper > upper)
        throw InvalidParameter("fit", item,
                               fmt::format("NAME:LOWER:UPPER with LOWER < UPPER, LOWER finite, within {}'s range [{}, {}]",
                                           key_reference(f->name), format_value(lower), format_value(upper)));
    }
    for (const FitParameter& q : out)
      if (q.option == p.option) throw InvalidParameter("fit", list, "a list naming each parameter once");
    out.push_back(p);
  }
  return out;
}

TraceFit fit_trace(const MeasuredTrace& trace_in, const RunOptions& base, const PaperParameters& paper,
                   const TraceFitSettings& settings) {
  use_gsl_return_codes();
  if (!(settings.steps_per_contact >= 100)) throw InvalidParameter("steps per contact", std::to_string(settings.steps_per_contact), ">= 100");
  std::vector<std::string> names;
  std::vector<Transform> transforms;
  for (const FitParameter& p : settings.parameters) {
    names.push_back(p.option);
    transforms.push_back({p.lower, p.upper});
  }
  const std::vector<double> initial = initial_values(base, paper, settings.parameters);
  TraceModel model(base, paper, names, settings.steps_per_contact);
  const ImpactHistory* at_start = model.history(initial);
  if (!at_start) throw InvalidParameter("fit", "the starting values", "values inside the model's domain");
  const double g = resolve_setup(base, paper).gravity_mps2;
  PreparedTrace prepared = prepare_trace(trace_in, settings, model.contact_time_s(), g);
  const MeasuredTrace& trace = prepared.trace;

  TraceFit fit;
  fit.law = base.damping;
  fit.channels = std::move(prepared.channels);
  std::vector<std::string> channels;
  std::vector<Observation> obs;
  for (std::size_t c = 0; c < fit.channels.size(); ++c) {
    ChannelFit& ch = fit.channels[c];
    channels.push_back(ch.name);
    const std::vector<double>& y = *quantity(trace, ch.name);
    for (std::size_t i = 0; i < y.size(); ++i)
      if (std::isfinite(y[i])) obs.push_back({c, trace.t_s[i], y[i], 1.0 / ch.noise_sigma}), ++ch.samples;
  }
  FitProblem problem(std::move(obs), model, transforms, channels);
  const std::size_t n = problem.n(), p = problem.p();
  if (n <= p) throw DataError(fmt::format("{}: {} values cannot determine {} parameters", trace.path.string(), n, p));

  // Start: the initial values, and the onset time that fits best at them: first where the
  // trace's contact departs from free fall minus where the model's does (onset_guess_s), then
  // a scan over +-0.3 t_H around it (the onset needs no model run).
  std::vector<double> z0;
  for (std::size_t j = 0; j < transforms.size(); ++j) z0.push_back(transforms[j].z(initial[j]));
  const double guess = onset_guess_s(trace, fit.channels, *at_start, g, model.solver().dt_s) / model.time_scale_s();
  z0.push_back(guess);
  {
    std::vector<double> r(n);
    double best = inf, best_z = guess;
    for (int k = -30; k <= 30; ++k) {
      z0.back() = guess + 0.01 * k;
      problem.residuals(z0.data(), r.data());
      double chi2 = 0;
      for (double v : r) chi2 += v * v;
      if (chi2 < best) best = chi2, best_z = z0.back();
    }
    z0.back() = best_z;
  }

  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  const std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p), &gsl_multifit_nlinear_free);
  if (!w) throw std::bad_alloc();
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals_thunk;
  fdf.df = jacobian_thunk;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &problem;
  gsl_vector_view start = gsl_vector_view_array(z0.data(), p);
  int status = gsl_multifit_nlinear_init(&start.vector, &fdf, w.get());
  if (problem.error) std::rethrow_exception(problem.error);
  if (status != GSL_SUCCESS) throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_init failed: ") + gsl_strerror(status));
  int info = 0;
  status = gsl_multifit_nlinear_driver(settings.max_iterations, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, w.get());
  if (problem.error) std::rethrow_exception(problem.error);
  if (status != GSL_SUCCESS && status != GSL_EMAXITER && status != GSL_ENOPROG)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_driver failed: ") + gsl_strerror(status));
  fit.stop_reason = stop_reason(status, info);
  fit.converged = status == GSL_SUCCESS;
  fit.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w.get()));

  const gsl_vector* zv = gsl_multifit_nlinear_position(w.get());
  const std::vector<double> z(zv->data, zv->data + p);
  const gsl_matrix* J = gsl_multifit_nlinear_jac(w.get());
  const gsl_vector* f = gsl_multifit_nlinear_residual(w.get());
  gsl_blas_ddot(f, f, &fit.chi_square);
  fit.samples = n;
  fit.reduced_chi_square = fit.chi_square / static_cast<double>(n - p);

  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> covar(gsl_matrix_alloc(p, p), &gsl_matrix_free);
  if (const int s = gsl_multifit_nlinear_covar(J, 0.0, covar.get()); s != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_covar failed: ") + gsl_strerror(s));
  gsl_matrix_scale(covar.get(), fit.reduced_chi_square);
  fit.condition_number = scaled_condition_number(J, problem, z.data());

  // A parameter the trace does not see has a zero column in J; GSL's pivoted covariance then
  // sets its variance to zero, which would read as perfectly determined: it is infinite.
  for (std::size_t j = 0; j < p; ++j) {
    gsl_vector_const_view column = gsl_matrix_const_column(J, j);
    if (gsl_blas_dnrm2(&column.vector) == 0 || !(gsl_matrix_get(covar.get(), j, j) > 0))
      for (std::size_t i = 0; i < p; ++i) {
        gsl_matrix_set(covar.get(), i, j, i == j ? inf : NAN);
        gsl_matrix_set(covar.get(), j, i, i == j ? inf : NAN);
      }
  }
  const std::vector<double> estimate = problem.physical(z.data());
  bool finite_errors = true;
  for (std::size_t j = 0; j < p; ++j) {
    FittedParameter fp;
    const double sz = std::sqrt(gsl_matrix_get(covar.get(), j, j));
    if (j < transforms.size()) {
      const Transform& t = transforms[j];
      fp = {names[j], initial[j], estimate[j], std::abs(t.dp_dz(z[j])) * sz, t.lo, t.hi};
      // At a bound the transform flattens (dp/dz -> 0) and the standard error shrinks with it:
      // within 1e-3 of the range (two bounds) or of the starting distance from the bound.
      fp.at_bound = t.two_sided() ? std::abs(z[j]) > std::log(1e3)
                                  : (estimate[j] - t.lo) < 1e-3 * std::abs(initial[j] - t.lo);
    } else {
      fp = {"onset-time", guess * model.time_scale_s(), problem.onset_s(z.data()), model.time_scale_s() * sz, -inf, inf};
    }
    finite_errors = finite_errors && std::isfinite(fp.standard_error);
    fit.parameters.push_back(fp);
  }
  for (std::size_t i = 0; i < p; ++i) {
    fit.correlation.emplace_back();
    for (std::size_t j = 0; j < p; ++j)
      fit.correlation.back().push_back(gsl_matrix_get(covar.get(), i, j) /
                                       std::sqrt(gsl_matrix_get(covar.get(), i, i) * gsl_matrix_get(covar.get(), j, j)));
  }
  double largest_correlation = 0;
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < i; ++j) largest_correlation = std::max(largest_correlation, std::abs(fit.correlation[i][j]));
  fit.identifiable = finite_errors && fit.condition_number < identifiable_condition_limit &&
                     largest_correlation < identifiable_correlation_limit;
  const double k = static_cast<double>(p);
  fit.aic = fit.chi_square + 2.0 * k;
  fit.bic = fit.chi_square + k * std::log(static_cast<double>(n));

  // The model at the estimate, channel by channel.
  const std::vector<double> m = problem.model_values(z.data());
  fit.contact_time_s = model.contact_time_s();
  fit.model_summary = model.summary();
  std::vector<double> sum_sq(channels.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Observation& o = problem.observations()[i];
    ChannelFit& ch = fit.channels[o.channel];
    ch.t_s.push_back(o.t_s);
    ch.measured.push_back(o.y);
    ch.model.push_back(m[i]);
    sum_sq[o.channel] += (o.y - m[i]) * (o.y - m[i]);
  }
  for (std::size_t c = 0; c < channels.size(); ++c)
    fit.channels[c].residual_rms = std::sqrt(sum_sq[c] / static_cast<double>(fit.channels[c].samples));
  fit.model_runs = model.runs();
  fit.fitted_options = model.options_at(estimate);
  fit.model_solver = model.solver();
  return fit;
}

LawComparison compare_laws(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                           const TraceFitSettings& settings) {
  LawComparison out;
  initial_values(base, paper, settings.parameters);  // a bad --fit is the user's, not a law's
  for (const LawInfo& law : registered_laws()) {
    RunOptions o = base;
    o.damping = std::string(law.name);
    try {
      out.fits.push_back(fit_trace(trace, o, paper, settings));
    } catch (const DataError&) {
      throw;  // the trace's fault, the same for every law
    } catch (const std::exception& e) {
      out.failures.emplace_back(o.damping, e.what());
    }
  }
  std::stable_sort(out.fits.begin(), out.fits.end(), [](const TraceFit& a, const TraceFit& b) { return a.aic < b.aic; });
  return out;
}

}  // namespace hertzdash

// Fitting a measured trace (simulation/fit/trace_fit.hpp): fit_trace drives GSL's multifit_nlinear
// over the least-squares problem (trace_fit_problem.hpp) of the model (trace_fit_model.hpp) and
// the prepared trace (trace_preparation.hpp), from the starting values and an onset guess, and
// turns its solution into estimates, standard errors, correlations and criteria; compare_laws
// fits every registered law. The --fit list is parsed in fit_parameters.cpp.
#include "hertzdash/simulation/fit/trace_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/trace_fit_model.hpp"
#include "hertzdash/simulation/fit/least_squares.hpp"
#include "hertzdash/simulation/fit/profile_interval.hpp"
#include "hertzdash/simulation/fit/trace_fit_problem.hpp"
#include "hertzdash/simulation/fit/trace_preparation.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"

#include <fmt/format.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

namespace hertzdash {

using namespace trace_fit_detail;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

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

// The profile-likelihood interval of each fitted parameter but the onset (trace_fit.hpp,
// "Profile intervals"): each point a fit of the others and the onset, parameter j held there.
void add_profile_intervals(TraceFit& fit, const MeasuredTrace& trace, const PaperParameters& paper,
                           const TraceFitSettings& settings, const std::vector<Transform>& transforms,
                           const std::vector<double>& z) {
  for (std::size_t j = 0; j < transforms.size(); ++j) {
    const Transform& t = transforms[j];
    TraceFitSettings others = settings;
    others.parameters.erase(others.parameters.begin() + static_cast<std::ptrdiff_t>(j));
    others.profile_intervals = false;
    auto rise = [&](double zj) -> std::optional<double> {
      RunOptions at = fit.fitted_options;
      set_number(at, *find_run_option(settings.parameters[j].option), t.p(zj));
      try {
        const TraceFit f = fit_trace(trace, at, paper, others);
        if (!std::isfinite(f.chi_square)) return std::nullopt;
        return f.chi_square - fit.chi_square;
      } catch (const std::exception&) {
        return std::nullopt;
      }
    };
    FittedParameter& fp = fit.parameters[j];
    const double se_z = fp.standard_error / std::abs(t.dp_dz(z[j]));
    fp.profile = profile_interval(rise, fit.reduced_chi_square, z[j], se_z, [&t](double zj) { return t.p(zj); });
  }
}

}  // namespace

const FittedParameter& TraceFit::parameter(const std::string& name) const {
  for (const FittedParameter& p : parameters)
    if (p.name == name) return p;
  throw std::out_of_range("fit: no fitted parameter " + name);
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

  // The work bound (trace_fit.hpp, "Work"): refused before iterating if the first iterations
  // alone would exceed it, each model run costing what the one at the starting values did.
  const double run_cost = static_cast<double>(model.summary().work.steps) + static_cast<double>(n);
  if (const double predicted = min_predicted_iterations * static_cast<double>(2 * p + 2) * run_cost;
      predicted > settings.max_work)
    throw DataError(fmt::format("{}: the fit would exceed its work limit: a model run costs {:.3g} ({} RK4 steps and {} "
                                "observations), {:g} iterations of {} runs {:.3g}, above {:.3g}; average the trace "
                                "(--resample) or fit fewer channels (--channels)",
                                trace.path.string(), run_cost, model.summary().work.steps, n,
                                min_predicted_iterations, 2 * p + 2, predicted, settings.max_work));

  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  const std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p), &gsl_multifit_nlinear_free);
  if (!w) throw std::bad_alloc();
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = fit_detail::residuals_thunk<FitProblem>;
  fdf.df = fit_detail::jacobian_thunk<FitProblem>;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &problem;
  gsl_vector_view start = gsl_vector_view_array(z0.data(), p);
  int status = gsl_multifit_nlinear_init(&start.vector, &fdf, w.get());
  if (problem.error) std::rethrow_exception(problem.error);
  if (status != GSL_SUCCESS) throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_init failed: ") + gsl_strerror(status));
  // gsl_multifit_nlinear_driver's loop, with the work bound checked after each iteration (one
  // iteration is at most 16 trial runs and a Jacobian of 2p runs).
  int info = 0;
  bool work_limit = false;
  for (int iteration = 0;; ++iteration) {
    status = gsl_multifit_nlinear_iterate(w.get());
    if (problem.error) std::rethrow_exception(problem.error);
    if (status == GSL_ENOPROG && iteration == 0) break;  // no step from the start lowers the cost
    status = gsl_multifit_nlinear_test(1e-10, 1e-10, 0.0, &info, w.get());
    if (status != GSL_CONTINUE) break;
    if (iteration + 1 >= settings.max_iterations) {
      status = GSL_EMAXITER;
      break;
    }
    if (problem.work() > settings.max_work) {
      work_limit = true;
      status = GSL_EMAXITER;
      break;
    }
  }
  if (status == GSL_ETOLF || status == GSL_ETOLX || status == GSL_ETOLG) info = status, status = GSL_SUCCESS;
  if (status != GSL_SUCCESS && status != GSL_EMAXITER && status != GSL_ENOPROG)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_iterate failed: ") + gsl_strerror(status));
  fit.stop_reason = work_limit ? fmt::format("work limit reached ({:.3g} RK4 steps and interpolations)", settings.max_work)
                               : fit_detail::stop_reason(status, info);
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
  // A fit that determined nothing has failed (trace_fit.hpp, "Failure").
  std::vector<std::string> why;
  if (work_limit)
    why.push_back(fmt::format("it reached its work limit ({:.3g} RK4 steps and interpolations) after {} model runs",
                              settings.max_work, model.runs()));
  else if (status == GSL_EMAXITER && info != GSL_ENOPROG)
    why.push_back(fmt::format("it reached its iteration limit ({})", settings.max_iterations));
  for (const FittedParameter& fp : fit.parameters)
    if (fp.at_bound) why.push_back(fmt::format("{} ended at its bound ({:.6g})", fp.name, fp.estimate));
  if (fit.parameters.size() > 1 && std::none_of(fit.parameters.begin(), fit.parameters.end() - 1,
                   [](const FittedParameter& fp) { return std::isfinite(fp.standard_error); }))
    why.push_back("no fitted parameter has a finite standard error");
  if (!std::isfinite(fit.chi_square)) why.push_back("the chi-square is not finite");
  fit.failed = !why.empty();
  for (const std::string& reason : why) fit.failure += (fit.failure.empty() ? "" : "; ") + reason;
  fit.identifiable = !fit.failed && finite_errors && fit.condition_number < identifiable_condition_limit &&
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
  fit.work = problem.work();
  fit.fitted_options = model.options_at(estimate);
  fit.model_solver = model.solver();
  if (settings.profile_intervals && !fit.failed) add_profile_intervals(fit, trace_in, paper, settings, transforms, z);
  return fit;
}

LawComparison compare_laws(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                           const TraceFitSettings& settings) {
  LawComparison out;
  initial_values(base, paper, settings.parameters);  // a bad --fit is the user's, not a law's
  for (const LawInfo& law : registered_laws()) {
    RunOptions o = base;
    o.damping = std::string(law.name);
    // Each law is fitted with what it reads: an option given, or a parameter fitted, that this
    // law does not read is left out of its fit, and said so (TraceFit::left_out).
    TraceFitSettings own = settings;
    std::vector<std::string> left_out;
    auto reads = [&](const RunOption& option) {
      try {
        require_read(o, option, "");
        return true;
      } catch (const InvalidParameter&) {
        return false;
      }
    };
    for (const RunOption& option : run_options())
      if (is_given(o, option) && !reads(option)) {
        clear_option(o, option);
        left_out.push_back(option.name);
      }
    std::erase_if(own.parameters, [&](const FitParameter& p) {
      const bool unread = !reads(*find_run_option(p.option));
      if (unread && std::find(left_out.begin(), left_out.end(), p.option) == left_out.end()) left_out.push_back(p.option);
      return unread;
    });
    try {
      out.fits.push_back(fit_trace(trace, o, paper, own));
      out.fits.back().left_out = left_out;
    } catch (const DataError&) {
      throw;  // the trace's fault, the same for every law
    } catch (const std::exception& e) {
      out.failures.emplace_back(o.damping, e.what());
    }
  }
  // Failed fits last: the best is a fit that determined its parameters, if any did.
  std::stable_sort(out.fits.begin(), out.fits.end(), [](const TraceFit& a, const TraceFit& b) {
    return a.failed != b.failed ? b.failed : a.aic < b.aic;
  });
  return out;
}

}  // namespace hertzdash

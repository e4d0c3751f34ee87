// Fitting a law to a bounce recording (simulation/fit/bounce_fit.hpp): the least-squares problem
// on the model of bounce_fit_model.hpp, two nuisance parameters per drop, its structured
// Jacobian, GSL's multifit_nlinear; the estimates, standard errors and criteria;
// leave-one-drop-out cross-validation; every law compared.
#include "hertzdash/simulation/fit/bounce_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/bounce_fit_model.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/least_squares.hpp"
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>

namespace hertzdash {

using namespace bounce_fit_detail;
using trace_fit_detail::Transform;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Least RSS / n: the model's accuracy in time (bounce_fit.hpp, "Residuals and uncertainty").
constexpr double least_variance = 1e-10 * 1e-10;
constexpr double outside = 1e30;  // a residual where the model cannot be evaluated

// The least-squares problem: z = [the law's free variables (transformed)], then per drop
// [ln v0, t0]. With no free law variable the law's values are `fixed_law` (a left-out drop's
// prediction).
struct Problem {
  BounceModel* model;
  std::vector<Transform> transforms;
  std::vector<double> fixed_law;
  const std::vector<CheckedDrop>* drops;
  std::exception_ptr error;

  std::size_t pl() const { return transforms.size(); }
  std::size_t n() const {
    std::size_t k = 0;
    for (const CheckedDrop& d : *drops) k += d.impact_time_s.size();
    return k;
  }
  std::size_t p() const { return pl() + 2 * drops->size(); }
  std::vector<double> law(const double* z) const {
    if (transforms.empty()) return fixed_law;
    std::vector<double> v;
    for (std::size_t j = 0; j < pl(); ++j) v.push_back(transforms[j].p(z[j]));
    return v;
  }
  // Drop d's residuals from row `row` on.
  void drop_residuals(const std::vector<double>& law, std::size_t d, double ln_v0, double t0, double* r) {
    const CheckedDrop& drop = (*drops)[d];
    const auto* m = model->impacts(law, std::exp(ln_v0), drop.impact_number.back() + 1);
    for (std::size_t k = 0; k < drop.impact_time_s.size(); ++k)
      r[k] = m ? drop.impact_time_s[k] - (t0 + (*m)[static_cast<std::size_t>(drop.impact_number[k])].onset_s) : outside;
  }
  void residuals(const double* z, double* r) {
    const std::vector<double> theta = law(z);
    std::size_t row = 0;
    for (std::size_t d = 0; d < drops->size(); ++d) {
      drop_residuals(theta, d, z[pl() + 2 * d], z[pl() + 2 * d + 1], r + row);
      row += (*drops)[d].impact_time_s.size();
    }
  }
  // Central differences (step 1e-6, least_squares.hpp) for the law and each drop's ln v0, in that
  // drop's rows only; -1 for t0 (exact).
  void jacobian(const double* z, gsl_matrix* J) {
    gsl_matrix_set_zero(J);
    const std::size_t rows = n();
    const double h = 1e-6;
    std::vector<double> zz(z, z + p()), plus(rows), minus(rows);
    for (std::size_t j = 0; j < pl(); ++j) {
      zz[j] = z[j] + h;
      residuals(zz.data(), plus.data());
      zz[j] = z[j] - h;
      residuals(zz.data(), minus.data());
      zz[j] = z[j];
      for (std::size_t i = 0; i < rows; ++i) gsl_matrix_set(J, i, j, (plus[i] - minus[i]) / (2.0 * h));
    }
    const std::vector<double> theta = law(z);
    std::size_t row = 0;
    for (std::size_t d = 0; d < drops->size(); ++d) {
      const std::size_t m = (*drops)[d].impact_time_s.size(), jv = pl() + 2 * d;
      drop_residuals(theta, d, z[jv] + h, z[jv + 1], plus.data());
      drop_residuals(theta, d, z[jv] - h, z[jv + 1], minus.data());
      for (std::size_t k = 0; k < m; ++k) {
        gsl_matrix_set(J, row + k, jv, (plus[k] - minus[k]) / (2.0 * h));
        gsl_matrix_set(J, row + k, jv + 1, -1.0);
      }
      row += m;
    }
  }
};

int jacobian_thunk(const gsl_vector* z, void* params, gsl_matrix* J) {
  auto* problem = static_cast<Problem*>(params);
  try {
    problem->jacobian(z->data, J);
    return GSL_SUCCESS;
  } catch (...) {
    problem->error = std::current_exception();
    return GSL_EBADFUNC;
  }
}

// GSL's solution: the variables, the Jacobian there, the residuals, why it stopped.
struct Solution {
  std::vector<double> z, f;
  std::vector<double> covariance;  // (J^T J)^-1, p x p, row-major (unscaled)
  std::vector<double> jacobian_norms;  // of each column
  int status = GSL_SUCCESS, info = 0, iterations = 0;
  double rss = 0;
};

Solution solve(Problem& problem, const std::vector<double>& z0, int max_iterations) {
  const std::size_t n = problem.n(), p = problem.p();
  std::vector<double> zs = z0;
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  const std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p), &gsl_multifit_nlinear_free);
  if (!w) throw std::bad_alloc();
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = fit_detail::residuals_thunk<Problem>;
  fdf.df = jacobian_thunk;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &problem;
  gsl_vector_view z_start = gsl_vector_view_array(zs.data(), p);
  int status = gsl_multifit_nlinear_init(&z_start.vector, &fdf, w.get());
  if (problem.error) std::rethrow_exception(problem.error);
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_init failed: ") + gsl_strerror(status));
  Solution s;
  for (int iteration = 0;; ++iteration) {
    status = gsl_multifit_nlinear_iterate(w.get());
    if (problem.error) std::rethrow_exception(problem.error);
    if (status == GSL_ENOPROG && iteration == 0) break;
    status = gsl_multifit_nlinear_test(1e-10, 1e-10, 0.0, &s.info, w.get());
    if (status != GSL_CONTINUE) break;
    if (iteration + 1 >= max_iterations) {
      status = GSL_EMAXITER;
      break;
    }
  }
  if (status == GSL_ETOLF || status == GSL_ETOLX || status == GSL_ETOLG) s.info = status, status = GSL_SUCCESS;
  if (status != GSL_SUCCESS && status != GSL_EMAXITER && status != GSL_ENOPROG)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_iterate failed: ") + gsl_strerror(status));
  s.status = status;
  s.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w.get()));
  const gsl_vector* zv = gsl_multifit_nlinear_position(w.get());
  s.z.assign(zv->data, zv->data + p);
  const gsl_vector* f = gsl_multifit_nlinear_residual(w.get());
  s.f.assign(f->data, f->data + n);
  gsl_blas_ddot(f, f, &s.rss);
  const gsl_matrix* J = gsl_multifit_nlinear_jac(w.get());
  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> covar(gsl_matrix_alloc(p, p), &gsl_matrix_free);
  if (const int c = gsl_multifit_nlinear_covar(J, 0.0, covar.get()); c != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_covar failed: ") + gsl_strerror(c));
  for (std::size_t i = 0; i < p; ++i) {
    gsl_vector_const_view column = gsl_matrix_const_column(J, i);
    s.jacobian_norms.push_back(gsl_blas_dnrm2(&column.vector));
    for (std::size_t j = 0; j < p; ++j) s.covariance.push_back(gsl_matrix_get(covar.get(), i, j));
  }
  return s;
}

std::vector<FitParameter> parameters_of(const RunOptions& base, const BounceFitSettings& settings) {
  return settings.parameters.empty() ? default_restitution_fit_parameters(base) : settings.parameters;
}

std::vector<std::string> names_of(const std::vector<FitParameter>& parameters) {
  std::vector<std::string> names;
  for (const FitParameter& p : parameters) names.push_back(p.option);
  return names;
}

}  // namespace

const FittedParameter& BounceFit::parameter(const std::string& name) const {
  for (const FittedParameter& p : parameters)
    if (p.name == name) return p;
  throw std::out_of_range("bounce fit: no fitted parameter " + name);
}

BounceFit fit_bounce_recording(const CheckedRecording& data, const std::string& path, const RunOptions& given,
                               const PaperParameters& paper, const BounceFitSettings& settings,
                               const std::optional<std::vector<double>>& start) {
  use_gsl_return_codes();
  check_bounce_fit_options(given);
  RunOptions base = given;
  base.follows_flights = true;  // the model's flights read the air drag, from the start values on
  {
    RunOptions probe = base;
    probe.impact_velocity_mps = 1.0;
    resolve_setup(probe, paper);  // the options' own refusals first
  }
  const std::vector<FitParameter> parameters = parameters_of(base, settings);
  if (parameters.empty())
    throw InvalidParameter("damping", base.damping,
                           "a law with a parameter to fit for `bounce-times` (this one reads neither `restitution` nor a "
                           "time constant: its e is fixed), or parameters given with `fit`");
  const std::vector<std::string> names = names_of(parameters);
  std::vector<Transform> transforms;
  for (const FitParameter& p : parameters) transforms.push_back({p.lower, p.upper});
  const std::vector<double> initial = start ? *start : starting_values(data, base, paper, parameters);
  const std::size_t pl = parameters.size();

  BounceModel model(base, paper, names);
  Problem problem{&model, transforms, {}, &data.drops, nullptr};
  const std::size_t n = problem.n(), p = problem.p();
  if (n <= p)
    throw DataError(fmt::format("{}: {} usable impact times cannot determine {} parameters (the law's {} and two per "
                                "drop)",
                                path, n, p, pl));
  (void)restitution_fit_detail::restitution_contact(model.options_at({initial.begin(), initial.begin() + pl}), paper,
                                                    initial[pl]);  // a set-up the options refuse says why
  std::vector<double> z0;
  for (std::size_t j = 0; j < pl; ++j) z0.push_back(transforms[j].z(initial[j]));
  for (std::size_t d = 0; d < data.drops.size(); ++d) z0.push_back(std::log(initial[pl + 2 * d])), z0.push_back(initial[pl + 2 * d + 1]);
  {
    std::vector<double> r0(n);
    problem.residuals(z0.data(), r0.data());
    if (std::any_of(r0.begin(), r0.end(), [](double r) { return r >= outside; }))
      throw InvalidParameter("fit", "the starting values", "values inside the model's domain (every drop's impacts reached)");
  }
  const Solution s = solve(problem, z0, settings.max_iterations);

  BounceFit fit;
  fit.law = base.damping;
  fit.times = n;
  fit.fitted = p;
  fit.stop_reason = fit_detail::stop_reason(s.status, s.info);
  fit.converged = s.status == GSL_SUCCESS;
  fit.iterations = s.iterations;
  fit.chi_square = s.rss;
  const double s2 = s.rss / static_cast<double>(n - p);
  fit.sigma = std::sqrt(s2);
  fit.reduced_chi_square = NAN;
  auto covariance = [&](std::size_t i, std::size_t j) {
    if (s.jacobian_norms[i] == 0 || s.jacobian_norms[j] == 0 || !(s.covariance[i * p + i] >= 0) ||
        !(s.covariance[j * p + j] >= 0))
      return i == j ? inf : NAN;
    return s2 * s.covariance[i * p + j];
  };
  const std::vector<double> estimate = problem.law(s.z.data());
  bool finite_errors = true;
  for (std::size_t j = 0; j < pl; ++j) {
    const Transform& t = transforms[j];
    FittedParameter fp{names[j], initial[j], estimate[j], std::abs(t.dp_dz(s.z[j])) * std::sqrt(covariance(j, j)), t.lo,
                       t.hi};
    fp.at_bound = t.two_sided() ? std::abs(s.z[j]) > std::log(1e3)
                                : (estimate[j] - t.lo) < 1e-3 * std::abs(initial[j] - t.lo);
    finite_errors = finite_errors && std::isfinite(fp.standard_error);
    fit.parameters.push_back(fp);
  }
  double largest_correlation = 0;
  for (std::size_t i = 0; i < pl; ++i) {
    fit.correlation.emplace_back();
    for (std::size_t j = 0; j < pl; ++j) {
      const double c = covariance(i, j) / std::sqrt(covariance(i, i) * covariance(j, j));
      fit.correlation.back().push_back(c);
      if (i != j) largest_correlation = std::max(largest_correlation, std::isfinite(c) ? std::abs(c) : 1.0);
    }
  }
  for (std::size_t d = 0; d < data.drops.size(); ++d) {
    const CheckedDrop& drop = data.drops[d];
    const std::size_t jv = pl + 2 * d;
    const double v0 = std::exp(s.z[jv]);
    fit.drops.push_back({drop.label, drop.impact_time_s.size(), drop.drop_height_m,
                         {"first_impact_speed_mps", initial[jv], v0, v0 * std::sqrt(covariance(jv, jv)), 0, inf},
                         {"clock_offset_s", initial[jv + 1], s.z[jv + 1], std::sqrt(covariance(jv + 1, jv + 1)), -inf, inf}});
  }
  std::vector<std::string> why;
  if (s.status == GSL_EMAXITER) why.push_back(fmt::format("it reached its iteration limit ({})", settings.max_iterations));
  for (const FittedParameter& fp : fit.parameters)
    if (fp.at_bound) why.push_back(fmt::format("{} ended at its bound ({:.6g})", fp.name, fp.estimate));
  if (std::none_of(fit.parameters.begin(), fit.parameters.end(),
                   [](const FittedParameter& fp) { return std::isfinite(fp.standard_error); }))
    why.push_back("no fitted parameter of the law has a finite standard error");
  if (!std::isfinite(fit.chi_square) || fit.chi_square >= outside) why.push_back("the model could not be evaluated at the estimate");
  fit.failed = !why.empty();
  for (const std::string& reason : why) fit.failure += (fit.failure.empty() ? "" : "; ") + reason;
  fit.identifiable = !fit.failed && finite_errors && largest_correlation < identifiable_correlation_limit;

  const double k = static_cast<double>(p), nn = static_cast<double>(n);
  const double log_variance = std::log(std::max(fit.chi_square / nn, least_variance));
  fit.aic = nn * log_variance + 2.0 * (k + 1.0);
  fit.bic = nn * log_variance + (k + 1.0) * std::log(nn);

  fit.e_min = inf, fit.e_max = -inf;
  std::size_t row = 0;
  for (std::size_t d = 0; d < data.drops.size(); ++d) {
    const CheckedDrop& drop = data.drops[d];
    const auto* m = model.impacts(estimate, std::exp(s.z[pl + 2 * d]), drop.impact_number.back() + 1);
    for (std::size_t i = 0; i < drop.impact_time_s.size(); ++i, ++row) {
      const ModelImpact* mi = m ? &(*m)[static_cast<std::size_t>(drop.impact_number[i])] : nullptr;
      const double model_time = mi ? s.z[pl + 2 * d + 1] + mi->onset_s : NAN;
      fit.points.push_back({drop.label, drop.index[i], drop.impact_number[i], drop.impact_time_s[i], model_time,
                            drop.impact_time_s[i] - model_time, mi ? mi->approach_mps : NAN});
      if (mi && mi->rebound_mps > 0) {
        const double e = mi->rebound_mps / mi->approach_mps;
        fit.e_min = std::min(fit.e_min, e), fit.e_max = std::max(fit.e_max, e);
      }
    }
  }
  if (!(fit.e_min <= fit.e_max)) fit.e_min = fit.e_max = NAN;
  fit.model_runs = model.runs();
  fit.integrator_used = model.integrator_used();
  fit.fitted_options = model.options_at(estimate);
  return fit;
}

BounceCrossValidation cross_validate_bounces(const CheckedRecording& data, const std::string& path,
                                             const RunOptions& base, const PaperParameters& paper,
                                             const BounceFitSettings& settings, const BounceFit& fit) {
  if (data.drops.size() < 2)
    throw DataError(fmt::format("{}: cross-validation leaves out each drop in turn and needs at least two usable drops "
                                "(the recording has {})",
                                path, data.drops.size()));
  BounceCrossValidation cv;
  cv.folds = data.drops.size();
  BounceFitSettings fold_settings = settings;
  fold_settings.parameters = parameters_of(base, settings);
  const std::vector<std::string> names = names_of(fold_settings.parameters);
  std::vector<double> law;
  for (const FittedParameter& p : fit.parameters) law.push_back(p.estimate);
  double sum_sq = 0, dof = 0;
  for (std::size_t left = 0; left < data.drops.size(); ++left) {
    CheckedRecording rest, held;
    std::vector<double> start = law;
    for (std::size_t d = 0; d < data.drops.size(); ++d) {
      if (d == left) {
        held.drops.push_back(data.drops[d]);
        continue;
      }
      rest.drops.push_back(data.drops[d]);
      start.push_back(fit.drops[d].first_impact_speed.estimate);
      start.push_back(fit.drops[d].clock_offset.estimate);
    }
    try {
      const BounceFit f = fit_bounce_recording(rest, path, base, paper, fold_settings, start);
      if (f.failed) throw std::runtime_error(f.failure);
      std::vector<double> fold_law;
      for (const FittedParameter& p : f.parameters) fold_law.push_back(p.estimate);
      // The left-out drop: the law fixed, its own v0 and t0 fitted.
      BounceModel model(base, paper, names);
      Problem problem{&model, {}, fold_law, &held.drops, nullptr};
      const std::vector<double> z0{std::log(fit.drops[left].first_impact_speed.estimate),
                                   fit.drops[left].clock_offset.estimate};
      const Solution s = solve(problem, z0, settings.max_iterations);
      if (!(s.rss < outside)) throw std::runtime_error("the model cannot reach the left-out drop's impacts");
      sum_sq += s.rss;
      dof += static_cast<double>(problem.n()) - 2.0;
    } catch (const std::exception& e) {
      cv.failure = fmt::format("the fit without drop '{}': {}", data.drops[left].label, e.what());
      return cv;
    }
  }
  cv.rms_prediction_error = std::sqrt(sum_sq / dof);
  cv.scatter = fit.sigma;
  cv.ratio = cv.scatter > 0 ? cv.rms_prediction_error / cv.scatter : inf;
  return cv;
}

BounceLawComparison compare_laws_on_bounces(const CheckedRecording& data, const std::string& path,
                                            const RunOptions& base, const PaperParameters& paper,
                                            const BounceFitSettings& settings) {
  BounceLawComparison out;
  check_bounce_fit_options(base);
  RunOptions flying = base;
  flying.follows_flights = true;  // the model's flights read the air drag: not "left out"
  for (const LawInfo& law : registered_laws()) {
    const LawTrial trial = law_trial(flying, law.name, settings.parameters);
    const RunOptions& o = trial.options;
    if (!trial.refusal.empty()) {
      out.failures.emplace_back(o.damping, trial.refusal);
      continue;
    }
    BounceFitSettings own = settings;
    own.parameters = trial.parameters;
    try {
      BounceFit f = fit_bounce_recording(data, path, o, paper, own);
      f.left_out = trial.left_out;
      if (settings.cross_validate) f.cross_validation = cross_validate_bounces(data, path, o, paper, own, f);
      out.fits.push_back(std::move(f));
    } catch (const DataError&) {
      throw;  // the recording's fault, the same for every law
    } catch (const std::exception& e) {
      out.failures.emplace_back(o.damping, e.what());
    }
  }
  std::stable_sort(out.fits.begin(), out.fits.end(), [](const BounceFit& a, const BounceFit& b) {
    return a.failed != b.failed ? b.failed : a.aic < b.aic;
  });
  return out;
}

}  // namespace hertzdash

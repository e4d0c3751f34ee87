// Fitting a law to a restitution table (simulation/fit/restitution_fit.hpp): the least-squares
// problem of e against the impact speed, driven by GSL's multifit_nlinear; the estimates,
// standard errors, correlations and criteria; leave-one-speed-out cross-validation; every law
// compared.
#include "hertzdash/simulation/fit/restitution_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/least_squares.hpp"
#include "hertzdash/simulation/fit/profile_interval.hpp"
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"

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
#include <numeric>
#include <set>

namespace hertzdash {

using namespace restitution_fit_detail;
using trace_fit_detail::Transform;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Least RSS / n of the likelihood without e_sd: the model's accuracy (restitution_fit.hpp, "Criteria").
constexpr double least_variance = 1e-9 * 1e-9;

bool reads(const RunOptions& o, const std::string& option) {
  try {
    require_read(o, *find_run_option(option), "");
    return true;
  } catch (const InvalidParameter&) {
    return false;
  }
}

bool has_time_constant(const std::string& law) { return registered_law(law).material_time_constant; }

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The A of a material-time-constant law whose e at `speed` is `e` (the simulator's calibration).
double calibrated_time_constant(const RunOptions& base, const PaperParameters& paper, double speed, double e) {
  RunOptions o = base;
  o.restitution = e;
  o.viscous_time_constant_s.reset();
  const DropTestSetup s = restitution_contact(o, paper, speed);
  const LawRuns& runs = law_runs(base.damping);
  return runs.calibrated_time_constant ? *runs.calibrated_time_constant(s).damping.viscous_time_constant_s : 0.0;
}

// The starting values (restitution_fit.hpp, "Parameters").
std::vector<double> starting_values(const RestitutionTable& table, const RunOptions& base, const PaperParameters& paper,
                                    const std::vector<FitParameter>& parameters) {
  const double e_mean = std::clamp(mean(table.e), 0.01, 0.99);
  std::vector<double> v;
  for (const FitParameter& p : parameters) {
    require_read(base, *find_run_option(p.option), "(fitted)");
    double x;
    if (p.option == "restitution" && !base.restitution) x = e_mean;
    else if (p.option == "viscous-time-constant" && !base.viscous_time_constant_s)
      x = calibrated_time_constant(base, paper, median(table.impact_speed_mps), e_mean);
    else x = trace_fit_detail::initial_values(base, paper, {p}).front();
    if (!(x > p.lower && x < p.upper))
      throw InvalidParameter("fit", fmt::format("{}:{}:{}", p.option, format_value(p.lower), format_value(p.upper)),
                             fmt::format("bounds around the starting value {} {} (set it inside them)",
                                         key_reference(p.option), format_value(x)));
    v.push_back(x);
  }
  return v;
}

// The weighted least-squares problem in the unbounded variables.
struct Problem {
  RestitutionModel* model;
  std::vector<Transform> transforms;
  std::vector<double> speeds, e, inv_sd;
  std::exception_ptr error;
  static constexpr double outside = 1e30;

  std::size_t n() const { return e.size(); }
  std::size_t p() const { return transforms.size(); }
  std::vector<double> physical(const double* z) const {
    std::vector<double> v;
    for (std::size_t j = 0; j < p(); ++j) v.push_back(transforms[j].p(z[j]));
    return v;
  }
  void residuals(const double* z, double* r) {
    const auto m = model->e_at(physical(z), speeds);
    for (std::size_t i = 0; i < n(); ++i) r[i] = m ? (e[i] - (*m)[i]) * inv_sd[i] : outside;
  }
};

// The profile-likelihood interval of each fitted parameter (restitution_fit.hpp, "Profile
// intervals"), the fit's estimate at z in the unbounded variables.
void add_profile_intervals(RestitutionFit& fit, const RestitutionTable& table, const PaperParameters& paper, const RestitutionFitSettings& settings,
                           const std::vector<FitParameter>& parameters, Problem& problem, const std::vector<double>& z) {
  const std::size_t p = parameters.size();
  const double threshold = fit.chi_square / static_cast<double>(fit.rows - p);
  const std::vector<double> estimate = problem.physical(z.data());
  for (std::size_t j = 0; j < p; ++j) {
    const Transform& t = problem.transforms[j];
    FittedParameter& fp = fit.parameters[j];
    std::function<std::optional<double>(double)> rise;
    if (p == 1) {  // the profile is chi^2 itself
      rise = [&](double zj) -> std::optional<double> {
        std::vector<double> r(problem.n());
        problem.residuals(&zj, r.data());
        double chi2 = 0;
        for (double v : r) chi2 += v * v;
        if (!(chi2 < Problem::outside)) return std::nullopt;
        return chi2 - fit.chi_square;
      };
    } else {  // the others re-fitted from their estimates, parameter j held at p(z)
      RestitutionFitSettings others = settings;
      others.parameters.clear();
      std::vector<double> start;
      for (std::size_t i = 0; i < p; ++i)
        if (i != j) others.parameters.push_back(parameters[i]), start.push_back(estimate[i]);
      others.cross_validate = others.profile_intervals = false;
      rise = [&, others, start](double zj) -> std::optional<double> {
        std::vector<double> at = estimate;
        at[j] = t.p(zj);
        try {
          const RestitutionFit f = fit_restitution_table(table, problem.model->options_at(at), paper, others, start);
          if (!(f.chi_square < Problem::outside)) return std::nullopt;
          return f.chi_square - fit.chi_square;
        } catch (const std::exception&) {
          return std::nullopt;
        }
      };
    }
    const double se_z = fp.standard_error / std::abs(t.dp_dz(z[j]));
    fp.profile = profile_interval(rise, threshold, z[j], se_z, [&t](double zj) { return t.p(zj); });
  }
}

}  // namespace

const FittedParameter& RestitutionFit::parameter(const std::string& name) const {
  for (const FittedParameter& p : parameters)
    if (p.name == name) return p;
  throw std::out_of_range("restitution fit: no fitted parameter " + name);
}

std::vector<FitParameter> default_restitution_fit_parameters(const RunOptions& base) {
  if (has_time_constant(base.damping)) return parse_fit_parameters("viscous-time-constant");
  if (reads(base, "restitution")) return parse_fit_parameters("restitution");
  return {};
}

LawTrial law_trial(const RunOptions& base, std::string_view law, const std::vector<FitParameter>& parameters) {
  LawTrial t{base, parameters, {}, {}};
  RunOptions& o = t.options;
  o.damping = std::string(law);
  for (const RunOption& option : run_options())
    if (is_given(o, option) && !reads(o, option.name)) {
      clear_option(o, option);
      t.left_out.push_back(option.name);
    }
  std::erase_if(t.parameters, [&](const FitParameter& p) {
    const bool unread = !reads(o, p.option);
    if (unread && std::find(t.left_out.begin(), t.left_out.end(), p.option) == t.left_out.end())
      t.left_out.push_back(p.option);
    return unread;
  });
  if (!parameters.empty() && t.parameters.empty()) t.refusal = "it reads none of the parameters given to fit";
  else if (parameters.empty() && default_restitution_fit_parameters(o).empty())
    t.refusal = "nothing to fit: it reads neither the input e nor a time constant (its e does not depend on a "
                "parameter of its own)";
  return t;
}

RestitutionFit fit_restitution_table(const RestitutionTable& table, const RunOptions& base, const PaperParameters& paper,
                                     const RestitutionFitSettings& settings,
                                     const std::optional<std::vector<double>>& start) {
  use_gsl_return_codes();
  check_restitution_fit_options(base);
  resolve_setup(base, paper);  // the options' own refusals first
  const std::vector<FitParameter> parameters =
      settings.parameters.empty() ? default_restitution_fit_parameters(base) : settings.parameters;
  if (parameters.empty())
    throw InvalidParameter("damping", base.damping,
                           "a law with a parameter to fit for `restitution-table` (this one reads neither `restitution` "
                           "nor a time constant: its e is fixed), or parameters given with `fit`");
  std::vector<std::string> names;
  std::vector<Transform> transforms;
  for (const FitParameter& p : parameters) names.push_back(p.option), transforms.push_back({p.lower, p.upper});
  const std::vector<double> initial = start ? *start : starting_values(table, base, paper, parameters);

  RestitutionModel model(base, paper, names);
  Problem problem{&model, transforms, table.impact_speed_mps, table.e, {}, nullptr};
  for (std::size_t i = 0; i < table.rows(); ++i) problem.inv_sd.push_back(table.has_sd() ? 1.0 / table.e_sd[i] : 1.0);
  const std::size_t n = problem.n(), p = problem.p();
  if (n <= p)
    throw DataError(fmt::format("{}: {} rows cannot determine {} parameters", table.path.string(), n, p));
  // A set-up the options refuse says why, naming the option (`restitution` beside a time constant).
  (void)restitution_contact(model.options_at(initial), paper, table.impact_speed_mps.front());
  if (!model.e_at(initial, table.impact_speed_mps))
    throw InvalidParameter("fit", "the starting values", "values inside the model's domain");

  std::vector<double> z0;
  for (std::size_t j = 0; j < p; ++j) z0.push_back(transforms[j].z(initial[j]));
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  const std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p), &gsl_multifit_nlinear_free);
  if (!w) throw std::bad_alloc();
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = fit_detail::residuals_thunk<Problem>;
  fdf.df = fit_detail::jacobian_thunk<Problem>;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &problem;
  gsl_vector_view z_start = gsl_vector_view_array(z0.data(), p);
  int status = gsl_multifit_nlinear_init(&z_start.vector, &fdf, w.get());
  if (problem.error) std::rethrow_exception(problem.error);
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_init failed: ") + gsl_strerror(status));
  int info = 0;
  for (int iteration = 0;; ++iteration) {
    status = gsl_multifit_nlinear_iterate(w.get());
    if (problem.error) std::rethrow_exception(problem.error);
    if (status == GSL_ENOPROG && iteration == 0) break;
    status = gsl_multifit_nlinear_test(1e-10, 1e-10, 0.0, &info, w.get());
    if (status != GSL_CONTINUE) break;
    if (iteration + 1 >= settings.max_iterations) {
      status = GSL_EMAXITER;
      break;
    }
  }
  if (status == GSL_ETOLF || status == GSL_ETOLX || status == GSL_ETOLG) info = status, status = GSL_SUCCESS;
  if (status != GSL_SUCCESS && status != GSL_EMAXITER && status != GSL_ENOPROG)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_iterate failed: ") + gsl_strerror(status));

  RestitutionFit fit;
  fit.law = base.damping;
  fit.rows = n;
  fit.stop_reason = fit_detail::stop_reason(status, info);
  fit.converged = status == GSL_SUCCESS;
  fit.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w.get()));
  const gsl_vector* zv = gsl_multifit_nlinear_position(w.get());
  const std::vector<double> z(zv->data, zv->data + p);
  const gsl_matrix* J = gsl_multifit_nlinear_jac(w.get());
  const gsl_vector* f = gsl_multifit_nlinear_residual(w.get());
  gsl_blas_ddot(f, f, &fit.chi_square);
  const double dof = static_cast<double>(n - p), s2 = fit.chi_square / dof;
  fit.sigma_estimated = !table.has_sd();
  fit.sigma = fit.sigma_estimated ? std::sqrt(s2) : 0.0;
  fit.reduced_chi_square = fit.sigma_estimated ? NAN : s2;

  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> covar(gsl_matrix_alloc(p, p), &gsl_matrix_free);
  if (const int s = gsl_multifit_nlinear_covar(J, 0.0, covar.get()); s != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_covar failed: ") + gsl_strerror(s));
  gsl_matrix_scale(covar.get(), s2);
  for (std::size_t j = 0; j < p; ++j) {  // a parameter the table does not see: an infinite error (trace_fit.cpp)
    gsl_vector_const_view column = gsl_matrix_const_column(J, j);
    if (gsl_blas_dnrm2(&column.vector) == 0 || !(gsl_matrix_get(covar.get(), j, j) >= 0))
      for (std::size_t i = 0; i < p; ++i) {
        gsl_matrix_set(covar.get(), i, j, i == j ? inf : NAN);
        gsl_matrix_set(covar.get(), j, i, i == j ? inf : NAN);
      }
  }
  const std::vector<double> estimate = problem.physical(z.data());
  bool finite_errors = true;
  for (std::size_t j = 0; j < p; ++j) {
    const Transform& t = transforms[j];
    FittedParameter fp{names[j], initial[j], estimate[j],
                       std::abs(t.dp_dz(z[j])) * std::sqrt(gsl_matrix_get(covar.get(), j, j)), t.lo, t.hi};
    fp.at_bound = t.two_sided() ? std::abs(z[j]) > std::log(1e3)
                                : (estimate[j] - t.lo) < 1e-3 * std::abs(initial[j] - t.lo);
    finite_errors = finite_errors && std::isfinite(fp.standard_error);
    fit.parameters.push_back(fp);
  }
  double largest_correlation = 0;
  for (std::size_t i = 0; i < p; ++i) {
    fit.correlation.emplace_back();
    for (std::size_t j = 0; j < p; ++j) {
      const double c = gsl_matrix_get(covar.get(), i, j) /
                       std::sqrt(gsl_matrix_get(covar.get(), i, i) * gsl_matrix_get(covar.get(), j, j));
      fit.correlation.back().push_back(c);
      if (i != j) largest_correlation = std::max(largest_correlation, std::isfinite(c) ? std::abs(c) : 1.0);
    }
  }
  std::vector<std::string> why;
  if (status == GSL_EMAXITER) why.push_back(fmt::format("it reached its iteration limit ({})", settings.max_iterations));
  for (const FittedParameter& fp : fit.parameters)
    if (fp.at_bound) why.push_back(fmt::format("{} ended at its bound ({:.6g})", fp.name, fp.estimate));
  if (std::none_of(fit.parameters.begin(), fit.parameters.end(),
                   [](const FittedParameter& fp) { return std::isfinite(fp.standard_error); }))
    why.push_back("no fitted parameter has a finite standard error");
  if (!std::isfinite(fit.chi_square) || fit.chi_square >= Problem::outside)
    why.push_back("the model could not be evaluated at the estimate");
  fit.failed = !why.empty();
  for (const std::string& reason : why) fit.failure += (fit.failure.empty() ? "" : "; ") + reason;
  fit.identifiable = !fit.failed && finite_errors && largest_correlation < identifiable_correlation_limit;

  const double k = static_cast<double>(p), nn = static_cast<double>(n);
  if (fit.sigma_estimated) {
    const double log_variance = std::log(std::max(fit.chi_square / nn, least_variance));
    fit.aic = nn * log_variance + 2.0 * (k + 1.0);
    fit.bic = nn * log_variance + (k + 1.0) * std::log(nn);
  } else {
    fit.aic = fit.chi_square + 2.0 * k;
    fit.bic = fit.chi_square + k * std::log(nn);
  }

  const auto m = model.e_at(estimate, table.impact_speed_mps);
  for (std::size_t i = 0; i < n; ++i) {
    const double mi = m ? (*m)[i] : NAN;
    fit.points.push_back({table.impact_speed_mps[i], table.e[i], mi, table.e[i] - mi});
  }
  fit.e_min = inf, fit.e_max = -inf;
  for (const RestitutionPoint& pt : fit.points) fit.e_min = std::min(fit.e_min, pt.model), fit.e_max = std::max(fit.e_max, pt.model);
  fit.model_runs = model.runs();
  fit.integrator_used = model.integrator_used();
  fit.fitted_options = model.options_at(estimate);
  if (settings.profile_intervals && !fit.failed) add_profile_intervals(fit, table, paper, settings, parameters, problem, z);
  return fit;
}

RestitutionCrossValidation cross_validate_restitution(const RestitutionTable& table, const RunOptions& base,
                                                      const PaperParameters& paper,
                                                      const RestitutionFitSettings& settings, const RestitutionFit& fit) {
  const std::set<double> speeds(table.impact_speed_mps.begin(), table.impact_speed_mps.end());
  if (speeds.size() < 2)
    throw DataError(fmt::format("{}: cross-validation leaves out each distinct impact speed in turn and needs at "
                                "least two (the table has {})",
                                table.path.string(), speeds.size()));
  RestitutionCrossValidation cv;
  cv.folds = speeds.size();
  std::vector<FitParameter> parameters = settings.parameters;
  if (parameters.empty()) parameters = default_restitution_fit_parameters(base);
  std::vector<double> start;
  for (const FittedParameter& p : fit.parameters) start.push_back(p.estimate);
  RestitutionFitSettings fold_settings = settings;
  fold_settings.parameters = parameters;
  fold_settings.profile_intervals = false;  // the folds' predictions need their estimates only
  double sum_sq = 0;
  for (double left_out : speeds) {
    RestitutionTable rest = table, held;
    rest.impact_speed_mps.clear(), rest.e.clear(), rest.e_sd.clear(), rest.contact_time_s.clear();
    held = rest;
    for (std::size_t i = 0; i < table.rows(); ++i) {
      RestitutionTable& to = table.impact_speed_mps[i] == left_out ? held : rest;
      to.impact_speed_mps.push_back(table.impact_speed_mps[i]);
      to.e.push_back(table.e[i]);
      if (table.has_sd()) to.e_sd.push_back(table.e_sd[i]);
    }
    try {
      const RestitutionFit f = fit_restitution_table(rest, base, paper, fold_settings, start);
      if (f.failed) throw std::runtime_error(f.failure);
      RestitutionModel model(base, paper, [&] {
        std::vector<std::string> names;
        for (const FitParameter& p : parameters) names.push_back(p.option);
        return names;
      }());
      std::vector<double> estimate;
      for (const FittedParameter& p : f.parameters) estimate.push_back(p.estimate);
      const auto predicted = model.e_at(estimate, held.impact_speed_mps);
      if (!predicted) throw std::runtime_error("the model cannot be evaluated at the left-out speed");
      for (std::size_t i = 0; i < held.rows(); ++i) sum_sq += (held.e[i] - (*predicted)[i]) * (held.e[i] - (*predicted)[i]);
    } catch (const std::exception& e) {
      cv.failure = fmt::format("the fit without speed {:g} m/s: {}", left_out, e.what());
      return cv;
    }
  }
  cv.rms_prediction_error = std::sqrt(sum_sq / static_cast<double>(table.rows()));
  if (table.has_sd()) {
    double s = 0;
    for (double sd : table.e_sd) s += sd * sd;
    cv.scatter = std::sqrt(s / static_cast<double>(table.rows()));
  } else {
    cv.scatter = fit.sigma;
  }
  cv.ratio = cv.scatter > 0 ? cv.rms_prediction_error / cv.scatter : inf;
  return cv;
}

RestitutionLawComparison compare_laws_on_restitution(const RestitutionTable& table, const RunOptions& base,
                                                     const PaperParameters& paper,
                                                     const RestitutionFitSettings& settings) {
  RestitutionLawComparison out;
  check_restitution_fit_options(base);
  for (const LawInfo& law : registered_laws()) {
    const LawTrial trial = law_trial(base, law.name, settings.parameters);
    const RunOptions& o = trial.options;
    if (!trial.refusal.empty()) {
      out.failures.emplace_back(o.damping, trial.refusal);
      continue;
    }
    RestitutionFitSettings own = settings;
    own.parameters = trial.parameters;
    try {
      RestitutionFit f = fit_restitution_table(table, o, paper, own);
      f.left_out = trial.left_out;
      if (settings.cross_validate) f.cross_validation = cross_validate_restitution(table, o, paper, own, f);
      out.fits.push_back(std::move(f));
    } catch (const DataError&) {
      throw;  // the table's fault, the same for every law
    } catch (const std::exception& e) {
      out.failures.emplace_back(o.damping, e.what());
    }
  }
  std::stable_sort(out.fits.begin(), out.fits.end(), [](const RestitutionFit& a, const RestitutionFit& b) {
    return a.failed != b.failed ? b.failed : a.aic < b.aic;
  });
  return out;
}

}  // namespace hertzdash

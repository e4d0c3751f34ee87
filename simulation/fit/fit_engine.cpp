// The fit engine (simulation/fit/fit_engine.hpp): GSL's multifit_nlinear over any FitData, the
// covariance, criteria and failure of its solution, profile intervals, cross-validation, and
// every law compared.
#include "hertzdash/simulation/fit/fit_engine.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

namespace hertzdash {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

bool reads_option(const RunOptions& o, const std::string& option) {
  try {
    require_read(o, *find_run_option(option), "");
    return true;
  } catch (const InvalidParameter&) {
    return false;
  }
}

template <class T> using gsl_ptr = std::unique_ptr<T, void (*)(T*)>;

// The least-squares problem in the variables z = (law, nuisances), of which `free` are moved
// (the others held at their values in `z`: a profile's parameter, a prediction's law).
struct Problem {
  FitData* data;
  std::vector<Transform> law;
  std::vector<Nuisance> nuisances;
  std::vector<double> z;
  std::vector<std::size_t> free;
  std::exception_ptr error;
  const std::atomic<bool>* cancel = nullptr;  // FitSettings::cancel

  std::size_t n() const { return data->rows(); }
  std::size_t p() const { return free.size(); }
  std::vector<double> full(const double* zf) const {
    std::vector<double> v = z;
    for (std::size_t k = 0; k < free.size(); ++k) v[free[k]] = zf[k];
    return v;
  }
  std::vector<double> law_values(const std::vector<double>& v) const {
    std::vector<double> out;
    for (std::size_t j = 0; j < law.size(); ++j) out.push_back(law[j].p(v[j]));
    return out;
  }
  std::vector<double> nuisance_values(const std::vector<double>& v) const {
    std::vector<double> out;
    for (std::size_t j = 0; j < nuisances.size(); ++j) out.push_back(nuisances[j].value(v[law.size() + j]));
    return out;
  }
  // d value / d z of variable j at v.
  double derivative(std::size_t j, const std::vector<double>& v) const {
    return j < law.size() ? law[j].dp_dz(v[j]) : nuisances[j - law.size()].dvalue_dz(v[j]);
  }
  void residuals(const double* zf, double* r) {
    if (cancel && cancel->load()) throw FitCancelled();
    const std::vector<double> v = full(zf);
    if (!data->residuals(law_values(v), nuisance_values(v), r)) std::fill(r, r + n(), outside_residual);
  }
  // Central differences, step h = 1e-6 in every free variable.
  static constexpr double step = 1e-6;
  void jacobian(const double* zf, gsl_matrix* J) {
    const double h = step;
    std::vector<double> zz(zf, zf + p()), plus(n()), minus(n());
    for (std::size_t j = 0; j < p(); ++j) {
      zz[j] = zf[j] + h;
      residuals(zz.data(), plus.data());
      zz[j] = zf[j] - h;
      residuals(zz.data(), minus.data());
      zz[j] = zf[j];
      for (std::size_t i = 0; i < n(); ++i) gsl_matrix_set(J, i, j, (plus[i] - minus[i]) / (2.0 * h));
    }
  }
};

// FitResult::e_effective at the estimate v, C the covariance of the variables (fit_engine.hpp):
// each impact's e and the mean, their gradients over the law's variables by central differences.
EffectiveRestitution effective_restitution(FitData& data, const Problem& problem, const std::vector<double>& v,
                                           const std::vector<std::vector<double>>& C) {
  EffectiveRestitution r;
  r.impacts = data.restitution_at(problem.law_values(v));
  const std::size_t n = r.impacts.size(), pl = problem.law.size();
  if (n == 0) return r;
  r.value = 0;
  r.min = inf, r.max = -inf;
  for (const ImpactRestitution& i : r.impacts) {
    r.value += i.e / static_cast<double>(n);
    if (i.e < r.min) r.min = i.e, r.speed_at_min_mps = i.speed_mps;
    if (i.e > r.max) r.max = i.e, r.speed_at_max_mps = i.speed_mps;
  }
  // g[i][j] = d e_i / d z_j; row n the mean's. An impact lost at a step (it no longer separates)
  // leaves the errors NaN.
  std::vector<std::vector<double>> g(n + 1, std::vector<double>(pl, 0.0));
  bool same_impacts = true;
  for (std::size_t j = 0; j < pl && same_impacts; ++j) {
    std::vector<double> plus = v, minus = v;
    plus[j] += effective_restitution_step, minus[j] -= effective_restitution_step;
    const std::vector<ImpactRestitution> up = data.restitution_at(problem.law_values(plus));
    const std::vector<ImpactRestitution> down = data.restitution_at(problem.law_values(minus));
    same_impacts = up.size() == n && down.size() == n;
    for (std::size_t i = 0; i < n && same_impacts; ++i) {
      same_impacts = up[i].row == r.impacts[i].row && down[i].row == r.impacts[i].row;
      g[i][j] = (up[i].e - down[i].e) / (2 * effective_restitution_step);
      g[n][j] += g[i][j] / static_cast<double>(n);
    }
  }
  data.restitution_at(problem.law_values(v));  // the model's last runs at the estimate again
  if (!same_impacts) return r;
  // g^T C g over the law's block; a variable e does not depend on adds nothing, even at an infinite variance.
  const auto error = [&](const std::vector<double>& gi) {
    double variance = 0;
    for (std::size_t a = 0; a < pl; ++a)
      for (std::size_t b = 0; b < pl; ++b)
        if (gi[a] != 0 && gi[b] != 0) variance += gi[a] * C[a][b] * gi[b];
    return std::sqrt(variance);
  };
  for (std::size_t i = 0; i < n; ++i) r.impacts[i].standard_error = error(g[i]);
  r.standard_error = error(g[n]);
  return r;
}

// GSL's f and df: an exception is stored (rethrown once GSL has returned) and GSL told GSL_EBADFUNC.
int residuals_thunk(const gsl_vector* z, void* params, gsl_vector* f) {
  auto* problem = static_cast<Problem*>(params);
  try {
    problem->residuals(z->data, f->data);
    return GSL_SUCCESS;
  } catch (...) {
    problem->error = std::current_exception();
    return GSL_EBADFUNC;
  }
}
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

std::string stop_reason(int status, int info) {
  if (status == GSL_EMAXITER) return "maximum number of iterations reached";
  if (status == GSL_ENOPROG) return "no further decrease of the cost within its resolution";
  return info == 1 ? "small step (xtol)" : "small gradient (gtol)";
}

// GSL's solution: the free variables, the residuals and Jacobian there, why it stopped.
struct Solution {
  std::vector<double> z, f;
  gsl_ptr<gsl_matrix> J{nullptr, gsl_matrix_free};
  int status = GSL_SUCCESS, info = 0, iterations = 0;
  bool work_limit = false;
  double rss = 0;
};

Solution solve(Problem& problem, const std::vector<double>& z0, const FitSettings& settings) {
  const std::size_t n = problem.n(), p = problem.p();
  Solution s;
  if (p == 0) {  // nothing free: the residuals at z
    s.f.resize(n);
    problem.residuals(nullptr, s.f.data());
    for (double r : s.f) s.rss += r * r;
    return s;
  }
  if (n < p) throw DataError(problem.data->too_few(n, p));  // GSL's workspace needs n >= p
  std::vector<double> zs = z0;
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  const gsl_ptr<gsl_multifit_nlinear_workspace> w(gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p),
                                                  gsl_multifit_nlinear_free);
  if (!w) throw std::bad_alloc();
  problem.cancel = settings.cancel;
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals_thunk;
  fdf.df = jacobian_thunk;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &problem;
  gsl_vector_view start = gsl_vector_view_array(zs.data(), p);
  int status = gsl_multifit_nlinear_init(&start.vector, &fdf, w.get());
  if (problem.error) std::rethrow_exception(problem.error);
  if (status != GSL_SUCCESS) throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_init failed: ") + gsl_strerror(status));
  // gsl_multifit_nlinear_driver's loop, with the work bound checked after each iteration.
  const double work0 = problem.data->work();
  for (int iteration = 0;; ++iteration) {
    status = gsl_multifit_nlinear_iterate(w.get());
    if (problem.error) std::rethrow_exception(problem.error);
    if (status == GSL_ENOPROG && iteration == 0) break;  // no step from the start lowers the cost
    status = gsl_multifit_nlinear_test(1e-10, 1e-10, 0.0, &s.info, w.get());
    if (settings.progress) {
      const gsl_vector* f = gsl_multifit_nlinear_residual(w.get());
      double chi2 = 0;
      gsl_blas_ddot(f, f, &chi2);
      settings.progress(fmt::format("iteration {}: chi-square {:.6g}", iteration + 1, chi2));
    }
    if (status != GSL_CONTINUE) break;
    if (iteration + 1 >= settings.max_iterations) {
      status = GSL_EMAXITER;
      break;
    }
    if (problem.data->work() - work0 > settings.max_work) {
      s.work_limit = true;
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
  s.J.reset(gsl_matrix_alloc(n, p));
  gsl_matrix_memcpy(s.J.get(), gsl_multifit_nlinear_jac(w.get()));
  return s;
}

// Condition number of J with the law's columns scaled to relative changes of the parameters.
double scaled_condition_number(const gsl_matrix* J, const Problem& problem, const std::vector<double>& v) {
  const std::size_t n = J->size1, p = J->size2;
  if (n < p) return inf;
  const gsl_ptr<gsl_matrix> A(gsl_matrix_alloc(n, p), gsl_matrix_free), V(gsl_matrix_alloc(p, p), gsl_matrix_free);
  gsl_matrix_memcpy(A.get(), J);
  for (std::size_t j = 0; j < problem.law.size(); ++j) {
    const double value = problem.law[j].p(v[j]), scale = value != 0 ? std::abs(value) : 1.0;
    gsl_vector_view column = gsl_matrix_column(A.get(), j);
    gsl_vector_scale(&column.vector, scale / problem.law[j].dp_dz(v[j]));
  }
  const gsl_ptr<gsl_vector> S(gsl_vector_alloc(p), gsl_vector_free), work(gsl_vector_alloc(p), gsl_vector_free);
  if (const int status = gsl_linalg_SV_decomp(A.get(), V.get(), S.get(), work.get()); status != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_linalg_SV_decomp failed: ") + gsl_strerror(status));
  const double smallest = gsl_vector_min(S.get()), largest = gsl_vector_max(S.get());
  return smallest > 0 ? largest / smallest : inf;
}

// The norm of a Jacobian column of rounding noise alone: each r_i = (y_i - model_i) / sd_i is
// reproducible to model_rounding |y_i - r_i sd_i| / sd_i <= model_rounding (|y_i| / sd_i + |r_i|)
// (a model run is thousands of floating-point steps, not one: its rounding is about 1e3 eps, not
// eps), so a central difference of step h is noise below model_rounding (|y / sd| + |r|) / h.
double difference_noise(const FitData& data, double rss) {
  constexpr double model_rounding = 1e3 * std::numeric_limits<double>::epsilon();
  double y2 = 0;
  for (std::size_t i = 0; i < data.rows(); ++i) {
    const FitPoint row = data.row(i);
    y2 += std::pow(row.measured / row.unit, 2);
  }
  return model_rounding * (std::sqrt(y2) + std::sqrt(rss)) / Problem::step;
}

// The covariance s2 (J^T J)^-1 of the variables, infinite for a variable J does not see: its
// column's norm at most `noise` (difference_noise), or a variance GSL's pivoting sets to zero.
std::vector<std::vector<double>> covariance(const gsl_matrix* J, double s2, double noise) {
  const std::size_t p = J->size2;
  const gsl_ptr<gsl_matrix> c(gsl_matrix_alloc(p, p), gsl_matrix_free);
  if (const int s = gsl_multifit_nlinear_covar(J, 0.0, c.get()); s != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_multifit_nlinear_covar failed: ") + gsl_strerror(s));
  std::vector<std::vector<double>> out(p, std::vector<double>(p));
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j) out[i][j] = s2 * gsl_matrix_get(c.get(), i, j);
  for (std::size_t j = 0; j < p; ++j) {
    gsl_vector_const_view column = gsl_matrix_const_column(J, j);
    if (!(gsl_blas_dnrm2(&column.vector) > noise) || !(out[j][j] > 0))
      for (std::size_t i = 0; i < p; ++i) out[i][j] = out[j][i] = i == j ? inf : NAN;
  }
  return out;
}

Problem problem_of(FitData& data, const std::vector<FitParameter>& parameters) {
  Problem problem{&data, {}, data.nuisances(), {}, {}, nullptr};
  for (const FitParameter& p : parameters) problem.law.push_back({p.lower, p.upper});
  return problem;
}

// chi^2 of the problem with variable j held at zj, every other free variable re-fitted from
// the estimate; nothing where it cannot be evaluated.
std::optional<double> profile_chi_square(Problem problem, std::size_t j, double zj, const FitSettings& settings) {
  problem.z[j] = zj;
  std::erase(problem.free, j);
  std::vector<double> z0;
  for (std::size_t k : problem.free) z0.push_back(problem.z[k]);
  try {
    const Solution s = solve(problem, z0, settings);
    if (!std::isfinite(s.rss) || s.rss >= outside_residual || s.work_limit) return std::nullopt;
    return s.rss;
  } catch (const FitCancelled&) {
    throw;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Cross-validation of `fit`, the result of fit(data, ..., settings) (fit_engine.hpp, "Cross-validation").
CrossValidation cross_validate(const FitData& data, const FitSettings& settings, const FitResult& fit) {
  CrossValidation cv;
  cv.folds = data.folds();
  const std::size_t pl = settings.parameters.size();
  std::vector<double> law, nuisances;
  for (std::size_t j = 0; j < pl; ++j) law.push_back(fit.parameters[j].estimate);
  {  // this data's nuisance values, in its order: the reported ones after the law's, each group's in turn
    std::size_t reported = pl;
    std::vector<std::size_t> in_group(fit.groups.size(), 0);
    for (const Nuisance& u : data.nuisances())
      nuisances.push_back(u.group ? fit.groups[*u.group].nuisances[in_group[*u.group]++].estimate
                                  : fit.parameters[reported++].estimate);
  }
  FitSettings fold = settings;
  fold.profile_intervals = fold.cross_validate = false;
  fold.progress = {};
  const bool standardized = data.mixed_units();
  double sum_sq = 0, dof = 0;
  for (std::size_t k = 0; k < cv.folds; ++k) {
    if (settings.progress) settings.progress(fmt::format("cross-validation: fold {} of {}, without {}", k + 1, cv.folds, data.fold_name(k)));
    try {
      const std::unique_ptr<FitData> rest = data.part(k, false, nuisances), held = data.part(k, true, nuisances);
      const FitResult f = hertzdash::fit(*rest, fit.law, fold, law);
      if (f.failed) throw std::runtime_error(f.failure);
      // The left-out part: the law fixed at the rest's estimate, its own nuisances fitted.
      Problem problem = problem_of(*held, settings.parameters);
      for (std::size_t j = 0; j < pl; ++j) problem.z.push_back(problem.law[j].z(f.parameters[j].estimate));
      std::vector<double> z0;
      for (const Nuisance& u : problem.nuisances) {
        problem.free.push_back(problem.z.size());
        problem.z.push_back(u.variable(u.start));
        z0.push_back(problem.z.back());
      }
      const Solution s = solve(problem, z0, fold);
      if (!(s.rss < outside_residual)) throw std::runtime_error("the model cannot be evaluated on the left-out data");
      for (std::size_t i = 0; i < held->rows(); ++i) sum_sq += std::pow(standardized ? s.f[i] : s.f[i] * held->row(i).unit, 2);
      dof += static_cast<double>(held->rows()) - static_cast<double>(problem.nuisances.size());
    } catch (const FitCancelled&) {
      throw;
    } catch (const std::exception& e) {  // a DataError too: a fold too small to fit, the full fit stands
      cv.failure = fmt::format("the fit without {}: {}", data.fold_name(k), e.what());
      return cv;
    }
  }
  cv.rms_prediction_error = std::sqrt(sum_sq / dof);
  if (standardized) {
    cv.scatter = 1;  // of r_i = e_i / sd_i
  } else if (data.sd_known()) {
    double s = 0;
    for (const FitPoint& pt : fit.points) s += pt.unit * pt.unit;
    cv.scatter = std::sqrt(s / static_cast<double>(fit.points.size()));
  } else {
    cv.scatter = fit.sigma;
  }
  cv.ratio = cv.scatter > 0 ? cv.rms_prediction_error / cv.scatter : inf;
  return cv;
}

// A request's predicted work: one fit (with two or more law parameters, its nested fits and
// restarts), its folds and its profiles (about 20 refits a parameter).
double request_work(const FitWork& one, const FitData& data, const FitSettings& settings) {
  const double folds = settings.cross_validate ? static_cast<double>(data.folds()) : 0.0;
  const double pl = static_cast<double>(settings.parameters.size());
  const double profiles = settings.profile_intervals ? 20.0 * pl : 0.0, nested = pl >= 2 ? 1.0 + 2.0 * pl : 1.0;  // in doubt
  return one.units * nested * (1.0 + folds + profiles);
}

// Refuses a request predicted above max_predicted_fit_work (see the header, "Work").
void require_bounded_fit_work(const FitWork& one, double total, const std::string& what) {
  if (!(total > max_predicted_fit_work)) return;
  throw DataError(fmt::format("{}: {} is predicted at about {:.3g} units of work (one fit {:.3g}; a unit is about 1 us "
                              "on one core of the development machine), above the {:.3g} (about a minute) a fit may "
                              "take: fit fewer data at a time, or ask for less",
                              one.size, what, total, one.units, max_predicted_fit_work));
}

}  // namespace

const FittedParameter& FitResult::parameter(const std::string& name) const {
  for (const FittedParameter& q : parameters)
    if (q.name == name) return q;
  throw std::out_of_range("fit: no fitted parameter " + name);
}

FitResult fit(FitData& data, const std::string& law, const FitSettings& request,
              const std::optional<std::vector<double>>& start) {
  use_gsl_return_codes();
  FitSettings settings = request;
  settings.progress = {};  // only for a request predicted long
  if (const FitWork one = data.predicted_work(request.parameters.size()); one.units > 0) {
    const double total = request_work(one, data, request);
    std::string what = "the fit";
    if (request.cross_validate) what += fmt::format(" and its {} cross-validation folds", data.folds());
    if (request.profile_intervals) what += " and its profile intervals";
    require_bounded_fit_work(one, total, what);
    if (total >= progress_fit_work) settings.progress = request.progress;
  }
  const std::vector<FitParameter>& parameters = settings.parameters;
  Problem problem = problem_of(data, parameters);
  const std::size_t pl = parameters.size(), n = problem.n(), p = pl + problem.nuisances.size();
  if (n <= p) throw DataError(data.too_few(n, p));
  const std::vector<double> initial = start ? *start : data.start(parameters);
  for (std::size_t j = 0; j < pl; ++j) problem.z.push_back(problem.law[j].z(initial[j]));
  for (const Nuisance& u : problem.nuisances) problem.z.push_back(u.z_start ? *u.z_start : u.variable(u.start));
  for (std::size_t j = 0; j < p; ++j) problem.free.push_back(j);
  {
    std::vector<double> r(n);
    problem.residuals(problem.z.data(), r.data());
    if (std::any_of(r.begin(), r.end(), [](double v) { return v >= outside_residual; })) {
      std::string values;
      for (std::size_t j = 0; j < pl; ++j)
        values += fmt::format("{}{} {:.6g}", j ? ", " : "", parameters[j].option, initial[j]);
      const std::string why = data.outside_domain();
      throw InvalidParameter("the fit's starting values", values,
                             "values at which the model runs" + (why.empty() ? std::string() : ": " + why));
    }
  }
  const double work_start = data.work();
  Solution s = solve(problem, problem.z, settings);
  // A fit with more parameters is never worse than one with fewer at its optimum: where the fit
  // is in doubt (not converged, or ill-conditioned), each law parameter in turn is held at its
  // start (the fit without it); a lower chi-square there means the full fit stopped short (a far
  // start, a flat valley), and it is restarted from there, which a trust region cannot leave uphill.
  std::string restarted;
  const bool doubtful = pl >= 2 && !s.work_limit &&
                        (s.status != GSL_SUCCESS ||
                         !(scaled_condition_number(s.J.get(), problem, s.z) < identifiable_condition_limit));
  for (std::size_t j = 0; doubtful && j < pl; ++j) {
    FitSettings rest = settings;  // one work budget for the fit and its nested fits
    rest.max_work = settings.max_work - (data.work() - work_start);
    if (!(rest.max_work > 0)) break;
    Problem nested = problem;
    std::erase(nested.free, j);
    std::vector<double> z0;
    for (std::size_t k : nested.free) z0.push_back(nested.z[k]);
    const Solution fewer = solve(nested, z0, rest);
    if (!(fewer.rss < s.rss * (1.0 - 1e-9))) continue;
    std::vector<double> from = nested.z;  // every variable: the nested fit's free ones, parameter j at its start
    for (std::size_t k = 0; k < nested.free.size(); ++k) from[nested.free[k]] = fewer.z[k];
    rest.max_work = settings.max_work - (data.work() - work_start);
    if (!(rest.max_work > 0)) break;
    Solution again = solve(problem, from, rest);
    if (again.rss < s.rss) {
      restarted = fmt::format("restarted from the fit with {} held at its start ({:.6g}), whose chi-square {:.6g} was below "
                              "the first fit's {:.6g}",
                              parameters[j].option, initial[j], fewer.rss, s.rss);
      s = std::move(again);
    }
  }
  const std::vector<double> v = s.z;
  problem.z = v;

  FitResult fit;
  fit.law = law;
  fit.n = n;
  fit.p = p;
  fit.stop_reason = s.work_limit ? fmt::format("work limit reached ({:.3g} RK4 steps and interpolations)", settings.max_work)
                                 : stop_reason(s.status, s.info);
  if (!restarted.empty()) fit.stop_reason += "; " + restarted;
  fit.converged = s.status == GSL_SUCCESS;
  fit.iterations = s.iterations;
  fit.chi_square = s.rss;
  const double s2_fit = s.rss / static_cast<double>(n - p);
  fit.sigma_estimated = !data.sd_known();
  fit.sigma = fit.sigma_estimated ? std::sqrt(s2_fit) : 0.0;
  fit.reduced_chi_square = fit.sigma_estimated ? NAN : s2_fit;
  // The scale of the covariance and of the profiles' rise: with sd known never below 1 (the stated
  // scatter is not scaled away by data that agree better than it: six identical rows), with sigma
  // estimated never below the model's accuracy (noise-free data).
  const double s2 = fit.sigma_estimated ? std::max(s2_fit, data.least_variance()) : std::max(s2_fit, 1.0);
  const std::vector<std::vector<double>> C = covariance(s.J.get(), s2, difference_noise(data, s.rss));
  fit.condition_number = scaled_condition_number(s.J.get(), problem, v);

  // The parameters: the law's, then the nuisances of every row; a group's own with its group.
  const std::vector<std::string> labels = data.groups();
  for (const std::string& label : labels) fit.groups.push_back({label, 0, 1, 0, {}});
  std::vector<std::size_t> reported;
  bool finite_errors = true;
  for (std::size_t j = 0; j < p; ++j) {
    const double se = std::abs(problem.derivative(j, v)) * std::sqrt(C[j][j]);
    finite_errors = finite_errors && std::isfinite(se);
    if (j < pl) {
      const Transform& t = problem.law[j];
      FittedParameter fp{parameters[j].option, initial[j], t.p(v[j]), se, t.lo, t.hi};
      // At a bound the transform flattens (dp/dz -> 0) and the standard error shrinks with it:
      // within 1e-3 of the range (two bounds) or of the starting distance from the bound.
      fp.at_bound = t.two_sided() ? std::abs(v[j]) > std::log(1e3) : (fp.estimate - t.lo) < 1e-3 * std::abs(initial[j] - t.lo);
      fit.parameters.push_back(fp);
      reported.push_back(j);
      continue;
    }
    const Nuisance& u = problem.nuisances[j - pl];
    FittedParameter fp{u.name, u.start, u.value(v[j]), se, u.log ? 0.0 : -inf, inf};
    if (u.group) fit.groups[*u.group].nuisances.push_back(fp);
    else fit.parameters.push_back(fp), reported.push_back(j);
  }
  double largest_correlation = 0;
  for (std::size_t a : reported) {
    fit.correlation.emplace_back();
    for (std::size_t b : reported) {
      const double c = C[a][b] / std::sqrt(C[a][a] * C[b][b]);
      fit.correlation.back().push_back(c);
      if (a != b) largest_correlation = std::max(largest_correlation, std::isfinite(c) ? std::abs(c) : 1.0);
    }
  }
  std::vector<std::string> why;
  if (s.work_limit)
    why.push_back(fmt::format("it reached its work limit ({:.3g} RK4 steps and interpolations)", settings.max_work));
  else if (s.status == GSL_EMAXITER) why.push_back(fmt::format("it reached its iteration limit ({})", settings.max_iterations));
  for (std::size_t j = 0; j < pl; ++j)
    if (fit.parameters[j].at_bound)
      why.push_back(fmt::format("{} ended at its bound ({:.6g})", fit.parameters[j].name, fit.parameters[j].estimate));
  if (pl > 0 && std::none_of(fit.parameters.begin(), fit.parameters.begin() + static_cast<std::ptrdiff_t>(pl),
                             [](const FittedParameter& fp) { return std::isfinite(fp.standard_error); }))
    why.push_back("no fitted parameter has a finite standard error");
  if (!std::isfinite(fit.chi_square) || fit.chi_square >= outside_residual)
    why.push_back("the model could not be evaluated at the estimate");
  fit.failed = !why.empty();
  for (const std::string& reason : why) fit.failure += (fit.failure.empty() ? "" : "; ") + reason;
  const bool determined = std::all_of(fit.parameters.begin(), fit.parameters.begin() + static_cast<std::ptrdiff_t>(pl),
                                     [](const FittedParameter& fp) {
                                       return fp.standard_error < identifiable_relative_error_limit * std::abs(fp.estimate);
                                     });
  fit.identifiable = !fit.failed && finite_errors && determined && fit.condition_number < identifiable_condition_limit &&
                     largest_correlation < identifiable_correlation_limit;

  const double k = static_cast<double>(p), nn = static_cast<double>(n);
  if (fit.sigma_estimated) {
    const double log_variance = std::log(std::max(fit.chi_square / nn, data.least_variance()));
    fit.aic = nn * log_variance + 2.0 * (k + 1.0);
    fit.bic = nn * log_variance + (k + 1.0) * std::log(nn);
  } else {
    fit.aic = fit.chi_square + 2.0 * k;
    fit.bic = fit.chi_square + k * std::log(nn);
  }

  // Every row at the estimate, each group's residual RMS.
  std::vector<double> sum_sq(fit.groups.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    FitPoint pt = data.row(i);
    const bool inside = s.f[i] < outside_residual;
    pt.residual = inside ? s.f[i] * pt.unit : NAN;
    pt.model = pt.measured - pt.residual;
    if (pt.group) {
      FitGroup& g = fit.groups[*pt.group];
      ++g.rows;
      g.unit = pt.unit;
      sum_sq[*pt.group] += pt.residual * pt.residual;
    }
    fit.points.push_back(pt);
  }
  for (std::size_t g = 0; g < fit.groups.size(); ++g)
    fit.groups[g].residual_rms = std::sqrt(sum_sq[g] / static_cast<double>(fit.groups[g].rows));
  data.finish(fit, problem.law_values(v), problem.nuisance_values(v));
  fit.e_effective = effective_restitution(data, problem, v, C);
  fit.work = data.work();

  if (settings.profile_intervals && !fit.failed)
    for (std::size_t j = 0; j < pl; ++j) {
      FittedParameter& fp = fit.parameters[j];
      const Transform& t = problem.law[j];
      auto rise = [&](double zj) -> std::optional<double> {
        const std::optional<double> chi2 = profile_chi_square(problem, j, zj, settings);
        return chi2 ? std::optional<double>(*chi2 - fit.chi_square) : std::nullopt;
      };
      fp.profile = profile_interval(rise, s2, v[j], fp.standard_error / std::abs(t.dp_dz(v[j])),
                                    [&t](double zj) { return t.p(zj); });
    }
  if (settings.cross_validate) fit.cross_validation = cross_validate(data, settings, fit);
  return fit;
}


std::vector<FitParameter> law_fit_parameters(const RunOptions& base) {
  if (const ParameterDecl* constant = registered_law(base.damping).material_constant())
    return parse_fit_parameters(std::string(constant->key));
  if (reads_option(base, "restitution")) return parse_fit_parameters("restitution");
  return {};
}

LawTrial law_trial(const RunOptions& base, std::string_view law, const std::vector<FitParameter>& parameters) {
  LawTrial t{base, parameters, {}, {}};
  RunOptions& o = t.options;
  o.damping = std::string(law);
  for (const RunOption& option : run_options())
    if (is_given(o, option) && !reads_option(o, option.name)) {
      clear_option(o, option);
      t.left_out.push_back(option.name);
    }
  std::erase_if(t.parameters, [&](const FitParameter& p) {
    const bool unread = !reads_option(o, p.option);
    if (unread && std::find(t.left_out.begin(), t.left_out.end(), p.option) == t.left_out.end())
      t.left_out.push_back(p.option);
    return unread;
  });
  if (!parameters.empty() && t.parameters.empty()) t.refusal = "it reads none of the parameters given to fit";
  else if (parameters.empty() && law_fit_parameters(o).empty())
    t.refusal = "nothing to fit: it reads neither the input e nor a time constant (its e does not depend on a "
                "parameter of its own)";
  return t;
}

namespace {

// Every law's fit predicted at the default law's (see the header, "Work"): refused above the
// bound, the progress kept only above progress_fit_work.
void bound_comparison_work(const FitDataMaker& make, const RunOptions& base, FitSettings& settings) {
  const auto progress = std::exchange(settings.progress, {});  // only for a request predicted long
  const LawTrial trial = law_trial(base, RunOptions{}.damping, settings.parameters);
  if (!trial.refusal.empty()) return;
  const std::vector<FitParameter> parameters = trial.parameters.empty() ? law_fit_parameters(trial.options) : trial.parameters;
  const std::unique_ptr<FitData> data = make(trial.options, parameters);
  const FitWork one = data->predicted_work(parameters.size());
  if (!(one.units > 0)) return;
  const double total = request_work(one, *data, settings) * static_cast<double>(registered_laws().size());
  require_bounded_fit_work(one, total, fmt::format("fitting every one of the {} laws", registered_laws().size()));
  if (total >= progress_fit_work) settings.progress = progress;
}

}  // namespace

LawComparison compare_laws(const FitDataMaker& make, const RunOptions& base, const FitSettings& request) {
  LawComparison out;
  FitSettings settings = request;
  bound_comparison_work(make, base, settings);
  const std::vector<LawInfo> laws = registered_laws();
  for (const LawInfo& law : laws) {
    if (settings.progress)
      settings.progress(fmt::format("law {} of {}: {}", static_cast<std::size_t>(&law - laws.data()) + 1, laws.size(), law.name));
    const LawTrial trial = law_trial(base, law.name, settings.parameters);
    const RunOptions& o = trial.options;
    if (!trial.refusal.empty()) {
      out.failures.emplace_back(o.damping, trial.refusal);
      continue;
    }
    FitSettings own = settings;
    own.parameters = trial.parameters.empty() ? law_fit_parameters(o) : trial.parameters;
    try {
      const std::unique_ptr<FitData> data = make(o, own.parameters);
      FitResult f = fit(*data, o.damping, own);
      f.left_out = trial.left_out;
      out.fits.push_back(std::move(f));
    } catch (const DataError&) {
      throw;  // the data's fault, the same for every law
    } catch (const FitCancelled&) {
      throw;
    } catch (const std::exception& e) {
      out.failures.emplace_back(o.damping, e.what());
    }
  }
  // Failed fits last: the best is a fit that determined its parameters, if any did.
  std::stable_sort(out.fits.begin(), out.fits.end(), [](const FitResult& a, const FitResult& b) {
    return a.failed != b.failed ? b.failed : a.aic < b.aic;
  });
  return out;
}

}  // namespace hertzdash

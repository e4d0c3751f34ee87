// Measured rebound angles as a kind of data for the fit engine (simulation/fit/oblique_fit.hpp):
// its rows, starting values, residuals of the rebound angle against the incident angle and folds
// (each row); the fit and its cross-validation are the engine's.
#include "hertzdash/simulation/fit/oblique_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <string_view>

namespace hertzdash {

namespace {

/// The linear spring's default k_t (Mindlin's 8 G* a at the undamped Hertz maximum overlap) of the
/// head-on impact at `base`'s speed.
double head_on_linear_stiffness(ObliqueImpactSpec base) {
  base.incidence_angle_deg = 0;
  return matched_linear_stiffness_N_per_m(base);
}

/// The parameters a fit of rebound angles can take: the option, its start from the base run, and
/// where its value goes in each run.
struct ReboundAngleParameter {
  std::string_view option;
  double (*start)(const ObliqueImpactSpec& base);
  void (*apply)(ObliqueImpactSpec& run, double value);
};
constexpr ReboundAngleParameter rebound_angle_parameters[] = {
    {"friction", [](const ObliqueImpactSpec&) { return 0.1; }, [](ObliqueImpactSpec& s, double v) { s.friction = v; }},
    {"ball-nu", [](const ObliqueImpactSpec& b) { return b.setup.ball.nu; },
     [](ObliqueImpactSpec& s, double v) { s.setup.ball.nu = v; }},
    {"tangential-stiffness",
     [](const ObliqueImpactSpec& b) { return b.linear_stiffness_N_per_m ? *b.linear_stiffness_N_per_m : head_on_linear_stiffness(b); },
     [](ObliqueImpactSpec& s, double v) { s.linear_stiffness_N_per_m = v; }},
};

/// The entry of rebound_angle_parameters for `option`, or nullptr.
const ReboundAngleParameter* find_rebound_angle_parameter(std::string_view option) {
  for (const ReboundAngleParameter& p : rebound_angle_parameters)
    if (p.option == option) return &p;
  return nullptr;
}

class ReboundAngleData final : public FitData {
 public:
  ReboundAngleData(ReboundAngleTable table, ObliqueImpactSpec base, std::vector<std::string> names)
      : table_(std::move(table)), base_(std::move(base)), names_(std::move(names)) {
    base_.solver = oblique_fit_solver();
  }

  std::size_t rows() const override { return table_.incidence_angle_deg.size(); }
  FitPoint row(std::size_t i) const override {
    return {std::nullopt, i, 0, table_.incidence_angle_deg[i], table_.rebound_angle_deg[i], 0, 0, 1.0};
  }
  std::vector<double> start(const std::vector<FitParameter>& parameters) override {
    std::vector<double> v;
    for (const FitParameter& p : parameters) v.push_back(find_rebound_angle_parameter(p.option)->start(base_));
    return v;
  }
  bool residuals(const std::vector<double>& law, const std::vector<double>&, double* r) override {
    for (std::size_t i = 0; i < rows(); ++i) {
      ObliqueImpactResult run;
      try {
        run = run_at(law, table_.incidence_angle_deg[i]);
      } catch (const std::runtime_error& e) {
        outside_ = e.what();
        return false;
      }
      if (!run.separated) {
        outside_ = fmt::format("the sphere did not separate at {:g} degrees", table_.incidence_angle_deg[i]);
        return false;
      }
      r[i] = table_.rebound_angle_deg[i] - run.rebound_angle_deg;
    }
    return true;
  }
  bool sd_known() const override { return false; }
  double least_variance() const override { return 1e-6 * 1e-6; }  // the runs' accuracy in degrees, and then some
  std::string outside_domain() const override { return outside_; }
  // A run takes about 0.1 ms at the fit's tolerance (about 200 steps): 2e2 units, with margin; a fit about 10
  // iterations of 2 p + 2 evaluations of every row.
  FitWork predicted_work(std::size_t p) const override {
    return {2e2 * static_cast<double>(rows()) * 10.0 * (2.0 * static_cast<double>(p) + 2.0),
            fmt::format("{}: {} rebound angles, {} parameter{}", table_.source, rows(), p, p == 1 ? "" : "s")};
  }
  std::string too_few(std::size_t n, std::size_t p) const override {
    return fmt::format("{}: {} rebound angles cannot determine {} parameters", table_.source, n, p);
  }
  std::size_t folds() const override {
    if (rows() < 2) throw DataError(table_.source + ": cross-validation leaves out each row in turn and needs two");
    return rows();
  }
  std::string fold_name(std::size_t k) const override { return fmt::format("{:g} degrees", table_.incidence_angle_deg[k]); }
  std::unique_ptr<FitData> part(std::size_t k, bool held, const std::vector<double>&) const override {
    ReboundAngleTable t{table_.source, {}, {}};
    for (std::size_t i = 0; i < rows(); ++i)
      if ((i == k) == held) {
        t.incidence_angle_deg.push_back(table_.incidence_angle_deg[i]);
        t.rebound_angle_deg.push_back(table_.rebound_angle_deg[i]);
      }
    return std::make_unique<ReboundAngleData>(std::move(t), base_, names_);
  }
  void finish(FitResult& fit, const std::vector<double>&, const std::vector<double>&) override {
    fit.model_runs = runs_;
    fit.integrator_used = "dormand-prince";
    fit.model_solver = base_.solver;
  }

 private:
  ObliqueImpactResult run_at(const std::vector<double>& law, double angle_deg) {
    ObliqueImpactSpec s = base_;
    s.incidence_angle_deg = angle_deg;
    for (std::size_t j = 0; j < names_.size(); ++j) find_rebound_angle_parameter(names_[j])->apply(s, law[j]);
    ++runs_;
    return run_oblique_impact(s);
  }

  ReboundAngleTable table_;
  ObliqueImpactSpec base_;
  std::vector<std::string> names_;
  int runs_ = 0;
  std::string outside_;
};

}  // namespace

SolverSettings oblique_fit_solver() {
  SolverSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-12;
  return s;
}

FitResult fit_rebound_angles(const ReboundAngleTable& table, const ObliqueImpactSpec& base, const FitSettings& given) {
  if (table.incidence_angle_deg.size() != table.rebound_angle_deg.size())
    throw DataError(table.source + ": as many rebound angles as incident angles are needed");
  FitSettings settings = given;
  if (settings.parameters.empty()) settings.parameters = {{"friction", 1e-3, 2.0}};
  std::vector<std::string> names;
  for (const FitParameter& p : settings.parameters) {
    if (!find_rebound_angle_parameter(p.option)) {
      std::string options;
      for (const ReboundAngleParameter& q : rebound_angle_parameters) options += (options.empty() ? "" : ", ") + std::string(q.option);
      throw InvalidParameter("fit", p.option, "one of " + options + ", the parameters fitted to rebound angles");
    }
    if (p.option == "tangential-stiffness" && base.tangential_model != "linear-spring")
      throw InvalidParameter("fit", p.option, "fitted with the tangential model linear-spring only");
    names.push_back(p.option);
  }
  const auto stiffness = std::find(names.begin(), names.end(), "tangential-stiffness");
  if (stiffness == names.end() || names.size() != 2) {
    ReboundAngleData data(table, base, names);
    return fit(data, base.tangential_model, settings);
  }
  // mu and k_t together: the least squares have many minima in k_t (the header), so mu alone is
  // fitted on a grid of k_t, 20 points a decade over a decade and a half either side of k_t0 (the
  // given stiffness, else the default), within the parameter's bounds, and the best point starts
  // the joint fit.
  const std::size_t k = static_cast<std::size_t>(stiffness - names.begin()), m = 1 - k;
  const double k0 = base.linear_stiffness_N_per_m ? *base.linear_stiffness_N_per_m : head_on_linear_stiffness(base);
  FitSettings scan = settings;
  scan.parameters = {settings.parameters[m]};
  scan.cross_validate = scan.profile_intervals = false;
  std::vector<double> best_start(2);
  double best_chi_square = INFINITY;
  for (int i = -30; i <= 30; ++i) {
    const double k_t = k0 * std::pow(10.0, i / 20.0);
    if (!(k_t > settings.parameters[k].lower && k_t < settings.parameters[k].upper)) continue;
    ObliqueImpactSpec at = base;
    at.linear_stiffness_N_per_m = k_t;
    ReboundAngleData data(table, at, {"friction"});
    const FitResult r = fit(data, base.tangential_model, scan);
    if (!r.failed && r.chi_square < best_chi_square)
      best_chi_square = r.chi_square, best_start[m] = r.parameters[0].estimate, best_start[k] = k_t;
  }
  if (!std::isfinite(best_chi_square))
    throw DataError(table.source + ": mu could not be fitted at any k_t of the scan within the stiffness's bounds");
  ReboundAngleData data(table, base, names);
  return fit(data, base.tangential_model, settings, best_start);
}

}  // namespace hertzdash

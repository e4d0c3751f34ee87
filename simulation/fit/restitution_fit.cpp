// A restitution table as a kind of data for the fit engine (simulation/fit/restitution_fit.hpp):
// its rows, the law's starting values, its residuals of e against the speed, its folds (the
// distinct speeds); the fit, its cross-validation and every law compared are the engine's.
#include "hertzdash/simulation/fit/restitution_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace hertzdash {

using namespace restitution_fit_detail;
using namespace fit_detail;

namespace {

class TableData final : public FitData {
 public:
  TableData(RestitutionTable table, const RunOptions& base, const PaperParameters& paper, std::vector<std::string> names)
      : table_(std::move(table)), base_(base), paper_(&paper), names_(names), model_(base, paper, std::move(names)) {}

  std::size_t rows() const override { return table_.rows(); }
  FitPoint row(std::size_t i) const override {
    return {std::nullopt, i, 0, table_.impact_speed_mps[i], table_.e[i], 0, 0, table_.has_sd() ? table_.e_sd[i] : 1.0};
  }
  // The starting values (restitution_fit.hpp, "Parameters"); a set-up the options refuse says why.
  std::vector<double> start(const std::vector<FitParameter>& parameters) override {
    const double e_mean = std::clamp(mean(table_.e), 0.01, 0.99);
    std::vector<double> v = law_starting_values(base_, *paper_, parameters, e_mean, median(table_.impact_speed_mps));
    (void)restitution_contact(model_.options_at(v), *paper_, table_.impact_speed_mps.front());
    return v;
  }
  bool residuals(const std::vector<double>& law, const std::vector<double>&, double* r) override {
    const auto m = model_.e_at(law, table_.impact_speed_mps);
    if (!m) return false;
    for (std::size_t i = 0; i < rows(); ++i) r[i] = (table_.e[i] - (*m)[i]) / row(i).unit;
    return true;
  }
  bool sd_known() const override { return table_.has_sd(); }
  double least_variance() const override { return 1e-9 * 1e-9; }  // the model's accuracy in e
  // A model evaluation runs one contact per distinct speed, about 17 us each; a fit makes about
  // 10 iterations of 2 p + 2 evaluations (measured: 200 speeds, p = 1, 0.14 s; leave-one-out
  // over 100 speeds 6.6 s).
  FitWork predicted_work(std::size_t p) const override {
    const double speeds_n = static_cast<double>(speeds().size());
    return {17.0 * speeds_n * 10.0 * (2.0 * static_cast<double>(p) + 2.0),
            fmt::format("{}: {} rows at {} distinct speeds, {} parameter{}", table_.path.string(), rows(), speeds().size(), p,
                        p == 1 ? "" : "s")};
  }
  std::string too_few(std::size_t n, std::size_t p) const override {
    return fmt::format("{}: {} rows cannot determine {} parameters", table_.path.string(), n, p);
  }
  std::size_t folds() const override {
    if (speeds().size() < 2)
      throw DataError(fmt::format("{}: cross-validation leaves out each distinct impact speed in turn and needs at "
                                  "least two (the table has {})",
                                  table_.path.string(), speeds().size()));
    return speeds().size();
  }
  std::string fold_name(std::size_t k) const override {
    return fmt::format("speed {:g} m/s", *std::next(speeds().begin(), static_cast<std::ptrdiff_t>(k)));
  }
  std::unique_ptr<FitData> part(std::size_t k, bool held, const std::vector<double>&) const override {
    const double left_out = *std::next(speeds().begin(), static_cast<std::ptrdiff_t>(k));
    RestitutionTable t = table_;
    t.impact_speed_mps.clear(), t.e.clear(), t.e_sd.clear(), t.contact_time_s.clear();
    for (std::size_t i = 0; i < table_.rows(); ++i)
      if ((table_.impact_speed_mps[i] == left_out) == held) {
        t.impact_speed_mps.push_back(table_.impact_speed_mps[i]);
        t.e.push_back(table_.e[i]);
        if (table_.has_sd()) t.e_sd.push_back(table_.e_sd[i]);
      }
    return std::make_unique<TableData>(std::move(t), base_, *paper_, names_);
  }
  void finish(FitResult& fit, const std::vector<double>& law, const std::vector<double>&) override {
    fit.model_runs = model_.runs();
    fit.integrator_used = model_.integrator_used();
    fit.model_solver = restitution_model_solver();
    fit.fitted_options = model_.options_at(law);
  }
  std::vector<ImpactRestitution> restitution_at(const std::vector<double>& law) override {
    std::vector<ImpactRestitution> at;
    if (const auto m = model_.e_at(law, table_.impact_speed_mps))
      for (std::size_t i = 0; i < rows(); ++i)
        if ((*m)[i] > 0) at.push_back({i, table_.impact_speed_mps[i], (*m)[i]});
    return at;
  }

 private:
  std::set<double> speeds() const { return {table_.impact_speed_mps.begin(), table_.impact_speed_mps.end()}; }

  RestitutionTable table_;
  RunOptions base_;
  const PaperParameters* paper_;
  std::vector<std::string> names_;
  RestitutionModel model_;
};

std::vector<std::string> names_of(const std::vector<FitParameter>& parameters) {
  std::vector<std::string> names;
  for (const FitParameter& p : parameters) names.push_back(p.option);
  return names;
}

// The settings with the law's own parameters where none are given; refused for a law with none.
FitSettings with_parameters(const RunOptions& base, FitSettings settings) {
  if (settings.parameters.empty()) settings.parameters = law_fit_parameters(base);
  if (settings.parameters.empty())
    throw InvalidParameter("damping", base.damping,
                           "a law with a parameter to fit for `restitution-table` (this one reads neither `restitution` "
                           "nor a time constant: its e is fixed), or parameters given with `fit`");
  return settings;
}

}  // namespace

FitResult fit_restitution_table(const RestitutionTable& table, const RunOptions& base, const PaperParameters& paper,
                                     const FitSettings& given) {
  check_restitution_fit_options(base);
  resolve_setup(base, paper);  // the options' own refusals first
  const FitSettings settings = with_parameters(base, given);
  TableData data(table, base, paper, names_of(settings.parameters));
  return fit(data, base.damping, settings);
}

LawComparison compare_laws_on_restitution(const RestitutionTable& table, const RunOptions& base,
                                                     const PaperParameters& paper,
                                                     const FitSettings& settings) {
  check_restitution_fit_options(base);
  return compare_laws(
      [&](const RunOptions& o, const std::vector<FitParameter>& parameters) {
        return std::make_unique<TableData>(table, o, paper, names_of(parameters));
      },
      base, settings);
}

}  // namespace hertzdash

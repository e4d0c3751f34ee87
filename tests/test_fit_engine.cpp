// The fit engine's bookkeeping (simulation/fit/fit_engine.hpp) on a kind of data small enough to
// know exactly: drops in free fall, positions y = y0_d + v0_d t - g t^2 / 2 sampled without noise,
// the law's parameter g, each drop's start height y0_d and speed v0_d its nuisances, the drops
// the folds of the cross-validation.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/fit/fit_engine.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <string>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double g_true = 9.81;  // [m/s^2]
using Drops = std::vector<std::vector<double>>;  // each drop's sample times [s]

class FreeFall final : public FitData {
 public:
  /// drops[d]: the sample times of drop d [s]; each drop starts at rest from y0 = 1 m.
  explicit FreeFall(std::vector<std::vector<double>> drops, std::vector<double> start = {})
      : drops_(std::move(drops)), start_(std::move(start)) {
    if (start_.empty())
      for (std::size_t d = 0; d < drops_.size(); ++d) start_.insert(start_.end(), {0.9, 0.1});
    for (std::size_t d = 0; d < drops_.size(); ++d)
      for (double t : drops_[d]) rows_.push_back({d, t});
  }
  std::size_t rows() const override { return rows_.size(); }
  FitPoint row(std::size_t i) const override {
    const auto [d, t] = rows_[i];
    return {d, 0, 0, t, 1.0 - g_true * t * t / 2, 0, 0, 1.0};
  }
  std::vector<std::string> groups() const override {
    std::vector<std::string> labels;
    for (std::size_t d = 0; d < drops_.size(); ++d) labels.push_back(fmt::format("drop {}", d));
    return labels;
  }
  std::vector<Nuisance> nuisances() const override {
    std::vector<Nuisance> out;
    for (std::size_t d = 0; d < drops_.size(); ++d) {
      out.push_back({"y0", start_[2 * d], false, 1.0, d});
      out.push_back({"v0", start_[2 * d + 1], false, 1.0, d});
    }
    return out;
  }
  std::vector<double> start(const std::vector<FitParameter>&) override { return {5.0}; }
  bool residuals(const std::vector<double>& law, const std::vector<double>& u, double* r) override {
    for (std::size_t i = 0; i < rows(); ++i) {
      const auto [d, t] = rows_[i];
      r[i] = row(i).measured - (u[2 * d] + u[2 * d + 1] * t - law[0] * t * t / 2);
    }
    return true;
  }
  bool sd_known() const override { return false; }
  double least_variance() const override { return 1e-30; }
  std::string too_few(std::size_t n, std::size_t p) const override {
    return fmt::format("{} rows cannot determine {} parameters", n, p);
  }
  std::size_t folds() const override { return drops_.size(); }
  std::string fold_name(std::size_t k) const override { return fmt::format("drop {}", k); }
  std::unique_ptr<FitData> part(std::size_t k, bool held, const std::vector<double>& u) const override {
    std::vector<std::vector<double>> drops;
    std::vector<double> start;
    for (std::size_t d = 0; d < drops_.size(); ++d)
      if ((d == k) == held) drops.push_back(drops_[d]), start.insert(start.end(), {u[2 * d], u[2 * d + 1]});
    return std::make_unique<FreeFall>(std::move(drops), std::move(start));
  }
  void finish(FitResult&, const std::vector<double>&, const std::vector<double>&) override {}
  FitWork predicted_work(std::size_t) const override { return {predicted_units, "free fall"}; }
  double predicted_units = 0;  ///< what predicted_work() says one fit costs

 private:
  std::vector<std::vector<double>> drops_;
  std::vector<double> start_;
  std::vector<std::pair<std::size_t, double>> rows_;
};

FitSettings gravity_settings() {
  FitSettings s;
  s.parameters = {{"gravity", 0.0}};
  s.cross_validate = true;
  return s;
}

}  // namespace

// Drop 0 has one sample, drop 1 six: the whole data has n = 7 rows for p = 1 + 2 * 2 = 5
// variables, so it is fitted. Left out in turn, drop 0 alone is predicted with g fixed and its
// own y0, v0 fitted: 1 row for 2 variables, which cannot determine them (GSL's workspace needs
// n >= p). That fold is the cross-validation's failure, with the data's own message; the fit
// stands, its g the truth (drop 1 alone determines it: a parabola through six exact points).
TEST_CASE("fit engine: a fold with fewer rows than its nuisances is that fold's failure", "[fit_engine]") {
  FreeFall data(Drops{{0.1}, {0.0, 0.1, 0.2, 0.3, 0.4, 0.5}});
  FitResult f;
  REQUIRE_NOTHROW(f = fit(data, "free fall", gravity_settings()));
  CHECK(f.parameter("gravity").estimate == Approx(g_true).epsilon(1e-6));
  REQUIRE(f.cross_validation);
  const std::string& why = f.cross_validation->failure;
  CAPTURE(why);
  CHECK(why.find("the fit without drop 0: 1 rows cannot determine 2 parameters") != std::string::npos);
  CHECK(why.find("bad_alloc") == std::string::npos);
}

// Drop 0 has two samples, drop 1 four (6 rows for 5 variables). Without drop 0, drop 1 fits and
// predicts drop 0 (2 rows for its 2 nuisances); without drop 1 the rest is drop 0 alone, 2 rows
// for p = 1 + 2 = 3 variables: fit() refuses it with a DataError, which is again that fold's
// failure. Data that cannot be fitted as a whole (drop 1 with three samples: 5 rows for 5
// variables) is still the caller's DataError.
TEST_CASE("fit engine: a fold whose rest cannot be fitted is that fold's failure, not the data's", "[fit_engine]") {
  FreeFall data(Drops{{0.1, 0.2}, {0.1, 0.2, 0.3, 0.4}});
  const FitResult f = fit(data, "free fall", gravity_settings());
  REQUIRE(f.cross_validation);
  CHECK(f.cross_validation->failure == "the fit without drop 1: 2 rows cannot determine 3 parameters");
  FreeFall too_small(Drops{{0.1, 0.2}, {0.1, 0.2, 0.3}});
  CHECK_THROWS_AS(fit(too_small, "free fall", gravity_settings()), DataError);
}

// The work bound (fit_engine.hpp, "Work"): a request is its fit, each cross-validation fold (one
// per drop) and each profile (20 refits a parameter), each at the kind's predicted cost of one
// fit. Three drops, cross-validated: 4 fits. 1e6 each (4e6) runs quietly; 1e7 for the fit alone
// reaches progress_fit_work (1e7) and reports each iteration; 2e7 cross-validated (8e7) exceeds
// max_predicted_fit_work (6e7) and is refused before any model run, naming the data and the folds.
TEST_CASE("fit engine: a request's predicted work bounds it, reports its progress, and Ctrl-C stops it", "[fit_engine]") {
  const Drops drops{{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3, 0.4}, {0.05, 0.15, 0.25}};
  std::vector<std::string> lines;
  FitSettings s = gravity_settings();
  s.progress = [&](const std::string& line) { lines.push_back(line); };

  FreeFall quiet(drops);
  quiet.predicted_units = 1e6;
  CHECK_FALSE(fit(quiet, "free-fall", s).failed);
  CHECK(lines.empty());

  FreeFall long_fit(drops);
  long_fit.predicted_units = 1e7;
  FitSettings alone = s;
  alone.cross_validate = false;
  CHECK(fit(long_fit, "free-fall", alone).parameters[0].estimate == Approx(g_true).epsilon(1e-8));
  REQUIRE_FALSE(lines.empty());
  CHECK(lines.front().rfind("iteration 1: chi-square ", 0) == 0);

  FreeFall too_long(drops);
  too_long.predicted_units = 2e7;
  try {
    (void)fit(too_long, "free-fall", s);
    FAIL("a request predicted at 8e7 ran");
  } catch (const DataError& e) {
    const std::string why = e.what();
    CHECK(why.find("free fall: the fit and its 3 cross-validation folds is predicted at about 8e+07") != std::string::npos);
  }

  const std::atomic<bool> cancel = true;
  FitSettings cancelled = gravity_settings();
  cancelled.cancel = &cancel;
  FreeFall any(drops);
  CHECK_THROWS_AS(fit(any, "free-fall", cancelled), FitCancelled);
}

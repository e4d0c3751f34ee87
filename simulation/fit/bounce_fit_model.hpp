#pragma once
// Internal to the bounce-recording fit (simulation/fit/bounce_fit.cpp; not installed): the model
// of each drop's impact times (bounce_fit.hpp, "Model"): the bounce sequence run_bounce_sequence
// follows from a first approach speed v0, for given values of the fitted options, cached.
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hertzdash::bounce_fit_detail {

/// One impact of a drop's model sequence.
struct ModelImpact {
  double onset_s, approach_mps, rebound_mps;  ///< onset from the first impact's [s]; speeds [m/s]
};

/// The model of every drop: the bounce sequence for (the law's values, v0), its impacts by gbs8 in
/// the regularising variables at rtol = atol = 1e-12 (restitution_model_solver), cached (the
/// Jacobian's columns of one drop's speed and of t0 reuse the centre's runs).
class BounceModel : public fit_detail::FitModel {
 public:
  BounceModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names);

  /// The first `count` impacts at (law, v0), or nullptr where the values leave the model's domain
  /// (the set-up refuses them, a run fails, the body comes to rest before impact count - 1).
  const std::vector<ModelImpact>* impacts(const std::vector<double>& law, double v0, int count);
  /// Why the last run outside the model's domain was (the refusal, or the sequence's end).
  const std::string& outside_domain() const { return outside_domain_; }

 private:
  std::map<std::vector<double>, std::optional<std::vector<ModelImpact>>> cache_;
  std::map<std::vector<double>, std::string> outside_;  ///< why each cached run outside the domain was
  std::string outside_domain_;
};

}  // namespace hertzdash::bounce_fit_detail

#pragma once
// Internal to the restitution-table fit (simulation/fit/restitution_fit.cpp; not installed): the
// model (restitution_fit.hpp, "Model"): a law's effective restitution of one impact at each
// speed, in the contact phase of `hertzdash restitution`, for given values of the fitted options.
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hertzdash::restitution_fit_detail {

/// The solver of the model's impacts: gbs8 in the regularising variables at rtol = atol = 1e-12.
SolverSettings restitution_model_solver();

/// The contact of one impact at `speed_mps` with the options `o`, as `hertzdash restitution`
/// runs it: resolve_setup with --impact-velocity, the contact phase (a rigid flat unless `rod-E`
/// is given). Throws InvalidParameter for options the set-up refuses.
DropTestSetup restitution_contact(const RunOptions& o, const PaperParameters& paper, double speed_mps);

class RestitutionModel : public fit_detail::FitModel {
 public:
  RestitutionModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names);

  /// e_effective at each of `speeds` (0 where the rod does not separate), or nothing where the
  /// values leave the model's domain (the set-up refuses them, a run fails).
  std::optional<std::vector<double>> e_at(const std::vector<double>& values, const std::vector<double>& speeds);


 private:
  ImpactSimulator simulator_;
};

}  // namespace hertzdash::restitution_fit_detail

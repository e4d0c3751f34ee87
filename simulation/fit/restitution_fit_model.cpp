// The model of a restitution-table fit (simulation/fit/restitution_fit_model.hpp): a law's
// e_effective at each speed, in the contact phase `hertzdash restitution` runs.
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"

#include "hertzdash/simulation/fit/restitution_fit.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/run/calibrate_restitution.hpp"

#include <map>
#include <stdexcept>

namespace hertzdash::restitution_fit_detail {

SolverSettings restitution_model_solver() {
  SolverSettings s;
  s.integrator = IntegratorKind::gbs8_regularized;
  s.rtol = 1e-12;
  s.atol = 1e-12;  // of the impact's scales
  return s;
}

}  // namespace hertzdash::restitution_fit_detail

namespace hertzdash {

void check_restitution_fit_options(const RunOptions& o) {
  const std::string table = "omitted with `restitution-table` (the table gives the impact speeds)";
  if (o.impact_velocity_mps) throw InvalidParameter("impact-velocity", format_value(*o.impact_velocity_mps), table);
  if (o.height_m) throw InvalidParameter("height", format_value(*o.height_m), table);
  if (o.gravity_mps2)
    throw InvalidParameter("gravity", format_value(*o.gravity_mps2),
                           "omitted with `restitution-table` (the contact phase has no gravity)");
  if (o.rod_model != "rigid")
    throw InvalidParameter("rod-model", o.rod_model,
                           "rigid with `restitution-table` (e is the contact phase's, as `hertzdash restitution` runs it)");
  if (o.rod_nu && !o.rod_E_Pa)
    throw InvalidParameter("rod-nu", format_value(*o.rod_nu),
                           "given only with `rod-E` with `restitution-table` (against its default rigid wall the "
                           "wall's Poisson ratio does not enter)");
  if (o.omega_n && is_iterated(parse_omega_n_variant(*o.omega_n)))
    throw InvalidParameter("omega-n", *o.omega_n,
                           "a closed-form variant with `restitution-table`: paper, impact-energy, rebound-energy or "
                           "as-printed (the iterated variants need hertzdash simulate)");
}

}  // namespace hertzdash

namespace hertzdash::restitution_fit_detail {

DropTestSetup restitution_contact(const RunOptions& o, const PaperParameters& paper, double speed_mps) {
  RunOptions at = o;
  at.impact_velocity_mps = speed_mps;
  DropTestSetup s = contact_phase_setup(resolve_setup(at, paper));
  if (o.rod_E_Pa) {  // the wall the user gave, not the rigid one (as `hertzdash restitution`)
    s.rod.E_Pa = *o.rod_E_Pa;
    validate(s);
  }
  return s;
}

RestitutionModel::RestitutionModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names)
    : FitModel(std::move(base), paper, std::move(names)), simulator_(restitution_model_solver()) {}

std::optional<std::vector<double>> RestitutionModel::e_at(const std::vector<double>& values,
                                                         const std::vector<double>& speeds) {
  const RunOptions o = options_at(values);
  std::map<double, double> by_speed;  // each distinct speed runs once
  std::vector<double> e;
  e.reserve(speeds.size());
  try {
    for (double v : speeds) {
      auto it = by_speed.find(v);
      if (it == by_speed.end()) {
        const DropTestSetup s = restitution_contact(o, *paper_, v);
        const ImpactSummary r = simulator_.run(s, base_.damping);
        ++runs_;
        integrator_used_ = to_string(r.integrator_used);
        it = by_speed.emplace(v, r.separated ? r.e_effective : 0.0).first;
      }
      e.push_back(it->second);
    }
  } catch (const InvalidParameter&) {
    return std::nullopt;
  } catch (const std::runtime_error&) {  // a run that failed its checks: outside the model's domain
    return std::nullopt;
  }
  return e;
}

}  // namespace hertzdash::restitution_fit_detail

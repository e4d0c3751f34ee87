// A contact as a discrete-element engine takes it (simulation/export/engine_contact.hpp).
#include "hertzdash/simulation/export/engine_contact.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/restitution.hpp"
#include "hertzdash/model/two_spheres.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hertzdash {

const char* to_string(EngineImpactKind k) {
  return k == EngineImpactKind::sphere_sphere ? "sphere-sphere" : "sphere-wall";
}

double EngineContact::density_kg_per_m3() const {
  return mass_kg / sphere_mass_kg(radius_m, 1.0);
}

double EngineContact::effective_modulus_Pa(EngineImpactKind k) const {
  return 1.0 / (compliance(sphere) + compliance(k == EngineImpactKind::sphere_sphere ? sphere : wall));
}

double EngineContact::reduced_mass_kg(EngineImpactKind k) const {
  const Sphere each{radius_m, mass_kg, sphere};
  return k == EngineImpactKind::sphere_sphere ? hertzdash::reduced_mass_kg(each, each) : mass_kg;
}

double EngineContact::reduced_radius_m(EngineImpactKind k) const {
  const Sphere each{radius_m, mass_kg, sphere};
  return k == EngineImpactKind::sphere_sphere ? hertzdash::reduced_radius_m(each, each) : radius_m;
}

DropTestSetup engine_impact_setup(const EngineContact& c, EngineImpactKind k) {
  DropTestSetup s{};
  s.mass_kg = c.reduced_mass_kg(k);
  s.ball_radius_m = c.reduced_radius_m(k);
  s.ball = c.sphere;
  s.ball_yield_stress_Pa = INFINITY;  // the engines' contact is elastic: no yield check
  s.rod = k == EngineImpactKind::sphere_sphere ? c.sphere : c.wall;
  // Clamped, tsuji-dem's input is the e (with tension) of the zeta whose clamped e is c.restitution.
  s.restitution = c.tension_clamped ? std::exp(-std::numbers::pi * std::tan(std::asin(zeta_from_clamped_restitution(c.restitution))))
                                    : c.restitution;
  s.no_tension = c.tension_clamped;
  s.height_m = 0;
  s.impact_velocity_mps = c.speed_mps;
  s.gravity_mps2 = 0;
  s.damping = c.damping;
  if (c.material_constant > 0) law_runs(c.law).set_material_constant(s.damping, c.material_constant);
  validate(s);
  return s;
}

namespace {

EngineImpactResult predict(ImpactSimulator& simulator, const DropTestSetup& s, const std::string& law) {
  const ImpactSummary r = simulator.run(s, law);
  return {r.e_effective, r.contact_time_s, r.peak_force_N};
}

void predict_impacts(EngineContact& c) {
  SolverSettings accurate;
  accurate.integrator = IntegratorKind::gbs8_regularized;
  accurate.rtol = 1e-10;
  accurate.atol = 1e-10;
  ImpactSimulator simulator(accurate);
  c.pair = predict(simulator, engine_impact_setup(c, EngineImpactKind::sphere_sphere), c.law);
  c.on_wall = predict(simulator, engine_impact_setup(c, EngineImpactKind::sphere_wall), c.law);
}

}  // namespace

EngineContact make_engine_contact(const DropTestSetup& setup, const std::string& law, bool tension_clamped) {
  if (tension_clamped && law != "tsuji-dem")
    throw std::invalid_argument("an engine's clamped contact is known for tsuji-dem alone, not " + law);
  // The clamped law's e falls to e^-2 as zeta -> 1 (clamped_restitution); below, it is overdamped.
  if (tension_clamped && !(setup.restitution > std::exp(-2.0)))
    throw InvalidParameter("restitution", format_value(setup.restitution),
                           fmt::format("above e^-2 = {:.4f} for an engine that clamps the force at zero (tsuji-dem "
                                       "clamped reaches no lower e while underdamped)",
                                       std::exp(-2.0)));
  EngineContact c;
  c.law = law;
  c.tension_clamped = tension_clamped;
  c.radius_m = setup.ball_radius_m;
  c.mass_kg = setup.mass_kg;
  c.sphere = setup.ball;
  c.wall = setup.rod;
  c.restitution = setup.restitution;
  c.speed_mps = approach_speed(setup);
  c.damping = setup.damping;
  if (const LawRuns& runs = law_runs(law); runs.calibrated_time_constant) {
    DropTestSetup pair = engine_impact_setup(c, EngineImpactKind::sphere_sphere);
    if (!runs.material_constant(pair.damping)) pair = runs.calibrated_time_constant(pair);
    c.material_constant = *runs.material_constant(pair.damping);
    c.calibration_speed_mps = setup.damping.reference_velocity_mps > 0 ? setup.damping.reference_velocity_mps : c.speed_mps;
  }
  predict_impacts(c);
  return c;
}

EngineContact at_speed(const EngineContact& c, double speed_mps) {
  EngineContact out = c;
  out.speed_mps = speed_mps;
  predict_impacts(out);
  return out;
}

}  // namespace hertzdash

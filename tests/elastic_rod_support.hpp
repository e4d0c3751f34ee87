#pragma once
// Set-ups of the elastic rod on the load cell for the tests: the paper's drop test of one rod
// with --rod-model elastic and overrides, resolved through the same option table as the CLI.
#include "hertzdash/model/elastic_drop_test.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

namespace hertzdash::test {

inline const PaperParameters& paper() {
  static const PaperParameters p = load_paper_parameters();
  return p;
}

/// The options of the elastic model of `rod` dropped from h [m] with N elements.
inline RunOptions elastic_options(const std::string& rod, double height_m, int elements) {
  RunOptions o;
  o.rod = rod;
  o.height_m = height_m;
  o.rod_model = "elastic";
  o.rod_elements = elements;
  return o;
}

/// The same options with the rigid model (the elastic-only options cleared).
inline RunOptions rigid_options(RunOptions o) {
  o.rod_model = "rigid";
  o.rod_elements.reset();
  o.rod_damping_ratio.reset();
  o.cell_stiffness_N_per_m.reset();
  o.cell_damping_ratio.reset();
  o.hemisphere_mass_kg.reset();
  o.accelerometer.reset();
  return o;
}

inline ImpactSummary run(const RunOptions& o, const SolverSettings& solver, std::vector<TraceSample>* trace = nullptr) {
  return ImpactSimulator(solver).run(resolve_setup(o, paper()), o.damping, trace);
}

/// Adaptive dopri5 tight enough that the differences the tests measure (>= 1e-6 relative)
/// stand far above the integration error (~1e-10).
inline SolverSettings tight_dopri5() {
  SolverSettings s;
  s.integrator = IntegratorKind::dopri5;
  s.rtol = 1e-11;
  s.atol = 1e-15;
  return s;
}

}  // namespace hertzdash::test

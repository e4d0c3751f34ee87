#pragma once
// The effective restitution of one impact at each of a table's speeds, as `hertzdash restitution
// --impact-velocity v --rtol 1e-12` computes it (run_restitution; CVODE, another integrator than
// the restitution-table fit's gbs8): the truth of the tests' SYNTHETIC restitution tables.
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <vector>

namespace hertzdash::test {

inline std::vector<double> restitution_at_speeds(RunOptions o, const std::vector<double>& speeds_mps) {
  const PaperParameters paper = load_paper_parameters();
  o.rtol = 1e-12;
  std::vector<double> e;
  for (double v : speeds_mps) {
    o.impact_velocity_mps = v;
    e.push_back(run_restitution(o, paper).e_effective);
  }
  return e;
}

}  // namespace hertzdash::test

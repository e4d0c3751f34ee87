#pragma once
// Chung and Ooi's test 4 as an oblique impact (data/external/chung-ooi-2011/README.md): the alumina
// sphere of parameters.csv's row test4 (R = 2.5 mm, E = 380 GPa, nu = 0.23, 4000 kg/m^3) on a rigid
// flat at 3.9 m/s, with the test's e = 0.98 and mu = 0.092 (declared here: not columns of that
// table), solid (kappa = 2/5), no initial spin; the curve files of the test and their error as
// Kratos's Chung_Ooi_class measures it. Shared by validation/oblique_impacts and
// tests/test_oblique_impact.cpp.
#include "hertzdash/model/two_spheres.hpp"
#include "hertzdash/simulation/run/oblique_impact.hpp"
#include "validation/common/chung_ooi_benchmark.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace hertzdash {

/// The test's coefficient of restitution and friction coefficient (Kratos's Materials4.json).
inline constexpr double chung_ooi_test4_restitution = 0.98, chung_ooi_test4_friction = 0.092;

/// parameters.csv's row test4.
inline const ChungOoiTest& chung_ooi_test4_bodies() { return chung_ooi_row("test4"); }

/// The test's impact at `angle_deg` with the normal law `law` (e = 0.98 where it reads one) and
/// the tangential model `model`, friction `mu` (the test's 0.092 unless given), to rtol 1e-11.
inline ObliqueImpactSpec chung_ooi_test4(const std::string& law, const std::string& model, double angle_deg,
                                         double mu = chung_ooi_test4_friction) {
  const ChungOoiTest& bodies = chung_ooi_test4_bodies();
  ObliqueImpactSpec s;
  s.setup = chung_ooi_setup(bodies);
  s.setup.restitution = chung_ooi_test4_restitution;
  s.law = law;
  s.tangential_model = model;
  s.friction = mu;
  s.incidence_angle_deg = angle_deg;
  s.speed_mps = bodies.relative_speed_mps;
  s.solver.rtol = 1e-11;
  s.solver.atol = 1e-13;
  return s;
}

/// One of the test's reference curves: its file, what it plots, the run's value of it and the
/// tolerance Kratos's test holds its DEM to (the L1 relative error below).
struct ChungOoiTest4Curve {
  const char* file;
  const char* quantity;
  double kratos_tolerance;
  double (*value)(const ObliqueImpactResult&);
};
inline constexpr ChungOoiTest4Curve chung_ooi_test4_curves[] = {
    {"test4_tangential_restitution.dat", "tangential_restitution", 0.016,
     [](const ObliqueImpactResult& r) { return r.tangential_restitution; }},
    {"test4_rebound_angular_velocity.dat", "rebound_angular_velocity_rad_per_s", 0.022,
     [](const ObliqueImpactResult& r) { return r.spin_after_rad_per_s; }},
    {"test4_rebound_angle.dat", "rebound_angle_deg", 0.025, [](const ObliqueImpactResult& r) { return r.rebound_angle_deg; }},
};

/// The L1 relative error sum |run - reference| / sum |reference| over a curve's digitised angles
/// (Kratos's Chung_Ooi_class), the law and model run at each.
inline double chung_ooi_test4_error(const ChungOoiTest4Curve& c, const std::string& law, const std::string& model) {
  KratosL1Error error;
  for (const auto& [angle, value] : read_two_columns(chung_ooi_data_dir() / c.file)) {
    const ObliqueImpactResult r = run_oblique_impact(chung_ooi_test4(law, model, angle));
    if (!r.separated) throw std::runtime_error(std::string("Chung and Ooi test 4: no separation at ") + std::to_string(angle) + " deg");
    error.add(c.value(r), value);
  }
  return error.value();
}

}  // namespace hertzdash

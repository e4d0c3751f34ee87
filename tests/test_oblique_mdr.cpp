// cattaneo-mindlin-mdr (model/oblique_contact_mdr.hpp): Coulomb's law at every point of the
// contact by the method of dimensionality reduction. Its standard checks (gross sliding, energy,
// the rigs) are the registered models' in tests/test_oblique_impact.cpp and test_oblique_rig.cpp;
// here, what only this model has: its cells' convergence, and its agreement with the textbook
// form of the method, integrated independently.
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/tangential/tangential_model.hpp"
#include "hertzdash/simulation/run/oblique_impact.hpp"
#include "validation/common/chung_ooi_tests_5_6.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace hertzdash;

namespace {

/// Chung and Ooi's test 5 (steel, e = 1, mu = 0.3, validation/common/chung_ooi_tests_5_6.hpp) at
/// x = V_st / (mu V_cn) under cattaneo-mindlin-mdr with `cells` cells: the contact point's slip
/// after over before, V_st' / V_st.
double test5_slip_ratio(double x, int cells) {
  const ChungOoiOblique& c = chung_ooi_oblique_curve("test5_steel_rebound_slip.dat");
  ObliqueImpactSpec s = chung_ooi_oblique_spec(c, x, "cattaneo-mindlin-mdr");
  s.contact_cells = cells;
  const ObliqueImpactResult r = run_oblique_impact(s);
  REQUIRE(r.separated);
  return chung_ooi_oblique_value(c, x, s, r) * r.normal_restitution / x;  // y = V_st'/(mu V_cn'), x = V_st/(mu V_cn)
}

/// Test 6 (aluminium alloy, e = 0.5, mu = 0.4) at x = 3.5 mu (1 + e) V_cn / V_st under the law `law`
/// and cattaneo-mindlin-mdr with `cells` cells: beta = -V_st' / V_st.
double test6_beta(double x, const char* law, int cells) {
  const ChungOoiOblique& c = chung_ooi_oblique_curve("test6_aluminium_slip_ratio.dat");
  ObliqueImpactSpec s = chung_ooi_oblique_spec(c, x, "cattaneo-mindlin-mdr");
  s.law = law;
  s.contact_cells = cells;
  const ObliqueImpactResult r = run_oblique_impact(s);
  REQUIRE(r.separated);
  return chung_ooi_oblique_value(c, x, s, r);
}

/// The same impact by MDR's textbook form (Popov and Hess 2015, ch. 3-4), integrated here
/// independently of the run: `springs` springs at xi_j = (j + 1/2) h on [0, 1.01 a_max], each of
/// normal stiffness 2 E* h and tangential 2 * 4 G* h (both halves of the line), deflected
/// w_j = x - xi_j^2 / R; each spring's tangential force moves with the slip while within
/// mu 2 E* h w_j and stays on that limit otherwise (projected after each step), and is 0 out of
/// contact. Velocity Verlet in t with `steps` steps over the Hertz contact time: the projection
/// makes it first order in h.
double textbook_mdr_slip_ratio(double x, int springs, int steps) {
  const ChungOoiOblique& c = chung_ooi_oblique_curve("test5_steel_rebound_slip.dat");
  const ObliqueImpactSpec s = chung_ooi_oblique_spec(c, x, "cattaneo-mindlin-mdr");
  const DropTestSetup& b = s.setup;
  const double R = b.ball_radius_m, m = b.mass_kg, K = hertz_stiffness(b), E = 3 * K / (4 * std::sqrt(R));
  const double G = tangential_shear_modulus_Pa(b.ball.E_Pa, b.ball.nu, b.rod.E_Pa, b.rod.nu);
  const double mu = s.friction, m_t = m * 0.4 / 1.4;
  const double v0 = chung_ooi_row(c.row).relative_speed_mps, s0 = x * mu * v0;
  const double X = undamped_hertz_max_deformation_m(K, m, v0), t_c = undamped_hertz_contact_time_factor() * X / v0;
  const double h = 1.01 * std::sqrt(R * X) / springs, dt = t_c / steps;
  std::vector<double> f(springs, 0.0);
  double gap = 0, vn = v0, slip = s0, Fn = 0, T = 0;
  for (int n = 0; n < 4 * steps && !(n > 0 && gap < 0); ++n) {
    vn -= 0.5 * dt * Fn / m;
    slip += 0.5 * dt * T / m_t;
    gap += dt * vn;
    const double ds = dt * slip;
    Fn = T = 0;
    for (int j = 0; j < springs; ++j) {
      const double xi = (j + 0.5) * h, w = gap - xi * xi / R;
      if (w <= 0) {
        f[j] = 0;
        continue;
      }
      const double limit = mu * 2 * E * h * w;
      f[j] = std::clamp(f[j] - 2 * 4 * G * h * ds, -limit, limit);
      Fn += 2 * E * h * w;
      T += f[j];
    }
    vn -= 0.5 * dt * Fn / m;
    slip += 0.5 * dt * T / m_t;
  }
  return slip / s0;
}

}  // namespace

TEST_CASE("cattaneo-mindlin-mdr: the contact's cells converge at second order", "[oblique][mdr]") {
  // Each cell carries one tangential force for its whole length, where the exact row carries a
  // displacement varying along it: the cell's error in the force it stores is O(h) over a length h
  // at the stick-slip boundary, and the boundary's O(h) cells' sum cancels to O(h^2) as in the
  // midpoint rule (the lengths and the normal shares W_i are exact integrals). Expected order 2,
  // at 25, 50, 100 and 200 cells, rtol 1e-10 (the time error far below the differences):
  //  - test 5's steel sphere at x = 1, undamped, where a slip annulus and a stuck centre share the
  //    contact;
  //  - test 6's spinning sphere at x = 25, nearly stuck throughout, under lee-herrmann, whose
  //    dashpot opens the cone at the first touch: a first cell put on that cone there (a force no
  //    spring had stored) cost one order, 0.9 to 1.0 observed.
  struct Case {
    const char* label;
    double (*value)(int cells);
  };
  const Case cases[] = {{"test 5 steel at x = 1, V_st'/V_st", [](int n) { return test5_slip_ratio(1.0, n); }},
                        {"test 6 aluminium at x = 25 under lee-herrmann, beta", [](int n) { return test6_beta(25.0, "lee-herrmann", n); }}};
  const int cells[] = {25, 50, 100, 200};
  for (const Case& k : cases) {
    double value[4];
    for (int i = 0; i < 4; ++i) value[i] = k.value(cells[i]);
    std::printf("cattaneo-mindlin-mdr, %s, against the cells\n%8s %14s %12s %8s\n", k.label, "cells", "value", "difference",
                "order");
    for (int i = 0; i < 4; ++i) {
      const double d = i > 0 ? std::abs(value[i] - value[i - 1]) : NAN;
      const double order = i > 1 ? std::log2(std::abs(value[i - 1] - value[i - 2]) / d) : NAN;
      std::printf("%8d %14.8f %12.3e %8.2f\n", cells[i], value[i], d, order);
      CAPTURE(k.label, cells[i]);
      if (i > 1) CHECK(order == Approx(2).margin(0.3));
    }
  }
}

TEST_CASE("cattaneo-mindlin-mdr: the cells agree with the method's textbook springs", "[oblique][mdr]") {
  // The textbook MDR (springs at points, a first-order projected Verlet, textbook_mdr_slip_ratio)
  // and the run (cells with exact lengths and shares, adaptive Dormand-Prince through every switch)
  // share only the theory. The textbook scheme's error is estimated by halving its step and its
  // spacing: at 400 springs and 20000 steps against 800 and 40000 it is E; the run's, at 200 cells,
  // by Richardson from 100 cells at the order the test above asserts, E_c = |r200 - r100| / 3. The
  // two must agree to 3 (E + E_c). Where the contact sticks in its centre (x = 0.5), slips over an
  // annulus that reverses the slip (x = 2) and nearly slides throughout (x = 5).
  for (const double x : {0.5, 2.0, 5.0}) {
    const double run = test5_slip_ratio(x, 200), E_c = std::abs(run - test5_slip_ratio(x, 100)) / 3;
    const double coarse = textbook_mdr_slip_ratio(x, 400, 20000), fine = textbook_mdr_slip_ratio(x, 800, 40000);
    const double E = std::abs(fine - coarse);
    std::printf("x = %.1f: cells %.7f (error estimate %.1e), textbook springs %.7f (error estimate %.1e)\n", x, run, E_c,
                fine, E);
    CAPTURE(x, run, fine, E, E_c);
    CHECK(std::abs(run - fine) < 3 * (E + E_c));
  }
}

TEST_CASE("cattaneo-mindlin-mdr: the resolved contact never does positive work on the sphere", "[oblique][mdr]") {
  // Each cell stores U_i = T_i^2/(2 k_i) >= 0 while it sticks; sliding on its limit dissipates
  // mu |p_i| |slip|; the part of a cell the shrinking edge leaves takes its share of the force and of
  // U_i out of the contact, returning nothing. So W = int T s dt = -(dissipated) - (stored at the
  // end, 0 once every cell has left) <= 0, whatever the normal law does. Checked on test 6's set-up
  // (e = 0.5, a spinning sphere: sticking, slipping and reversing), 48 abscissae over its beta
  // curve, under tsuji-dem and under the two laws whose dashpot acts at zero overlap, so that the
  // cone is open at the first touch (lee-herrmann, kelvin-voigt: a cell entering on that cone
  // would have been handed mu F_n unstored), W <= 0 to the work's integration error (1e-9 of the
  // sphere's spin energy; the runs' W is below -1e-4 of it).
  const ChungOoiOblique& c = chung_ooi_oblique_curve("test6_aluminium_slip_ratio.dat");
  for (const char* law : {"tsuji-dem", "lee-herrmann", "kelvin-voigt"})
    for (int i = 0; i < 48; ++i) {
      const double x = 0.17 * std::pow(25.0 / 0.17, i / 47.0);
      ObliqueImpactSpec s = chung_ooi_oblique_spec(c, x, "cattaneo-mindlin-mdr");
      s.law = law;
      const ObliqueImpactResult r = run_oblique_impact(s);
      const double spin_energy_J = 0.5 * 0.4 * s.setup.mass_kg * std::pow(s.spin_rad_per_s * s.setup.ball_radius_m, 2);
      CAPTURE(law, x, r.tangential_work_J, spin_energy_J);
      CHECK(r.tangential_work_J <= 1e-9 * spin_energy_J);
    }
}

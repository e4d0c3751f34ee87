// Chung & Ooi (2011) DEM benchmark tests 1, 2 and 3 (data/external/chung-ooi-2011/): the set-ups
// read from parameters.csv, the undamped Hertz impact through the simulator against the closed
// forms, the textbook numbers, the digitised curves against the closed-form curves, and test 3's
// restitution from 0 to 1 against each law's exact restitution.
//
// Closed forms (model/hertz.hpp), for m* x'' = -(4/3) E* sqrt(R*) x^{3/2}, x'(0) = v:
//   x_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5},  F_max = (4/3) E* sqrt(R*) x_max^{3/2},
//   t_c   = (4/5) B(2/5, 1/2) x_max / v = 2.86827 (m*^2 / (R* E*^2 v))^{1/5}.
#include "hunt_crossley_restitution.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/damping/registered_law_types.hpp"
#include "hertzdash/model/restitution.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/undamped_hertz_trajectory.hpp"
#include "validation/common/chung_ooi_benchmark.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <unistd.h>

using namespace hertzdash;
using hertzdash::test::hunt_crossley_form_restitution;

namespace {

UndampedHertzImpact closed_form(const DropTestSetup& s) {
  return undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, *s.impact_velocity_mps);
}

// The digitisation uncertainty data/external/chung-ooi-2011/README.md states: roughly 1 % of
// full scale, in both columns.
constexpr double digitisation_uncertainty_pct = 1.0;

}  // namespace

TEST_CASE("Chung & Ooi: parameters.csv holds the benchmark's bodies and their one-degree-of-freedom reduction",
          "[chung-ooi]") {
  // m = rho (4/3) pi R^3. Test 1, two identical spheres: m* = m/2, R* = R/2, and both deform, so
  // 1/E* = 2 (1 - nu^2)/E: E* = 48e9 / (2 * 0.96) = 25 GPa. Test 2, a rigid flat: m* = m, R* = R,
  // E* = E / (1 - nu^2) = 70e9 / 0.91 = 76.923 GPa. The stored effective values carry 16 digits.
  for (const auto& [name, identical] : {std::pair{"test1", true}, std::pair{"test2", false}}) {
    INFO(name);
    const ChungOoiTest t = chung_ooi_row(name);
    const double m = t.density_kgpm3 * 4.0 / 3.0 * std::numbers::pi * std::pow(t.radius_m, 3);
    CHECK(t.rigid_flat == !identical);
    CHECK(t.effective_mass_kg == Approx(identical ? m / 2 : m).epsilon(1e-14));
    CHECK(t.effective_radius_m == Approx(identical ? t.radius_m / 2 : t.radius_m).epsilon(1e-14));
    const DropTestSetup s = chung_ooi_setup(t);
    const double E_star = 3 * hertz_stiffness(s) / (4 * std::sqrt(t.effective_radius_m));
    CHECK(E_star == Approx(identical ? 25e9 : 70e9 / 0.91).epsilon(1e-14));
    CHECK(s.gravity_mps2 == 0);
    CHECK(*s.impact_velocity_mps == t.relative_speed_mps);
  }
  CHECK(chung_ooi_row("test1").relative_speed_mps == 20.0);
  CHECK(chung_ooi_row("test2").relative_speed_mps == 0.2);
  // Test 3, alumina on a rigid flat (the Kratos test's Materials31.json, test3DEM.mdpa):
  // m = 4000 (4/3) pi (2.5e-3)^3 = 2.6179939e-4 kg, E* = 380e9 / (1 - 0.23^2) = 401.2248 GPa.
  const ChungOoiTest t3 = chung_ooi_row("test3");
  CHECK(t3.rigid_flat);
  CHECK(t3.effective_mass_kg == Approx(2.6179939e-4).epsilon(1e-7));
  CHECK(t3.effective_radius_m == 2.5e-3);
  CHECK(t3.relative_speed_mps == 3.9);
  const DropTestSetup s3 = chung_ooi_setup(t3);
  CHECK(3 * hertz_stiffness(s3) / (4 * std::sqrt(2.5e-3)) == Approx(380e9 / (1 - 0.23 * 0.23)).epsilon(1e-14));
  // Test 4 throws the same alumina sphere at the same resultant speed (Kratos's Materials4.json).
  const ChungOoiTest t4 = chung_ooi_row("test4");
  CHECK(t4.sphere.E_Pa == t3.sphere.E_Pa);
  CHECK(t4.sphere.nu == t3.sphere.nu);
  CHECK(t4.effective_mass_kg == t3.effective_mass_kg);
  CHECK(t4.radius_m == t3.radius_m);
  CHECK(t4.relative_speed_mps == t3.relative_speed_mps);
}

TEST_CASE("Chung & Ooi: the textbook numbers of tests 1 and 2 from the closed forms", "[chung-ooi]") {
  // Test 1: m* = 2800 (4/3) pi (0.01)^3 / 2 = 5.86431e-3 kg, R* = 0.005 m, E* = 25 GPa, v = 20 m/s:
  //   x_max = (15 * 5.86431e-3 * 400 / (16 * 25e9 * 0.0707107))^{2/5} = (1.24401e-9)^{2/5} = 274.113 um,
  //   F_max = (4/3) 25e9 * 0.0707107 * (2.74113e-4)^{3/2} = 2.35702e9 * 4.53834e-6 = 10.6969 kN,
  //   t_c   = 2.94328 * 274.113e-6 / 20 = 40.3395 us; with Chung & Ooi's constant 2.87,
  //           2.87 ((5.86431e-3)^2 / (0.005 * 6.25e20 * 20))^{1/5} = 2.87 * 1.40641e-5 = 40.3638 us.
  // Test 2: m* = 2699 (4/3) pi (0.1)^3 = 11.3055 kg, R* = 0.1 m, E* = 76.9231 GPa, v = 0.2 m/s:
  //   x_max = (15 * 11.3055 * 0.04 / (16 * 76.9231e9 * 0.316228))^{2/5} = (1.74287e-11)^{2/5} = 49.7172 um,
  //   F_max = (4/3) 76.9231e9 * 0.316228 * (4.97172e-5)^{3/2} = 11.3699 kN,
  //   t_c   = 2.94328 * 49.7172e-6 / 0.2 = 731.657 us; with 2.87: 732.099 us.
  // Each hand value is rounded to 6 digits: relative tolerance 1e-5. The constant 2.87 is the exact
  // (4/5) B(2/5, 1/2) (15/16)^{2/5} = 2.868266 rounded up, 6.05e-4 too large, in both tests.
  struct Expected {
    const char* name;
    double x_max_m, peak_force_N, contact_time_s, contact_time_287_s;
  };
  for (const Expected& e : {Expected{"test1", 274.113e-6, 10.6969e3, 40.3395e-6, 40.3638e-6},
                            Expected{"test2", 49.7172e-6, 11.3699e3, 731.657e-6, 732.099e-6}}) {
    INFO(e.name);
    const ChungOoiTest t = chung_ooi_row(e.name);
    const DropTestSetup s = chung_ooi_setup(t);
    const UndampedHertzImpact u = closed_form(s);
    CHECK(u.max_deformation_m == Approx(e.x_max_m).epsilon(1e-5));
    CHECK(u.peak_force_N == Approx(e.peak_force_N).epsilon(1e-5));
    CHECK(u.contact_time_s == Approx(e.contact_time_s).epsilon(1e-5));
    const double E_star = 3 * u.peak_force_N / (4 * std::sqrt(t.effective_radius_m) * std::pow(u.max_deformation_m, 1.5));
    const double m = t.effective_mass_kg, R = t.effective_radius_m, v = t.relative_speed_mps;
    const double tc_287 = 2.87 * std::pow(m * m / (R * E_star * E_star * v), 0.2);
    CHECK(tc_287 == Approx(e.contact_time_287_s).epsilon(1e-5));
    CHECK(tc_287 / u.contact_time_s - 1 == Approx(6.05e-4).epsilon(1e-3));
    // The energy form of x_max: (15 m v^2 / (16 E* sqrt(R)))^{2/5}.
    CHECK(u.max_deformation_m == Approx(std::pow(15 * m * v * v / (16 * E_star * std::sqrt(R)), 0.4)).epsilon(1e-14));
  }
}

TEST_CASE("Chung & Ooi: both tests through the simulator meet the closed forms to 1e-6", "[chung-ooi]") {
  // CVODE keeps each step's local error below rtol |y| + atol_i, so after N steps the global
  // relative error is at most about N rtol (tests/test_undamped_hertz_closed_form.cpp); events
  // are located to near roundoff. At rtol 1e-10 with N ~ 100 steps that is ~1e-8; the issue asks
  // for 1e-6, and both bounds are checked. The paper's law at e = 1 has zeta = 0, so its force is
  // the Hertz force and its run the same ODE: it differs from "none" only by roundoff, bounded by
  // the same N rtol.
  for (const char* name : {"test1", "test2"}) {
    INFO(name);
    const DropTestSetup s = chung_ooi_setup(chung_ooi_row(name));
    const UndampedHertzImpact u = closed_form(s);
    SolverSettings solver;
    solver.rtol = 1e-10;
    solver.atol = 1e-10;  // of each component's scale, X = x_max and v0
    ImpactSimulator simulator(solver);
    const ImpactSummary r = simulator.run(s, "none");
    REQUIRE(r.separated);
    const double bound = std::min(1e-6, static_cast<double>(r.work.steps) * solver.rtol);
    INFO(r.work.steps << " steps, bound " << bound);
    CHECK(std::abs(r.peak_force_N / u.peak_force_N - 1) < bound);
    CHECK(std::abs(r.max_deformation_m / u.max_deformation_m - 1) < bound);
    CHECK(std::abs(r.contact_time_s / u.contact_time_s - 1) < bound);
    CHECK(std::abs(r.e_effective - 1) < bound);
    const ImpactSummary paper = simulator.run(s, "hongo");
    CHECK(std::abs(paper.peak_force_N / r.peak_force_N - 1) < bound);
    CHECK(std::abs(paper.contact_time_s / r.contact_time_s - 1) < bound);
    CHECK(std::abs(paper.e_effective - 1) < bound);
  }
}

TEST_CASE("Chung & Ooi: the digitised curves lie within their digitisation uncertainty of the Hertz curves",
          "[chung-ooi]") {
  // The README: ~1 % of full scale in both columns. Full scale is taken as the closed-form peak of
  // each axis (x_max or t_c, F_max), the least the paper's axes can span, so 1 % of it is the
  // strictest reading. A point is within the uncertainty when it can be moved onto the curve by at
  // most 1 % of full scale in each column: curve_deviation's distance <= 1. Computed first: the
  // largest distance over the 80 points is 0.56 % (test 2, force against overlap).
  // The vertical deviation alone is not bounded by 1 %: an abscissa error of u x_full moves the
  // force by |dF/da| u x_full, so, to first order, |dF| <= u (F_full + |dF/da| a_full). On the
  // force-overlap curves dF/dx = (3/2) F / x, which reaches 1.5 F_max / x_max at the peak: the
  // bound grows to 2.5 %. Computed first: 3 points of test 2's force-overlap curve lie 1.1-1.3 %
  // below it vertically (all within the first-order bound), all others within 1 %.
  const std::filesystem::path dir = chung_ooi_data_dir();
  int total = 0, vertical_over = 0;
  for (const char* name : {"test1", "test2"}) {
    const DropTestSetup s = chung_ooi_setup(chung_ooi_row(name));
    const UndampedHertzImpact u = closed_form(s);
    const double K = hertz_stiffness(s), m = s.mass_kg, v = *s.impact_velocity_mps;
    auto by_overlap = [K](double x) { return x <= 0 ? 0.0 : K * std::pow(x, 1.5); };
    auto by_time = [&](double t) {
      return t <= 0 || t >= u.contact_time_s ? 0.0 : by_overlap(undamped_hertz_state_at(K, m, v, t).x_m);
    };
    for (const bool overlap : {true, false}) {
      const std::string file = std::string(name) + (overlap ? "_force_displacement.dat" : "_force_time.dat");
      INFO(file);
      const std::vector<CurvePoint> points = read_digitised_curve(dir / file);
      const double a_full = overlap ? u.max_deformation_m : u.contact_time_s;
      const std::function<double(double)> model = overlap ? std::function<double(double)>(by_overlap) : by_time;
      const CurveDeviation d =
          curve_deviation(points, model, 0.0, a_full, a_full, u.peak_force_N, digitisation_uncertainty_pct);
      CHECK(d.max_distance_pct <= digitisation_uncertainty_pct);
      for (std::size_t i = 0; i < points.size(); ++i) {
        // The slope at the point: dF/dx = 1.5 F / x on the force-overlap curve; by a central
        // difference of 1e-4 of full scale on the force-time curve.
        const double a = points[i].abscissa, h = 1e-4 * a_full;
        const double slope = overlap ? (a > 0 ? 1.5 * by_overlap(a) / a : 0.0) : (model(a + h) - model(a - h)) / (2 * h);
        const double bound = digitisation_uncertainty_pct * (1 + std::abs(slope) * a_full / u.peak_force_N);
        INFO("point " << i);
        CHECK(std::abs(d.vertical_pct[i]) <= bound);
      }
      total += d.points;
      vertical_over += d.vertical_over;
    }
  }
  CHECK(total == 15 + 24 + 16 + 25);
  CHECK(vertical_over == 3);  // reported in the article (validation/chung_ooi), not hidden
}

TEST_CASE("Chung & Ooi: the curve reader and the deviation measure", "[chung-ooi]") {
  // The files hold um or us against kN: the first force-time point of test 2 is
  // (0.9661857724141782 us, -0.000027293383400461835 kN).
  const std::vector<CurvePoint> t2 = read_digitised_curve(chung_ooi_data_dir() / "test2_force_time.dat");
  CHECK(t2.front().abscissa == Approx(0.9661857724141782e-6).epsilon(1e-15));
  CHECK(t2.front().force_N == Approx(-0.027293383400461835).epsilon(1e-15));

  // F = a^2 on [0, 1], full scale 1 and 1. A point on the curve is 0 away; (0.5, 0.25 + 0.004) is
  // 0.4 % above it and nearer than that to it; (0.505, 0.25) is 0.5025 % below it, but the curve
  // passes within max(|da|, |dF|) of it where 0.505 - a = a^2 - 0.25, a = (-1 + sqrt(4.02)) / 2
  // = 0.50250: 0.25 %. Sampling the curve every 5e-5 moves a distance by at most that times the
  // distance's slope along the curve (<= 1 here): 5e-3 %.
  auto square = [](double a) { return a * a; };
  const CurveDeviation d = curve_deviation({{0.3, 0.09}, {0.5, 0.254}, {0.505, 0.25}}, square, 0, 1, 1, 1, 0.45);
  CHECK(d.vertical_pct[0] == Approx(0).margin(1e-12));
  CHECK(d.distance_pct[0] == Approx(0).margin(5e-3));
  CHECK(d.vertical_pct[1] == Approx(0.4).epsilon(1e-9));
  CHECK(d.distance_pct[1] <= 0.4);
  CHECK(d.vertical_pct[2] == Approx(-100 * (0.505 * 0.505 - 0.25)).epsilon(1e-9));
  CHECK(d.distance_pct[2] == Approx(100 * (0.505 - (-1 + std::sqrt(1 + 4 * 0.755)) / 2)).margin(5e-3));
  CHECK(d.vertical_over == 1);
  CHECK(d.distance_over == 0);

  const std::filesystem::path bad =
      std::filesystem::temp_directory_path() / ("hertzdash_bad_curve_" + std::to_string(::getpid()) + ".dat");
  std::ofstream(bad) << "1 2\n3 4 5\n";
  CHECK_THROWS_WITH(read_digitised_curve(bad), bad.string() + ":2: expected two numbers, got 3: '3 4 5'");
  // Numbers are decimal and within a double, refused at their line and column (operator>> said
  // only "expected two numbers" for both, with no column or reason).
  std::ofstream(bad) << "1 2\n3  1e400\n";
  CHECK_THROWS_WITH(read_digitised_curve(bad),
                    Catch::StartsWith(bad.string() + ":2:4: '1e400' is out of range of double"));
  std::ofstream(bad) << "1 2\n\t0x10 4\n";
  CHECK_THROWS_WITH(read_digitised_curve(bad), Catch::StartsWith(bad.string() + ":2:2: '0x10' is not a decimal number"));
  std::filesystem::remove(bad);
}

TEST_CASE("Chung & Ooi: a corrupted parameters.csv is refused at the value's line and column with its range",
          "[chung-ooi]") {
  // A copy of the directory with one value changed. Before, each was read as it was: a Poisson
  // ratio of 0.5 (E* infinite), a negative density, an effective mass that is not the spheres'.
  namespace fs = std::filesystem;
  const fs::path copy = fs::temp_directory_path() / ("hertzdash_chung_ooi_" + std::to_string(::getpid()));
  const fs::path original = chung_ooi_data_dir() / "parameters.csv";
  std::ifstream in(original);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string row1 = "test1,elastic normal impact of two identical glass spheres,";
  const std::size_t at = text.find(row1);
  REQUIRE(at != std::string::npos);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  const std::size_t col_nu = row1.size() + std::string("48e9,").size() + 1, col_density = col_nu + std::string("0.20,").size();
  const std::size_t col_mass = text.substr(at).find("0.005864306286700948") + 1;
  const struct {
    std::string from, to, expected;
  } cases[] = {
      {row1 + "48e9,0.20,", row1 + "48e9,0.5,",
       fmt::format(":{}:{}: column 'nu': 0.5 is not in (-1, 0.5)", line, col_nu)},
      {row1 + "48e9,0.20,2800", row1 + "48e9,0.20,-2800",
       fmt::format(":{}:{}: column 'density_kgpm3': -2800 is not > 0", line, col_density)},
      {row1 + "48e9,", row1 + "0,", fmt::format(":{}:{}: column 'E_Pa': 0 is not > 0", line, row1.size() + 1)},
      // m* = (2800 (4/3) pi 0.01^3) / 2 = 0.0058643062867009...
      {"0.005864306286700948", "0.0058",
       fmt::format(":{}:{}: column 'effective_mass_kg': 0.0058 is not 0.0058643062867009", line, col_mass)},
  };
  for (const auto& c : cases) {
    INFO(c.to);
    fs::remove_all(copy);
    fs::create_directories(copy);
    std::string changed = text;
    changed.replace(changed.find(c.from), c.from.size(), c.to);
    std::ofstream(copy / "parameters.csv") << changed;
    CHECK_THROWS_WITH(load_chung_ooi_tests(copy), Catch::StartsWith((copy / "parameters.csv").string() + c.expected));
  }
  fs::remove_all(copy);
}

TEST_CASE("Chung & Ooi test 3: the laws that invert their own restitution pass its 1e-3, the clamp and the "
          "near-elastic laws cannot",
          "[chung-ooi]") {
  // Test 3 asks rebound speed / 3.9 m/s = input e at e = 0, 0.2, ..., 1 within 1e-3 (the Kratos
  // test's delta); the suite takes e in (0, 1], so e = 0 is approached at 0.001. Each law's
  // expected e_eff is derived in tests/test_damping_law_restitution.cpp and depends on e alone:
  //  - kelvin-voigt and tsuji-dem, tension allowed: e_eff = e (the linear oscillator's exact
  //    zeta, and its image under z = x^{5/4}); kuwabara-kono and lee-herrmann: e_eff = e either
  //    way (calibrated at the impact speed). All four pass.
  //  - kelvin-voigt clamped: e_eff = exp(-(zeta/s) theta_F), theta_F = pi - atan2(2 zeta s,
  //    1 - 2 zeta^2) (model/restitution.hpp clamped_restitution). At e = 0.2, zeta = 0.4559,
  //    theta_F = 2.195, e_eff = 0.325: it misses test 3 by 0.125.
  //  - hunt-crossley: e_eff = (1 + W0(-(1 + a) e^{-(1 + a)}))/a with a = chi v0 = 1.5 (1 - e).
  //    As e -> 0, a -> 1.5 and e_eff -> 0.488: the law cannot take away more than about half
  //    the impact speed, whatever e it is given.
  // CVODE at rtol 1e-10: e_eff to ~1e-8 (the bound 1e-7 of the restitution tests).
  constexpr double solver_bound = 1e-7, kratos_delta = 1e-3;
  const DropTestSetup base = chung_ooi_setup(chung_ooi_row("test3"));
  SolverSettings solver;
  solver.rtol = 1e-10;
  solver.atol = 1e-10;
  ImpactSimulator simulator(solver);
  auto e_eff = [&](std::string_view law, double e, bool clamped) {
    DropTestSetup s = base;
    s.restitution = e;
    s.no_tension = clamped;
    const ImpactSummary r = simulator.run(s, law);
    REQUIRE(r.separated);
    return r.e_effective;
  };
  for (const double e : {0.2, 0.4, 0.6, 0.8, 1.0}) {
    INFO("e = " << e);
    for (const auto& [law, clamped] : {std::pair{"kelvin-voigt", false}, std::pair{"tsuji-dem", false},
                                       std::pair{"kuwabara-kono", false}, std::pair{"kuwabara-kono", true},
                                       std::pair{"lee-herrmann", false}, std::pair{"lee-herrmann", true}}) {
      INFO(law << (clamped ? ", clamped" : ", tension allowed"));
      const double d = std::abs(e_eff(law, e, clamped) - e);
      CHECK(d < solver_bound);
      CHECK(d <= kratos_delta);
    }
    const double zeta = zeta_from_restitution(e, ZetaForm::exact);
    const double clamped = e_eff("kelvin-voigt", e, true);
    CHECK(std::abs(clamped - clamped_restitution(zeta)) < solver_bound);
    if (e < 1) CHECK(clamped - e > kratos_delta);
    CHECK(std::abs(e_eff("hunt-crossley", e, false) - hunt_crossley_form_restitution(HuntCrossley::chi_v0(e))) <
          solver_bound);
  }
  CHECK(std::abs(e_eff("kelvin-voigt", 0.2, true) - 0.325) < 5e-4);
  const double floor = hunt_crossley_form_restitution(1.5);
  CHECK(floor == Approx(0.488).margin(5e-4));
  CHECK(std::abs(e_eff("hunt-crossley", 1e-3, false) - hunt_crossley_form_restitution(HuntCrossley::chi_v0(1e-3))) <
        solver_bound);
  CHECK(e_eff("hunt-crossley", 1e-3, false) > floor - 1e-3);
}

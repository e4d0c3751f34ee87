// Chung and Ooi's tests 5, 6 and 8 (validation/common/chung_ooi_tests_5_6.hpp; the curves and where
// their set-ups come from: data/external/chung-ooi-2011/README.md), every registered tangential
// model, on the curves' gross-sliding branches: the closed forms and Kratos's tolerances.
//
// The sticking branches depend on the tangential model and are compared, not asserted, in
// validation/chung_ooi_oblique (none of the models here reproduces them).
#include "hertzdash/model/tangential/registry.hpp"
#include "validation/common/chung_ooi_tests_5_6.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace hertzdash;

TEST_CASE("Chung and Ooi tests 5 and 6: the set-ups are parameters.csv's rows", "[chung-ooi][oblique]") {
  // Test 5's sphere has radius 0.01 mm, test 6's 0.1 m; both strike a rigid flat, test 5 at a
  // normal speed of 5 m/s, test 6 at 0.2 m/s (README.md: Kratos's and LIGGGHTS-PFM's inputs).
  for (const char* row : {"test5-steel", "test5-polyethylene"}) {
    const ChungOoiTest t = chung_ooi_row(row);
    CHECK(t.rigid_flat);
    CHECK(t.radius_m == 1e-5);
    CHECK(t.relative_speed_mps == 5);
  }
  for (const char* row : {"test6-aluminium", "test6-nylon"}) {
    const ChungOoiTest t = chung_ooi_row(row);
    CHECK(t.rigid_flat);
    CHECK(t.radius_m == 0.1);
    CHECK(t.relative_speed_mps == 0.2);
  }
  CHECK(chung_ooi_row("test5-steel").sphere.nu == 0.30);
  CHECK(chung_ooi_row("test6-nylon").sphere.nu == 0.40);
}

TEST_CASE("Chung and Ooi tests 5 and 6: gross sliding's branch within Kratos's tolerances, every tangential model",
          "[chung-ooi][oblique]") {
  // Where the sphere slides throughout, the tangential impulse is mu times the normal one, m V_cn
  // (1 + e), so the slip falls by (1 + 1/kappa) mu (1 + e) V_cn and the spin changes by
  // -mu (1 + e) V_cn / (kappa R) (the header's closed forms): test 5 (e = 1) x - 7 and -5 for x >= 7,
  // test 6 (e = 0.5) beta = x - 1 for x < 1 and (t - 2.1) / 0.5 for t > 2.1.
  //  - Test 5 is undamped: the run meets the closed form to its tolerance (rtol 1e-10; 1e-7).
  //  - Test 6 runs tsuji-dem, which pulls in tension at the end of the contact, where the cone is
  //    closed, and whose dashpot opens the cone faster than the spring loads at onset
  //    (validation/oblique_normal_law): the run departs from the closed form by up to a few
  //    hundredths, so it is held to Kratos's test instead.
  // Kratos's test compares its DEM with the digitised sliding points by the relative L1 error
  // sum |run - reference| / sum |reference| (DEM_benchmarks_class.py: test 5 passes below 2 %, test
  // 6 below 5 %: it checks 3 % after setting every error below 5 % to 0). Here the runs are at the
  // digitised abscissae, on every point of the branch; the test-6 errors are 1.6 to 4.9 % (the linear
  // spring's the largest), from tsuji-dem's departure and the digitisation (1 % of full scale).
  for (const ChungOoiOblique& c : chung_ooi_oblique_curves)
    for (const TangentialModelInfo* model : registered_tangential_models) {
      KratosL1Error error;
      int points = 0;
      for (const auto& [x, y] : read_two_columns(chung_ooi_data_dir() / c.file)) {
        if (!chung_ooi_oblique_gross_sliding(c, x)) continue;
        const ObliqueImpactSpec s = chung_ooi_oblique_spec(c, x, std::string(model->name));
        const ObliqueImpactResult r = run_oblique_impact(s);
        REQUIRE(r.separated);
        const double run = chung_ooi_oblique_value(c, x, s, r);
        CAPTURE(c.file, model->name, x, y, run);
        if (c.test == 5) CHECK(run == Approx(chung_ooi_oblique_sliding_value(c, x)).margin(1e-7));
        error.add(run, y);
        ++points;
      }
      CAPTURE(c.file, model->name, points);
      CHECK(points >= 2);
      CHECK(error.value() < c.kratos_tolerance);
    }
}

TEST_CASE("Chung and Ooi test 8 as Kratos runs it: the sliding points within its 10 %, every tangential model",
          "[chung-ooi][oblique]") {
  // Test 8 is test 6 against a sphere instead of a flat. Its cases A and B are defined in no source
  // at hand; Kratos's benchmark 8 runs one set-up (chung_ooi_test8_spec: a sphere five times larger,
  // 1000 times denser and stiffer, so near-rigid and near-immovable) and compares it with case A's
  // curves. Where the sphere slides throughout the pair's slip falls by (1/m* + R1^2/I1 + R2^2/I2)
  // mu P_n: for m2/m1 = 1.25e5 that is test 6's 3.5 mu (1 + e) V_cn to 1e-5, so the sliding branch is
  // test 6's closed form again (beta = x - 1 below x = 1; (t - 2.1)/0.5 above t = 2.1). Kratos's
  // check (DEM_benchmarks_class.py, Benchmark8, commit 04d87618): the relative L1 error of the first
  // six beta points (x = 0.19 to 1.21) and of four recoil-tangent points (t = 2.14 to 5.66) below
  // 10 %. The runs are at the digitised abscissae.
  struct Check {
    const char* file;   ///< the case-A curve
    const char* test6;  ///< test 6's curve of the same axes (its spec and value)
    int first, count;   ///< the rows Kratos compares
  };
  for (const Check& k : {Check{"test8_case_a_slip_ratio.dat", "test6_aluminium_slip_ratio.dat", 0, 6},
                         Check{"test8_case_a_recoil_tangent.dat", "test6_aluminium_recoil_tangent.dat", 12, 4}}) {
    const auto points = read_two_columns(chung_ooi_data_dir() / k.file);
    REQUIRE(points.size() == 17);
    const ChungOoiOblique& c = chung_ooi_oblique_curve(k.test6);
    for (const TangentialModelInfo* model : registered_tangential_models) {
      KratosL1Error error;
      for (int i = k.first; i < k.first + k.count; ++i) {
        const auto [x, y] = points[static_cast<std::size_t>(i)];
        const ObliqueImpactSpec s = chung_ooi_test8_spec(c, x, std::string(model->name));
        const ObliqueImpactResult r = run_oblique_impact(s);
        REQUIRE(r.separated);
        const double run = chung_ooi_oblique_value(c, x, s, r);
        CAPTURE(k.file, model->name, x, y, run);
        error.add(run, y);
      }
      CAPTURE(k.file, model->name, error.value());
      std::printf("Chung and Ooi test 8, %s, %s: L1 relative error %.4f (Kratos's tolerance 0.10)\n", k.file,
                  std::string(model->name).c_str(), error.value());
      CHECK(error.value() < 0.10);
    }
  }
}

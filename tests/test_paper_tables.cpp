// Table 2's printed damping ratios follow from eq. (6), and both zeta forms
// satisfy their defining relations.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/restitution.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace hertzdash;

TEST_CASE("Table 2: zeta printed in brackets is eq. (6) rounded to two decimals", "[paper][table2]") {
  // eq. (6): zeta = ln(1/e^2)/(2 pi). e.g. steel e = 0.795: ln(1/0.632)/(2 pi) = 0.0730 -> 0.07.
  const CsvTable t2 = CsvTable::read(default_data_dir() / "table2_restitution.csv");
  REQUIRE(t2.rows() == 4);
  for (std::size_t r = 0; r < t2.rows(); ++r) {
    for (const char* column : {"e", "e_second"}) {
      if (t2.text(r, column).empty()) continue;
      const double e = t2.number(r, column);
      const double zeta = std::log(1.0 / (e * e)) / (2 * std::numbers::pi);
      INFO(t2.text(r, "rod") << " " << column << " = " << e);
      CHECK(zeta_from_restitution(e, ZetaForm::paper) == Approx(zeta).epsilon(1e-14));
      CHECK(std::round(zeta * 100) / 100 == Approx(t2.number(r, "zeta_printed")).epsilon(1e-12));
    }
  }
}

TEST_CASE("Exact zeta satisfies the linear oscillator's half-cycle restitution", "[restitution]") {
  // A linear oscillator released at x = 0 with speed v0 leaves after half a damped
  // period with speed v0 exp(-pi zeta / sqrt(1 - zeta^2)).
  for (double e : {0.05, 0.3, 0.795, 0.99, 1.0}) {
    const double z = zeta_from_restitution(e, ZetaForm::exact);
    CHECK(std::exp(-std::numbers::pi * z / std::sqrt(1 - z * z)) == Approx(e).epsilon(1e-14));
    // eq. (6) is its small-damping limit: with L = ln(1/e) and zp = L/pi,
    // z = zp (1 + zp^2)^{-1/2}, so 0 <= zp - z <= zp^3/2 (alternating series).
    const double zp = zeta_from_restitution(e, ZetaForm::paper);
    CHECK(zp - z >= 0);
    CHECK(zp - z <= 0.5 * zp * zp * zp * (1 + 1e-12));
  }
}

TEST_CASE("Paper parameters: Tables 1-3 load with the stated assumptions", "[paper]") {
  const PaperParameters p = load_paper_parameters();
  REQUIRE(p.rods.size() == 4);
  CHECK(p.rod("steel").mass_kg == 0.778);
  CHECK(p.rod("duralumin-c").E_Pa == 67.4e9);
  CHECK(p.rod("duralumin-a").restitution == 0.828);
  CHECK(p.ball.radius_m == Approx(p.ball.diameter_m / 2));
  CHECK(p.ball.E_Pa >= p.ball.E_min_Pa);
  CHECK(p.ball.E_Pa <= p.ball.E_max_Pa);
}

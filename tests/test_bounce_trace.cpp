// The time series of a bounce sequence (simulation/run/bounce_trace.hpp, `bounce --trace`):
// its contacts are the sequence's impacts and its flights the ballistic arcs between them.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/bounce_trace.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using namespace hertzdash;

TEST_CASE("Bounce trace: each contact is the sequence's impact, each flight a ballistic arc", "[bounce][trace]") {
  const DropTestSetup setup = paper_setup(load_paper_parameters(), "steel", 0.02);
  const SolverSettings solver;  // CVODE at its defaults
  const BounceSequence seq = run_bounce_sequence(setup, "hongo", solver, BounceOptions{.impacts = 4});
  REQUIRE(seq.impacts.size() == 4);
  const std::vector<TraceSample> trace = bounce_trace(seq, setup, "hongo", solver);
  const double g = setup.gravity_mps2;

  // Time increases strictly; the first sample is the first onset.
  for (std::size_t i = 1; i < trace.size(); ++i) REQUIRE(trace[i].t_s > trace[i - 1].t_s);
  CHECK(trace.front().t_s == Approx(seq.impacts.front().onset_time_s).epsilon(1e-12));

  for (std::size_t n = 0; n < seq.impacts.size(); ++n) {
    const BounceImpact& b = seq.impacts[n];
    INFO("impact " << n);
    // The contact: the samples in [onset, separation], re-run with the same set-up, approach
    // speed, law and solver, so their peak is the sequence's peak force to rounding.
    double peak = 0;
    for (const TraceSample& s : trace)
      if (s.t_s >= b.onset_time_s * (1 - 1e-12) && s.t_s <= b.separation_time_s * (1 + 1e-12))
        peak = std::max(peak, s.force_N);
    CHECK(peak == Approx(b.peak_force_N).epsilon(1e-12));
    if (n + 1 == seq.impacts.size()) break;
    // The flight: x = -v_r tau + g tau^2 / 2 after separation (no clamp: x_s = 0), no force, the
    // rod's acceleration g; the arc meets the ball again (x = 0) at the next onset, where the
    // sequence says: t_on[n+1] - t_sep[n] = 2 v_r / g.
    const double v_r = b.rebound_speed_mps, flight = seq.impacts[n + 1].onset_time_s - b.separation_time_s;
    CHECK(flight == Approx(2 * v_r / g).epsilon(1e-12));
    int in_flight = 0;
    for (const TraceSample& s : trace) {
      const double tau = s.t_s - b.separation_time_s;
      if (!(tau > 0 && tau < flight)) continue;
      ++in_flight;
      CHECK(s.x_m == Approx(-v_r * tau + 0.5 * g * tau * tau).margin(1e-12));
      CHECK(s.xdot_mps == Approx(-v_r + g * tau).margin(1e-12));
      CHECK(s.force_N == 0);
      CHECK(s.accel_mps2 == g);
    }
    CHECK(in_flight == bounce_flight_samples - 1);
  }
}

TEST_CASE("Bounce trace: the elastic rod has none, and says so", "[bounce][trace]") {
  const auto r = test::run_cli("bounce --rod-model elastic --trace /dev/null");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("invalid --rod-model = elastic: must be rigid with --trace"));
}

TEST_CASE("bounce --trace writes the trace format, labelled synthetic, time from the first onset", "[bounce][trace]") {
  const test::ScratchDir dir;
  const std::string path = (dir.path / "bounce.csv").string();
  const auto r = test::run_cli("bounce --bounces 3 --json --trace " + path);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  const MeasuredTrace m = read_measured_trace(path);
  CHECK(m.synthetic);
  CHECK(m.rod == "steel");
  CHECK(m.height_m == 0.02);
  CHECK(m.t_s.front() == 0);
  CHECK(m.model_columns == model_trace_columns());
  // The rod rises above the first onset point (displacement < 0, downward positive) to the apex
  // of the first flight, v_r^2 / (2 g) with v_r the first rebound speed. The flight's 100 samples
  // lie 2 v_r / g / 100 (about 1.1 ms) apart, so the highest one misses the apex by at most
  // g / 2 (0.55 ms)^2 = 1.5e-6 m.
  const double v_r = j["impacts"][0]["rebound_speed_mps"].get<double>(), g = 9.80665;
  const double highest = *std::min_element(m.displacement_m.begin(), m.displacement_m.end());
  CHECK(-highest == Approx(v_r * v_r / (2 * g)).margin(2e-6));
}

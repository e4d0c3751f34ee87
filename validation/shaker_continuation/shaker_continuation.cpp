// Stability of the bouncing ball's orbits by continuation, over the brute-force diagram.
//
// The shaker's bifurcation diagram (validation/shaker_bifurcation) is brute force: each value of
// Gamma = A (2 pi f)^2 / g runs until its impacts repeat and shows the attractor its start
// reaches. Continuation (simulation/orbits/continuation.hpp, docs/orbits.md) follows the periodic
// orbits themselves, stable and unstable, with their Floquet multipliers from saltation matrices,
// and locates where they change:
//   - the fold Gamma_1 = pi (1 - e)/(1 + e), where the period-1 orbit is born with its saddle;
//   - the period doubling Gamma_2, Eq. (shaker-gamma2) of the article, and the doubled branches
//     after it, whose thresholds accumulate by Feigenbaum's ratio delta = 4.6692...;
// against the closed forms and the brute-force diagram, whose period doublings the located ones
// must bracket. The instantaneous map with e = 0.5, f = 20 Hz (the paper's steel rod: its mass
// does not enter the map).
//
// Writes: OUT/shaker_continuation_branches.csv (one row per impact of each branch point: branch,
// period, gamma, impact_phase, stable, largest multiplier modulus), OUT/shaker_continuation_brute.csv
// (gamma and the kept impacts' phases), GENERATED/shaker_continuation.tex (macros
// \shakerCont...), GENERATED/shaker_continuation_table.tex (the stable orbit's period between
// consecutive thresholds, by continuation and by brute force); shaker_continuation.gp draws them.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/simulation/orbits/continuation.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "validation/common/latex_macros.hpp"
#include "validation/common/steel_rod_setups.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double e = 0.5, frequency_Hz = 20;
constexpr double gamma_low = 1.0, gamma_start = 1.3, gamma_high = 1.75;
constexpr double feigenbaum_delta = 4.6692016;

/// The paper's steel rod with e = 0.5 (read once: the continuation builds a sequence per point).
const DropTestSetup& setup() {
  static const DropTestSetup s = paper_steel_rod(e);
  return s;
}

ImpactSequenceSpec spec_at(double gamma, int transient, int kept) {
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(gamma, frequency_Hz, setup().gravity_mps2), .frequency_Hz = frequency_Hz};
  o.impact_model = ShakerImpactModel::instantaneous;
  o.transient = transient;
  o.impacts = kept;
  return make_shaker_sequence(setup(), "hongo-paper", {}, o).spec;
}

/// The branches from the stable period-1 orbit at gamma_start towards `to`.
Continuation branches_towards(double to) {
  const SectionGuess guess = section_guess(spec_at(gamma_start, 1000, 40), std::nullopt, std::nullopt);
  if (!guess.failure.empty()) throw std::runtime_error("no start at Gamma = 1.3: " + guess.failure);
  const double g = setup().gravity_mps2, T = 1 / frequency_Hz;
  const ContinuationOptions o{.from = gamma_start, .to = to, .period = guess.period, .section_phase = guess.section_phase,
                              .start = guess.state, .scale = Eigen::Vector2d(g * T * T, g * T)};
  return continue_periodic_orbits([](double gamma) { return spec_at(gamma, 1000, 40); }, o);
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const Parameters provenance{{"restitution", fmt::format("{}", e)}, {"frequency_Hz", fmt::format("{}", frequency_Hz)},
                              {"impact_model", "instantaneous"}};

  // 1. Continuation: up from Gamma = 1.3 through the cascade, down through the fold.
  const auto start = std::chrono::steady_clock::now();
  const Continuation up = branches_towards(gamma_high), down = branches_towards(gamma_low);
  const double continuation_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CsvWriter branches("hertzdash validation/shaker_continuation: the instantaneous shaker's periodic orbits by "
                     "continuation in gamma, one row per impact of each branch point (its drive phase)",
                     provenance, {"branch", "period", "gamma", "impact_phase", "stable", "max_multiplier_modulus"});
  std::vector<double> doublings;
  double fold = NAN;
  for (const Continuation* c : {&up, &down}) {
    const int first_branch = c == &down ? 100 : 0;  // the two runs' branches apart
    for (const BranchPoint& p : c->points)
      for (const double phase : p.impact_phases)
        branches.add_row({static_cast<long>(first_branch + p.branch), static_cast<long>(p.period), p.parameter, phase,
                          static_cast<long>(p.stable), std::abs(p.multipliers.front())});
    for (const BranchEvent& ev : c->events) {
      branches.add_comment(fmt::format("event: {} at gamma = {:.10g} (period {})", to_string(ev.type), ev.parameter, ev.period));
      if (ev.type == BranchEventType::period_doubling && c == &up) doublings.push_back(ev.parameter);
      if (ev.type == BranchEventType::fold && c == &down) fold = ev.parameter;
    }
  }
  if (doublings.size() < 4 || std::isnan(fold)) throw std::runtime_error("the cascade or the fold was not found");

  // 2. The brute-force diagram over the same range: each gamma from the shaker's default start.
  const int values = args.reduced ? 60 : 300, transient = args.reduced ? 500 : 2000, kept = 32;
  CsvWriter brute("hertzdash validation/shaker_continuation: the brute-force diagram, the kept impacts' drive phases "
                  "after the transient",
                  provenance, {"gamma", "impact_phase", "period"});
  const auto brute_start = std::chrono::steady_clock::now();
  for (int k = 0; k < values; ++k) {
    const double gamma = gamma_low + (gamma_high - gamma_low) * (k + 0.5) / values;
    const ImpactSequence run = run_impact_sequence(spec_at(gamma, transient, kept));
    for (const SequenceImpact& i : run.impacts) brute.add_row({gamma, i.phase, static_cast<long>(run.pattern.period)});
  }
  const double brute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - brute_start).count();

  // 3. The numbers: located thresholds against the closed forms, the cascade's ratios.
  const double gamma_1 = std::numbers::pi * (1 - e) / (1 + e);
  const double gamma_2 = std::hypot(gamma_1, 2 * (1 + e * e) / ((1 + e) * (1 + e)));
  LatexMacros macros("validation/shaker_continuation: thresholds of the instantaneous shaker by continuation", provenance);
  macros.add("shakerContFold", fold, "{:.8f}");
  macros.add_text("shakerContFoldError", latex_scientific(std::abs(fold - gamma_1)));
  macros.add("shakerContGammaOne", gamma_1, "{:.8f}");
  macros.add("shakerContGammaTwo", gamma_2, "{:.8f}");
  macros.add("shakerContDoublingOne", doublings[0], "{:.8f}");
  macros.add_text("shakerContDoublingOneError", latex_scientific(std::abs(doublings[0] - gamma_2)));
  macros.add("shakerContDoublingTwo", doublings[1], "{:.5f}");
  macros.add("shakerContDoublingThree", doublings[2], "{:.5f}");
  macros.add("shakerContDoublingFour", doublings[3], "{:.5f}");
  macros.add("shakerContRatioOne", (doublings[1] - doublings[0]) / (doublings[2] - doublings[1]), "{:.2f}");
  macros.add("shakerContRatioTwo", (doublings[2] - doublings[1]) / (doublings[3] - doublings[2]), "{:.2f}");
  macros.add("shakerContFeigenbaum", feigenbaum_delta, "{:.3f}");
  macros.add("shakerContPoints", static_cast<double>(up.points.size() + down.points.size()), "{:.0f}");
  macros.add("shakerContSeconds", continuation_s, "{:.2f}");
  macros.add("shakerContBruteValues", values, "{:.0f}");
  macros.add("shakerContBruteTransient", transient, "{:.0f}");
  macros.add("shakerContBruteSeconds", brute_s, "{:.1f}");
  // 4. The table: between consecutive located thresholds the stable orbit's period, against the
  // brute-force run's period at the interval's middle (its transient long enough there, away
  // from the thresholds' slow convergence).
  std::string table = "% Generated by validation/shaker_continuation; do not edit.\n"
                      "\\begin{tabular}{cccc}\n\\toprule\n"
                      "$\\Gamma$ from & $\\Gamma$ to & period, continuation & period, brute force \\\\\n\\midrule\n";
  std::vector<double> thresholds{fold};
  thresholds.insert(thresholds.end(), doublings.begin(), doublings.begin() + 4);
  for (std::size_t k = 0; k + 1 < thresholds.size(); ++k) {
    const double middle = 0.5 * (thresholds[k] + thresholds[k + 1]);
    const int brute_period = run_impact_sequence(spec_at(middle, args.reduced ? 2000 : 8000, 64)).pattern.period;
    table += fmt::format("{:.5f} & {:.5f} & {} & {} \\\\\n", thresholds[k], thresholds[k + 1], 1 << k, brute_period);
  }
  table += "\\bottomrule\n\\end{tabular}\n";
  return save_study_outputs(args, "shaker_continuation",
                            {{"shaker_continuation_branches.csv", branches}, {"shaker_continuation_brute.csv", brute}}, table,
                            macros);
} catch (const std::exception& ex) {
  return study_failed(argv[0], ex);
}

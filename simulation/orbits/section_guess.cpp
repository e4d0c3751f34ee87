// The brute-force guess of shooting (simulation/orbits/section_guess.hpp).
#include "hertzdash/simulation/orbits/section_guess.hpp"

#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace hertzdash {

double widest_gap_middle(std::span<const double> phases, std::span<const double> lengths) {
  if (phases.empty()) return 0.5;
  // (start, end) of each occupied arc, by start.
  std::vector<std::pair<double, double>> arcs;
  for (std::size_t i = 0; i < phases.size(); ++i)
    arcs.emplace_back(phases[i], phases[i] + (i < lengths.size() ? lengths[i] : 0.0));
  std::ranges::sort(arcs);
  // The arc from the last end round to the first start, then each arc between neighbours.
  double widest = arcs.front().first + 1 - arcs.back().second, middle = arcs.back().second + 0.5 * widest;
  for (std::size_t i = 1; i < arcs.size(); ++i) {
    const double gap = arcs[i].first - arcs[i - 1].second;
    if (gap > widest) widest = gap, middle = arcs[i - 1].second + 0.5 * gap;
  }
  return middle - std::floor(middle);
}

SectionGuess section_guess(const ImpactSequenceSpec& spec, std::optional<double> section_phase, std::optional<int> period) {
  SectionGuess guess;
  const ImpactSequence run = run_impact_sequence(spec);
  guess.period = run.pattern.period;
  guess.impacts_per_period = run.pattern.impacts_per_period;
  if (run.end_carried || run.impacts.empty()) {
    guess.failure = fmt::format("the brute-force run ends with the body {}: {}",
                                run.end_carried ? "on the wall" : "without impacts", run.end_reason);
    return guess;
  }
  if (!period && guess.period == 0) {
    guess.failure = fmt::format("the brute-force run ({} transient and {} kept impacts) settles on no period: give "
                                "`period` (and a guess) to look for an orbit",
                                spec.transient, spec.impacts);
    return guess;
  }
  if (period) guess.period = *period;
  std::vector<double> phases, lengths;
  for (const SequenceImpact& i : run.impacts)
    phases.push_back(i.phase), lengths.push_back(i.contact_time_s * spec.frequency_Hz);
  guess.section_phase = section_phase.value_or(widest_gap_middle(phases, lengths));
  // From the end state (just after the last impact) to the next time at the section phase.
  const double f = spec.frequency_Hz, t_end = run.end_time_s;
  double t_s = (std::floor(t_end * f) + guess.section_phase) / f;
  if (t_s <= t_end) t_s += 1 / f;
  const ImpactSequence to_section =
      run_impact_sequence(flow_spec(spec, t_end, section_state(spec, run), t_s));
  if (to_section.end_carried || to_section.sticking_episodes > 0) {
    guess.failure = "the brute-force attractor sticks to the wall (a sticking orbit: the map is not smooth there)";
    return guess;
  }
  if (!(to_section.end_time_s == t_s)) {
    guess.failure = "the flow to the section ended before it: " + to_section.end_reason;
    return guess;
  }
  guess.state = section_state(spec, to_section);
  return guess;
}

}  // namespace hertzdash

// Basins of attraction (simulation/orbits/basins.hpp).
#include "hertzdash/simulation/orbits/basins.hpp"

#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <utility>

namespace hertzdash {

namespace {

/// Where the run from one start settles (an attractor with cells = 0), or inside_wall.
struct CellOutcome {
  bool inside_wall = false;
  BasinAttractor attractor;
};

CellOutcome settle(ImpactSequenceSpec spec, double t_s, double y, double u, const BasinOptions& o) {
  CellOutcome out;
  if (!(smallest_gap_m(spec, t_s, y) > 0)) return {.inside_wall = true, .attractor = {}};
  spec = in_flight_from(std::move(spec), t_s, y, u);
  spec.transient = o.transient, spec.impacts = o.kept;
  const ImpactSequence run = run_impact_sequence(spec);
  BasinAttractor& a = out.attractor;
  if (run.end_carried || static_cast<int>(run.impacts.size()) < o.kept) {
    a.kind = BasinAttractor::Kind::rest;
    return out;
  }
  a.period = run.pattern.period, a.impacts_per_period = run.pattern.impacts_per_period;
  if (a.period == 0) {
    a.kind = BasinAttractor::Kind::no_period;
    return out;
  }
  // The last period's impacts.
  const std::size_t k = static_cast<std::size_t>(a.impacts_per_period);
  for (std::size_t i = run.impacts.size() - k; i < run.impacts.size(); ++i) a.phases.push_back(run.impacts[i].phase);
  std::ranges::sort(a.phases);
  return out;
}

bool same_attractor(const BasinAttractor& a, const BasinAttractor& b, double tol) {
  if (a.kind != b.kind || a.period != b.period || a.impacts_per_period != b.impacts_per_period ||
      a.phases.size() != b.phases.size())
    return false;
  for (std::size_t i = 0; i < a.phases.size(); ++i) {
    const double d = std::abs(a.phases[i] - b.phases[i]);
    if (std::min(d, 1 - d) > tol) return false;
  }
  return true;
}

}  // namespace

std::string BasinAttractor::describe() const {
  switch (kind) {
    case Kind::rest: return "at rest on the wall";
    case Kind::no_period: return "no period within the kept impacts";
    case Kind::periodic: break;
  }
  return fmt::format("period {}, {} impact{} per period", period, impacts_per_period, impacts_per_period == 1 ? "" : "s");
}

Basins compute_basins(const std::function<ImpactSequenceSpec()>& make_spec, const BasinOptions& o) {
  const int n = o.resolution;
  if (n < 2) throw std::invalid_argument("compute_basins: at least 2 cells per axis");
  if (!(o.position_max_m > o.position_min_m) || !(o.velocity_max_mps > o.velocity_min_mps))
    throw std::invalid_argument("compute_basins: an empty range");
  const std::size_t cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<CellOutcome> outcome(cells);
  const unsigned threads = std::max(1u, std::min<unsigned>(o.threads, static_cast<unsigned>(n)));
  // Thread j runs rows j, j + threads, ...: each cell's run depends on its start alone. The specs
  // are made here, one after the other.
  std::vector<ImpactSequenceSpec> specs;
  for (unsigned j = 0; j < threads; ++j) specs.push_back(make_spec());
  auto work = [&](unsigned j) {
    const ImpactSequenceSpec& spec = specs[j];
    const double t_s = o.section_phase / spec.frequency_Hz;
    for (int row = static_cast<int>(j); row < n; row += static_cast<int>(threads))
      for (int col = 0; col < n; ++col)
        outcome[static_cast<std::size_t>(row * n + col)] =
            settle(spec, t_s, cell_centre(o.position_min_m, o.position_max_m, col, n),
                   cell_centre(o.velocity_min_mps, o.velocity_max_mps, row, n), o);
  };
  std::vector<std::jthread> pool;
  for (unsigned j = 1; j < threads; ++j) pool.emplace_back(work, j);
  work(0);
  pool.clear();  // joins
  // Number the attractors in the order of their first cell.
  Basins out;
  out.cell.assign(cells, -1);
  for (std::size_t c = 0; c < cells; ++c) {
    if (outcome[c].inside_wall) {
      ++out.inside_wall;
      continue;
    }
    auto found = std::ranges::find_if(out.attractors, [&](const BasinAttractor& a) {
      return same_attractor(a, outcome[c].attractor, o.phase_tolerance);
    });
    if (found == out.attractors.end()) found = out.attractors.insert(out.attractors.end(), outcome[c].attractor);
    ++found->cells;
    out.cell[c] = static_cast<int>(found - out.attractors.begin());
  }
  return out;
}

}  // namespace hertzdash

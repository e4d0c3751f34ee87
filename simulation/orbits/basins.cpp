// Basins of attraction (simulation/orbits/basins.hpp).
#include "hertzdash/simulation/orbits/basins.hpp"

#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <sstream>
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
  const Eigen::VectorXd z = spec.prescribed ? Eigen::VectorXd(Eigen::Vector2d(y, u))
                                            : Eigen::VectorXd(Eigen::Vector4d(y, u, o.box_position_m, o.box_velocity_mps));
  if (!(smallest_gap_m(spec, t_s, z) > 0)) return {.inside_wall = true, .attractor = {}};
  spec = in_flight_from(std::move(spec), t_s, y, u);
  if (!spec.prescribed) spec.X0_m = o.box_position_m, spec.V0_mps = o.box_velocity_mps;
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

namespace {

/// One outcome as text: "w" (inside a wall), "r" (at rest), "n PERIOD IMPACTS" (no period) or
/// "p PERIOD IMPACTS PHASE..." with every phase in its shortest exact decimal.
std::string outcome_text(const CellOutcome& c) {
  if (c.inside_wall) return "w";
  const BasinAttractor& a = c.attractor;
  if (a.kind == BasinAttractor::Kind::rest) return "r";
  std::string s = fmt::format("{} {} {}", a.kind == BasinAttractor::Kind::no_period ? 'n' : 'p', a.period, a.impacts_per_period);
  for (double phase : a.phases) s += fmt::format(" {}", phase);
  return s;
}

CellOutcome outcome_from_text(const std::string& line) {
  std::istringstream in(line);
  char kind = 0;
  in >> kind;
  CellOutcome c;
  if (kind == 'w') return {.inside_wall = true, .attractor = {}};
  if (kind == 'r') {
    c.attractor.kind = BasinAttractor::Kind::rest;
    return c;
  }
  c.attractor.kind = kind == 'n' ? BasinAttractor::Kind::no_period : BasinAttractor::Kind::periodic;
  in >> c.attractor.period >> c.attractor.impacts_per_period;
  for (double phase; in >> phase;) c.attractor.phases.push_back(phase);
  if (kind != 'n' && kind != 'p') throw std::runtime_error("basins: a process sent an unreadable outcome: " + line);
  return c;
}

}  // namespace

Basins compute_basins(const std::function<ImpactSequenceSpec()>& make_spec, const BasinOptions& o) {
  const int n = o.resolution;
  if (n < 2) throw std::invalid_argument("compute_basins: at least 2 cells per axis");
  if (!(o.position_max_m > o.position_min_m) || !(o.velocity_max_mps > o.velocity_min_mps))
    throw std::invalid_argument("compute_basins: an empty range");
  if (o.ranks < 1 || o.rank < 0 || o.rank >= o.ranks || (o.ranks > 1 && !o.gather))
    throw std::invalid_argument("compute_basins: a rank outside the processes, or several without a gather");
  const std::size_t cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<CellOutcome> outcome(cells);
  // This process's rows: rank, rank + ranks, ...; its thread j of J runs every J-th of them.
  std::vector<int> rows;
  for (int row = o.rank; row < n; row += o.ranks) rows.push_back(row);
  const unsigned threads = std::max(1u, std::min<unsigned>(o.threads, static_cast<unsigned>(std::max<std::size_t>(1, rows.size()))));
  // Each cell's run depends on its start alone. The specs are made here, one after the other.
  std::vector<ImpactSequenceSpec> specs;
  for (unsigned j = 0; j < threads; ++j) specs.push_back(make_spec());
  auto work = [&](unsigned j) {
    const ImpactSequenceSpec& spec = specs[j];
    const double t_s = o.section_phase / spec.frequency_Hz;
    for (std::size_t k = j; k < rows.size(); k += threads)
      for (int col = 0; col < n; ++col)
        outcome[static_cast<std::size_t>(rows[k] * n + col)] =
            settle(spec, t_s, cell_centre(o.position_min_m, o.position_max_m, col, n),
                   cell_centre(o.velocity_min_mps, o.velocity_max_mps, rows[k], n), o);
  };
  std::vector<std::jthread> pool;
  for (unsigned j = 1; j < threads; ++j) pool.emplace_back(work, j);
  work(0);
  pool.clear();  // joins
  if (o.ranks > 1) {
    // Every process's rows as lines, in the order of its rows; process 0 puts them in place.
    std::string mine;
    for (int row : rows)
      for (int col = 0; col < n; ++col) mine += outcome_text(outcome[static_cast<std::size_t>(row * n + col)]) + "\n";
    const std::vector<std::string> all = o.gather(mine);
    if (o.rank != 0) return Basins{.cell = {}, .attractors = {}, .inside_wall = 0, .elsewhere = true};
    for (int r = 1; r < o.ranks; ++r) {
      std::istringstream lines(all.at(static_cast<std::size_t>(r)));
      std::string line;
      for (int row = r; row < n; row += o.ranks)
        for (int col = 0; col < n; ++col) {
          if (!std::getline(lines, line)) throw std::runtime_error("basins: a process sent fewer outcomes than its rows");
          outcome[static_cast<std::size_t>(row * n + col)] = outcome_from_text(line);
        }
    }
  }
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

#pragma once
// Where shooting starts (simulation/orbits/periodic_orbit.hpp) when no guess is given: the rig's
// own brute-force run (its transient and kept impacts, from its start) gives the attractor, its
// period p in drive cycles (simulation/shaker/impact_pattern.hpp) and the phases of its impacts.
// The section phase phi_s is the middle of the widest impact-free arc of the kept impacts'
// phases on the circle, so that no impact of the orbit lies near the section (an impact crossing
// it would make the map jump). The guess is the run's end state flowed, without a stop, to the
// next time at phase phi_s.
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <Eigen/Core>

#include <optional>
#include <span>
#include <string>

namespace hertzdash {

struct SectionGuess {
  std::string failure;   ///< empty: found; else why not (no period, a sticking attractor, ...)
  int period = 0;        ///< drive cycles of the brute-force attractor (0: none detected)
  int impacts_per_period = 0;
  double section_phase = 0;  ///< in [0, 1)
  Eigen::VectorXd state;     ///< at the section (section_coordinates: (y [m], u [m/s]), a box of its own's (X, V))
};

/// The middle of the widest arc of [0, 1) free of the impacts at drive phases `phases`, each
/// occupying [phase, phase + length] (`lengths`, a soft contact's duration in cycles; none: 0)
/// (0.5 when there are none).
double widest_gap_middle(std::span<const double> phases, std::span<const double> lengths = {});

/// The guess from the brute-force run of `spec` (see above); `section_phase` and `period`, where
/// set, replace the detected ones.
SectionGuess section_guess(const ImpactSequenceSpec& spec, std::optional<double> section_phase, std::optional<int> period);

}  // namespace hertzdash

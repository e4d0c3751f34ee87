// A rig's Lyapunov exponents (simulation/rigs/rig_lyapunov.hpp).
#include "hertzdash/simulation/rigs/rig_lyapunov.hpp"

#include "hertzdash/model/parameter.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"

#include <fmt/format.h>

namespace hertzdash {

LyapunovRequest lyapunov_request(const RigInputs& given) {
  for (const auto& [key, value] : given.numbers) require_in_range(command_option("lyapunov", key), value);
  LyapunovRequest r;
  r.periods = static_cast<long>(given.number_or_default(command_option("lyapunov", "periods")));
  r.section_phase = given.number("section-phase");
  return r;
}

LyapunovResult run_lyapunov(const Rig& rig, const RunOptions& options, const PaperParameters& paper,
                            const RigInputs& inputs, const LyapunovRequest& request) {
  RigSequence rs = orbit_sequence(rig, options, paper, inputs);
  const ImpactSequenceSpec& spec = rs.sequence.spec;
  // Period 1 given: the start needs no period of the attractor (a chaotic one has none).
  const SectionGuess start = section_guess(spec, request.section_phase, 1);
  LyapunovResult out{.heading = rs.heading, .inputs = std::move(rs.inputs), .method = monodromy_method(spec),
                     .section_phase = start.section_phase,
                     .spectrum = {}};
  out.inputs.emplace_back("periods", std::to_string(request.periods));
  out.inputs.emplace_back("section_phase", fmt::format("{}", out.section_phase));
  if (!start.failure.empty()) {
    out.spectrum.failure = start.failure;
    return out;
  }
  out.spectrum = lyapunov_spectrum(StroboscopicMap(spec, out.section_phase, 1), start.state, {.periods = request.periods});
  return out;
}

}  // namespace hertzdash

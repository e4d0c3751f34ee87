#pragma once
// `hertzdash lyapunov RIG`: the Lyapunov exponents of a rig's stroboscopic map along its
// attractor (simulation/orbits/lyapunov.hpp, docs/orbits.md). The rig's own run (its transient and
// kept impacts, from its start) brings the body onto the attractor; from its end state at the
// section phase (given, or the middle of the widest impact-free arc of its impacts) the map runs
// `periods` drive periods with the QR method on its monodromy matrices.
#include "hertzdash/simulation/orbits/lyapunov.hpp"
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include <optional>
#include <string>

namespace hertzdash {

struct LyapunovRequest {
  long periods = 10000;
  std::optional<double> section_phase;
};
/// The request of the options given by key (`lyapunov`'s declarations); InvalidParameter naming
/// a key outside its range.
LyapunovRequest lyapunov_request(const RigInputs& given);

struct LyapunovResult {
  std::string heading;    ///< the rig's
  Parameters inputs;      ///< the rig's run's, then the request's
  std::string method;     ///< how the monodromy matrices are computed (monodromy_method)
  double section_phase = 0;
  LyapunovSpectrum spectrum;  ///< its failure also where the rig's run gives no start
};

LyapunovResult run_lyapunov(const Rig& rig, const RunOptions& options, const PaperParameters& paper,
                            const RigInputs& inputs, const LyapunovRequest& request);

}  // namespace hertzdash

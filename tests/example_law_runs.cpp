// The runs of the worked example (tests/example_law.hpp), a law no registry knows: compiled here,
// once, from the definition of ImpactSimulator::run<Law> (simulation/run/impact_simulator_run.hpp),
// as the generated unit of a registered law compiles its own (model/README.md, "What recompiles").
// The tests that run it include only the declaration and link to this copy.
#include "example_law.hpp"
#include "hertzdash/simulation/run/impact_simulator_run.hpp"

namespace hertzdash {

template ImpactSummary ImpactSimulator::run<ExactHertzDashpot>(const DropTestSetup&, std::vector<TraceSample>*);

}  // namespace hertzdash

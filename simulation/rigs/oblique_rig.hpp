#pragma once
// The rig `oblique` (docs/oblique.md): a sphere onto a flat at `incidence-angle` from the normal
// and speed `impact-velocity`, with friction and an initial spin, its normal contact any registered
// damping law and its tangential contact any registered tangential model (simulation/run/
// oblique_impact.hpp). The sphere is the drop test's (`ball-radius`, `ball-E`, `ball-nu`, `mass`
// or `density`), the flat's material `rod-E`, `rod-nu`.
#include "hertzdash/simulation/rigs/rig.hpp"

namespace hertzdash {

const Rig& oblique_rig();

}  // namespace hertzdash

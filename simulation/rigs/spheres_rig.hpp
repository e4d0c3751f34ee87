#pragma once
// The rig `spheres` (docs/balls.md): two spheres of their own radius, modulus, Poisson ratio and
// mass, head-on at a relative speed v, in free space (no gravity). The first sphere is the drop
// test's sphere (`ball-radius`, `ball-E`, `ball-nu`) with the falling body's mass (`mass`, or
// `density`); the second has inputs of its own (`second-radius`, `second-E`, `second-nu`,
// `second-mass` or `second-density`), each the first sphere's unless given. The contact is one
// impact of the reduced mass m* and radius R* (model/two_spheres.hpp) with any law and any
// integrator, as `simulate` runs one; the spheres' velocities after follow from momentum and e.
#include "hertzdash/model/two_spheres.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"

namespace hertzdash {

const Rig& spheres_rig();

}  // namespace hertzdash

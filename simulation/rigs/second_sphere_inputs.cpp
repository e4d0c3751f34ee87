// The second sphere's inputs (simulation/rigs/second_sphere_inputs.hpp).
#include "hertzdash/simulation/rigs/second_sphere_inputs.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/parameter.hpp"

namespace hertzdash::second_sphere_inputs {

void refuse_both_masses(const RigInputs& in) {
  if (in.number(mass.key) && in.number(density.key))
    throw InvalidParameter(std::string(density.key), format_value(*in.number(density.key)),
                           "omitted when `second-mass` is given (the density gives the second sphere's mass)");
}

Sphere resolve(const RunOptions& options, const RigInputs& in, const Sphere& first) {
  Sphere second;
  second.radius_m = in.number(radius.key).value_or(first.radius_m);
  second.material = {in.number(E.key).value_or(first.material.E_Pa), in.number(nu.key).value_or(first.material.nu)};
  const std::optional<double> rho = in.number(density.key) ? in.number(density.key) : options.density_kg_per_m3;
  second.mass_kg = in.number(mass.key).value_or(rho ? sphere_mass_kg(second.radius_m, *rho) : first.mass_kg);
  return second;
}

}  // namespace hertzdash::second_sphere_inputs

#include "hertzdash/simulation/run/calibrate_restitution.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <typeinfo>

namespace hertzdash {

DropTestSetup contact_phase_setup(const DropTestSetup& s) {
  DropTestSetup c = s;
  c.impact_velocity_mps = approach_speed(s);
  c.gravity_mps2 = 0.0;
  c.rod.E_Pa = std::numeric_limits<double>::infinity();
  validate(c);
  return c;
}

RestitutionCalibration calibrate_input_restitution(const std::function<double(double)>& observable, double target,
                                                   const std::string& option, std::string_view what) {
  require_in_open_closed(option, target, 0.0, 1.0);
  auto residual = [&](double e_input) { return observable(e_input) - target; };
  // A target within the runs' accuracy of an end of the range is met at that end.
  const double f_hi = residual(1.0);
  if (std::abs(f_hi) <= calibration_end_tolerance) return {1.0, f_hi + target, 0};
  const double f_lo = residual(calibration_e_min);
  if (std::abs(f_lo) <= calibration_end_tolerance) return {calibration_e_min, f_lo + target, 0};
  if (f_lo > 0 || f_hi < 0)
    throw InvalidParameter(option, format_value(target),
                           fmt::format("within [{:.6g}, {:.6g}], the {} reached for input e in [{}, 1]", f_lo + target,
                                       f_hi + target, what, calibration_e_min));
  int iterations = 0;
  const double e = brent_root(residual, calibration_e_min, 1.0, 1e-10, 0.0, "restitution calibration", &iterations);
  const double f = residual(e);
  // A jump in the observable (an interval ratio that does not exist below some input e) can
  // hold the bracket without a root: Brent then ends on the jump.
  if (std::abs(f) > calibration_end_tolerance)
    throw InvalidParameter(option, format_value(target),
                           fmt::format("a value the {} take: they jump past it at input e = {:.6g}, to {:.6g}", what, e,
                                       f + target));
  return {e, f + target, iterations};
}

RestitutionCalibration calibrate_restitution(ImpactSimulator& simulator, const DropTestSetup& s, std::string_view law,
                                             double target) try {
  DropTestSetup contact = contact_phase_setup(s);
  return calibrate_input_restitution(
      [&](double e_input) {
        contact.restitution = e_input;
        return simulator.run(contact, law).e_effective;
      },
      target, "target-restitution", fmt::format("effective restitutions law '{}'", law));
} catch (const std::runtime_error& e) {  // say which calibration (a study calibrates every law)
  if (typeid(e) != typeid(std::runtime_error)) throw;
  throw std::runtime_error(
      fmt::format("{}, while calibrating the input e of law {} to e_effective = {}", e.what(), law, target));
}

}  // namespace hertzdash

#pragma once
// The physical set-up of one drop test (Fig. 4 of the paper), validated.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/elastic_rod_setup.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cmath>
#include <optional>

namespace hertzdash {

/// Everything that defines one drop: constant for the run.
struct DropTestSetup {
  double mass_kg;            ///< rod mass m [kg], > 0
  double ball_radius_m;      ///< hemisphere radius R [m], > 0
  Material ball;             ///< hemisphere (nylon): E [Pa] > 0, nu in (-1, 0.5)
  /// The hemisphere's yield stress Y [Pa] > 0 (+inf: never yields), for the elasticity check
  /// only: a run whose Hertz peak pressure exceeds hertz_yield_onset_pressure_Pa(Y, ball.nu) is flagged.
  double ball_yield_stress_Pa = INFINITY;
  Material rod;              ///< flat rod end: E [Pa] > 0 or +inf (rigid), nu in (-1, 0.5)
  double restitution;        ///< input e in (0, 1]; 1 is undamped for the paper's law
  double height_m;           ///< drop height h [m] >= 0: free fall from rest, eq. (1)
  std::optional<double> impact_velocity_mps;  ///< if set (> 0), start at contact onset with this speed
  double gravity_mps2;       ///< g [m/s^2] >= 0, acting throughout, eq. (1)
  bool no_tension = false;   ///< clamp the contact force at >= 0; contact then ends where it reaches zero
  DampingSettings damping;
  /// Unset: the paper's model, a rigid rod on a fixed hemisphere. Set: the elastic rod on the
  /// hemisphere's load cell (model/elastic_drop_test.hpp); rod.E_Pa is then also the bar's
  /// modulus and must be finite.
  std::optional<ElasticRodSetup> elastic_rod;
};

/// Which of the inputs that set the impact's scale a user gave (an impact velocity, when set,
/// is always given); the others are defaults. A refusal of the scale names an input the user
/// gave and marks the defaults among the values it lists. All true (the default): a C++
/// caller's set-up, every value its own.
struct GivenScaleInputs {
  bool height = true, gravity = true, mass = true, ball_radius = true, ball_E = true, rod_E = true, ball_nu = true,
       rod_nu = true;
};

/// Throws InvalidParameter naming the CLI option and its valid range; includes validate_hertz_scale.
void validate(const DropTestSetup& s, const GivenScaleInputs& given = {});

/// The least undamped Hertz deformation a set-up may have [m]: a picometre, a hundredth of an
/// atom's size, below which no continuum contact model applies (and the integrators' absolute
/// tolerances would exceed the whole motion).
inline constexpr double min_hertz_deformation_m = 1e-12;

/// The impact's own scale is one the Hertz model describes: the undamped Hertz deformation
/// X = (5 m v0^2 / (4 K))^{2/5} (model/hertz.hpp) is finite, below the ball radius R (the
/// small-deformation assumption) and at least min_hertz_deformation_m. Otherwise throws
/// InvalidParameter naming the first input of these the user gave, with the bound on it where
/// one input alone sets it: --impact-velocity (v0 = sqrt(4 K X^{5/2} / (5 m)) at X = R or
/// X = min_hertz_deformation_m), --height (v0^2 / 2g), --gravity (v0^2 / 2h), --mass
/// (4 K X^{5/2} / (5 v0^2)); then --ball-radius, --ball-E, --rod-E, --ball-nu, --rod-nu (which
/// enter through K and R). The message lists the inputs that together give X, "(default)" after
/// each the user did not give.
void validate_hertz_scale(const DropTestSetup& s, const GivenScaleInputs& given = {});

/// Hertz stiffness of the set-up, eq. (3) [N/m^{3/2}].
double hertz_stiffness(const DropTestSetup& s);

/// Approach speed at contact onset [m/s]: the given impact velocity, else sqrt(2 g h).
double approach_speed(const DropTestSetup& s);

}  // namespace hertzdash

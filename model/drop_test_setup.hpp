#pragma once
// The physical set-up of one drop test (Fig. 4 of the paper), validated.
#include "hertzdash/model/air_drag.hpp"
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/elastic_rod_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <cmath>
#include <optional>
#include <string>

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
  /// Air drag on the falling body in flight (model/air_drag.hpp); inactive by default. Only the
  /// rigid model's bounce sequence flies (simulation/run/bounce_sequence.hpp); a single impact
  /// integrates its fall without drag and refuses an active one.
  AirDrag air_drag;
  DampingSettings damping;
  /// Unset: the paper's model, a rigid rod on a fixed hemisphere. Set: the elastic rod on the
  /// hemisphere's load cell (model/elastic_drop_test.hpp); rod.E_Pa is then also the bar's
  /// modulus and must be finite.
  std::optional<ElasticRodSetup> elastic_rod;
  /// The rod of Tables 1-3 the set-up started from ("steel"; empty for one built otherwise): the
  /// run's description names it as `rod`.
  std::string rod_preset;
  /// Whether `restitution` is the preset's measured e (Table 2) although the pair it was measured
  /// on was changed (a mass, modulus, Poisson ratio or radius of its own): flagged
  /// preset_restitution, as e belongs to the preset's rod on the hemisphere, not to this pair.
  bool restitution_of_other_pair = false;
};

/// Throws InvalidParameter naming the parameter and its valid range; includes validate_hertz_scale.
void validate(const DropTestSetup& s);

/// The least undamped Hertz deformation a set-up may have [m]: a picometre, a hundredth of an
/// atom's size, below which no continuum contact model applies. A physical bound, not a
/// numerical one: the integrators' absolute tolerances are relative to the impact's own scales
/// (ode/ode_system.hpp, state_scale), so smaller impacts would integrate as accurately; what
/// double precision itself cannot hold (X^{5/2}, m v0^2 under- or overflowing) lies far beyond.
inline constexpr double min_hertz_deformation_m = 1e-12;

/// The impact's own scale against the bounds of the Hertz model: the undamped Hertz deformation
/// X = (5 m v0^2 / (4 K))^{2/5} (model/hertz.hpp) must be finite, below the ball radius R (the
/// small-deformation assumption) and at least min_hertz_deformation_m. Where X breaks a bound,
/// the approach speed and the mass that put it on the bound follow from X^{5/2} = 5 m v0^2 / (4 K).
struct HertzScale {
  double stiffness_N_per_m1_5;  ///< K, eq. (3)
  double approach_speed_mps;    ///< v0
  double deformation_m;         ///< X
  bool too_large;               ///< X >= R (or not finite)
  bool too_small;               ///< X < min_hertz_deformation_m
  double bound_m;               ///< the bound X breaks: R or min_hertz_deformation_m (R when within)
  double speed_at_bound_mps;    ///< v0 that gives X = bound_m with this K and m
  double mass_at_bound_kg;      ///< m that gives X = bound_m with this K and v0
  bool within() const { return !too_large && !too_small; }
  /// Why X is refused, without naming inputs: "at or above the ball radius ...".
  std::string reason() const;
};
HertzScale hertz_scale(const DropTestSetup& s);

/// The refusal of a set-up's scale: an InvalidParameter that also carries the numbers, so that
/// a front end which knows which inputs its user gave can name one of those instead
/// (simulation/options/hertz_scale_refusal.hpp).
class HertzScaleRefused : public InvalidParameter {
 public:
  HertzScaleRefused(const std::string& refused_key, const std::string& refused_value, const std::string& range,
                    const HertzScale& numbers)
      : InvalidParameter(refused_key, refused_value, range), scale(numbers) {}
  HertzScale scale;
};

/// Throws HertzScaleRefused when hertz_scale(s) is not within(), naming the approach speed:
/// `impact-velocity` when the set-up has one, else `height`, with the bound on it.
void validate_hertz_scale(const DropTestSetup& s);

/// Hertz stiffness of the set-up, eq. (3) [N/m^{3/2}].
double hertz_stiffness(const DropTestSetup& s);

/// Approach speed at contact onset [m/s]: the given impact velocity, else the fall from h,
/// sqrt(2 g h) without air and v_t sqrt(1 - exp(-2 g h / v_t^2)) with its drag (model/air_drag.hpp).
double approach_speed(const DropTestSetup& s);

}  // namespace hertzdash

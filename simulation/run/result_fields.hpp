#pragma once
// What one impact reports, declared once: every result field of `simulate` (its name with the
// unit in it, unit, type, meaning, the front ends that report it, and how to read it from an
// ImpactSummary and its set-up), in the order of `simulate --json`. Made from it: the JSON keys
// (simulation/reports/result_output.hpp, for `simulate --json` and Python's simulate()), the columns a
// sweep can record (simulation/sweep/sweep_outputs.hpp), simulate's text block, the arrays of
// Python's simulate_many(), and the simulate tables of docs/json-output.md
// (tests/test_result_fields.cpp compares each of them with this table).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

namespace hertzdash {

/// What a field holds, and so how each front end shows it.
enum class ResultType {
  number,          ///< a double; NaN where the run has none: left out of JSON and text, an empty sweep cell
  number_or_null,  ///< a double; JSON null where it is not finite
  integer,         ///< a count, held exactly by the double `value` returns
  boolean,         ///< `value` 1 or 0
  integrator,      ///< the name of ImpactSummary::integrator_used (JSON string)
  coefficients,    ///< ImpactSummary::law_coefficients, units in their names: a JSON object, a text line each
  warnings,        ///< ImpactSummary::diagnostics: the run's notes and warnings in JSON, the codes in Python
  group,           ///< a JSON object of the fields whose `group` is this one's name; `value` 1 where the run has it, else NaN
};

/// The front ends that report a field.
struct ResultReports {
  bool json = false;         ///< `simulate --json`, Python's simulate()
  bool sweep = false;        ///< a column a sweep can record (a case file's [output] columns)
  bool python_many = false;  ///< an array of Python's simulate_many()
};

/// One field of an impact's result.
struct ResultField {
  std::string_view name = {};     ///< the key, its unit in it
  std::string_view group = {};    ///< the name of the group field it belongs to; empty: top level
  ResultType type = ResultType::number;
  std::string_view unit = {};     ///< SI unit ("1": dimensionless; empty: not a physical quantity)
  std::string_view meaning = {};  ///< docs/json-output.md's text (Markdown)
  ResultReports in = {};
  int text_line = 0;  ///< its place in simulate's text block, 1 the first line after the heading; 0: not there
  /// The value (number, number_or_null, integer, boolean, group); nullptr for the other types.
  double (*value)(const ImpactSummary&, const DropTestSetup&) = nullptr;
  /// Its text line (without the indent) where it is not `name value`; may show other fields of its group.
  std::string (*text)(const ImpactSummary&) = nullptr;
};

/// The text line `name value` (name padded to a column, value to 6 significant digits).
std::string result_text_line(std::string_view name, double value);
/// `work  N steps, M rhs evaluations`: ImpactSummary::work.
std::string work_text_line(const ImpactSummary& s);
/// `omega_n_fixed_point  N iterations, converged (...)`: an iterated omega_n variant's fixed point.
std::string omega_n_fixed_point_text_line(const ImpactSummary& s);
/// `elastic rod: N elements, first longitudinal frequency ... Hz, 2L/c = ... s`.
std::string elastic_rod_text_line(const ImpactSummary& s);

/// The JSON type docs/json-output.md names ("number", "number or null", "integer", "boolean",
/// "string", "object", "array").
std::string_view json_type_name(ResultType type);

namespace result_field_detail {
inline constexpr double absent = std::numeric_limits<double>::quiet_NaN();
template <auto member>
double of_summary(const ImpactSummary& s, const DropTestSetup&) {
  return static_cast<double>(s.*member);
}
template <auto member>
double of_work(const ImpactSummary& s, const DropTestSetup&) {
  return static_cast<double>(s.work.*member);
}
template <auto member>
double of_omega_n_iteration(const ImpactSummary& s, const DropTestSetup&) {
  return s.omega_n_iteration ? static_cast<double>((*s.omega_n_iteration).*member) : absent;
}
template <auto member>
double of_elastic_rod(const ImpactSummary& s, const DropTestSetup&) {
  return s.elastic_rod ? static_cast<double>((*s.elastic_rod).*member) : absent;
}
template <auto member>
double of_fixed_step_elastic_rod(const ImpactSummary& s, const DropTestSetup&) {
  return s.elastic_rod && s.elastic_rod->step_used_s > 0 ? (*s.elastic_rod).*member : absent;
}
inline double yield_onset_pressure_Pa(const DropTestSetup& setup) {
  return hertz_yield_onset_pressure_Pa(setup.ball_yield_stress_Pa, setup.ball.nu);
}
}  // namespace result_field_detail

/// Every result field, in the order of `simulate --json`; a group's fields follow it.
inline constexpr std::array result_fields{
    ResultField{.name = "e_effective", .unit = "1",
                .meaning = "rebound speed at separation over approach speed at onset (0 if the rod never separates)",
                .in = {.json = true, .sweep = true, .python_many = true}, .text_line = 3,
                .value = &result_field_detail::of_summary<&ImpactSummary::e_effective>},
    ResultField{.name = "peak_force_N", .unit = "N", .meaning = "largest contact force (compressive positive)",
                .in = {.json = true, .sweep = true, .python_many = true}, .text_line = 4,
                .value = &result_field_detail::of_summary<&ImpactSummary::peak_force_N>},
    ResultField{.name = "max_deformation_m", .unit = "m", .meaning = "largest deformation x",
                .in = {.json = true, .sweep = true, .python_many = true}, .text_line = 5,
                .value = &result_field_detail::of_summary<&ImpactSummary::max_deformation_m>},
    ResultField{.name = "peak_contact_pressure_Pa", .unit = "Pa",
                .meaning = "Hertz peak pressure at the largest deformation, `p0 = 3 K x^{1/2} / (2 pi R)` "
                           "([bounce.md](bounce.md#the-elasticity-check---ball-yield-stress))",
                .in = {.json = true, .sweep = true}, .text_line = 6,
                .value = &result_field_detail::of_summary<&ImpactSummary::peak_contact_pressure_Pa>},
    ResultField{.name = "yield_onset_pressure_Pa", .type = ResultType::number_or_null, .unit = "Pa",
                .meaning = "where yield begins in the hemisphere, `f(nu) Y` (`hertz_yield_onset_factor` in "
                           "`model/hertz.hpp`) with `Y` from `--ball-yield-stress` (default: "
                           "`data/assumptions.csv`); null when `Y` is `inf` (no check)",
                .in = {.json = true},
                .value = [](const ImpactSummary&, const DropTestSetup& setup) {
                  return result_field_detail::yield_onset_pressure_Pa(setup);
                }},
    ResultField{.name = "exceeds_yield_onset", .type = ResultType::boolean,
                .meaning = "`peak_contact_pressure_Pa` > `yield_onset_pressure_Pa` (false without a check); stderr "
                           "warns when true",
                .in = {.json = true},
                .value = [](const ImpactSummary& s, const DropTestSetup& setup) {
                  return s.peak_contact_pressure_Pa > result_field_detail::yield_onset_pressure_Pa(setup) ? 1.0 : 0.0;
                }},
    ResultField{.name = "hertz_profile_error", .unit = "1",
                .meaning = "`x / (4R)` at the largest deformation: how far the sphere departs from the paraboloid "
                           "Hertz theory assumes at the contact's edge, `a^2/(4R^2)` with `a = sqrt(R x)` "
                           "(`model/hertz.hpp`)",
                .in = {.json = true},
                .value = [](const ImpactSummary& s, const DropTestSetup& setup) {
                  return hertz_profile_error(s.max_deformation_m, setup.ball_radius_m);
                }},
    ResultField{.name = "exceeds_small_deformation", .type = ResultType::boolean,
                .meaning = "`hertz_profile_error` > `hertz_profile_error_limit` (`model/hertz.hpp`): outside the "
                           "small-deformation range; stderr warns when true",
                .in = {.json = true},
                .value = [](const ImpactSummary& s, const DropTestSetup& setup) {
                  return hertz_profile_error(s.max_deformation_m, setup.ball_radius_m) > hertz_profile_error_limit
                             ? 1.0
                             : 0.0;
                }},
    ResultField{.name = "contact_time_s", .unit = "s",
                .meaning = "separation time minus onset time (0 without separation)",
                .in = {.json = true, .sweep = true, .python_many = true}, .text_line = 7,
                .value = &result_field_detail::of_summary<&ImpactSummary::contact_time_s>},
    ResultField{.name = "impact_velocity_mps", .unit = "m/s", .meaning = "approach speed at contact onset",
                .in = {.json = true, .sweep = true, .python_many = true}, .text_line = 1,
                .value = &result_field_detail::of_summary<&ImpactSummary::impact_velocity_mps>},
    ResultField{.name = "rebound_velocity_mps", .unit = "m/s",
                .meaning = "rebound speed at separation (0 without separation)",
                .in = {.json = true, .sweep = true, .python_many = true}, .text_line = 2,
                .value = &result_field_detail::of_summary<&ImpactSummary::rebound_velocity_mps>},
    ResultField{.name = "separated", .type = ResultType::boolean,
                .meaning = "false if the rod came to rest on the hemisphere (a sweep column: 1 or 0)",
                .in = {.json = true, .sweep = true, .python_many = true},
                .value = &result_field_detail::of_summary<&ImpactSummary::separated>},
    ResultField{.name = "K_N_per_m_1_5", .unit = "N/m^{3/2}", .meaning = "Hertz stiffness K of eq. (3)",
                .in = {.json = true, .sweep = true}, .text_line = 8,
                .value = &result_field_detail::of_summary<&ImpactSummary::K>},
    ResultField{.name = "law_coefficients", .type = ResultType::coefficients,
                .meaning = "the damping law's coefficients for this impact, units in the names (for the paper's "
                           "law: `zeta`, `omega_n_rad_per_s`, `c_e_coefficient_N_s_per_m_1_5`); `hertzdash models` "
                           "lists each law's",
                .in = {.json = true}, .text_line = 9},
    ResultField{.name = "steps", .type = ResultType::integer,
                .meaning = "accepted integrator steps, whole run (fall and contact)",
                .in = {.json = true, .sweep = true}, .text_line = 10,
                .value = &result_field_detail::of_work<&IntegrationStats::steps>, .text = &work_text_line},
    ResultField{.name = "rhs_evaluations", .type = ResultType::integer,
                .meaning = "right-hand-side evaluations, whole run", .in = {.json = true, .sweep = true},
                .value = &result_field_detail::of_work<&IntegrationStats::rhs_evaluations>},
    ResultField{.name = "events", .type = ResultType::integer,
                .meaning = "events fired (contact, maximum compression, peak force, separation, ...)",
                .in = {.json = true}, .value = &result_field_detail::of_work<&IntegrationStats::events>},
    ResultField{.name = "integrator_used", .type = ResultType::integrator,
                .meaning = "the integrator that ran: the one asked for, or its fall-back in the integrator table "
                           "(stderr says why)",
                .in = {.json = true}},
    ResultField{.name = "warnings", .type = ResultType::warnings,
                .meaning = "every note and warning the run printed on stderr (Python: `UserWarning`s), each "
                           "`{\"kind\": \"note\" or \"warning\", \"code\", \"message\"}` ([the codes](#warning-codes)); "
                           "empty for a clean run (`simulate_many()`: the codes of each point)",
                .in = {.json = true, .python_many = true}},
    ResultField{.name = "omega_n_fixed_point", .type = ResultType::group,
                .meaning = "only for the iterated `--omega-n` variants: [its keys](#omega_n_fixed_point)",
                .in = {.json = true}, .text_line = 11,
                .value = [](const ImpactSummary& s, const DropTestSetup&) {
                  return s.omega_n_iteration ? 1.0 : result_field_detail::absent;
                },
                .text = &omega_n_fixed_point_text_line},
    ResultField{.name = "iterations", .group = "omega_n_fixed_point", .type = ResultType::integer,
                .meaning = "simulations run", .in = {.json = true},
                .value = &result_field_detail::of_omega_n_iteration<&OmegaNIteration::iterations>},
    ResultField{.name = "converged", .group = "omega_n_fixed_point", .type = ResultType::boolean,
                .meaning = "whether the iteration converged", .in = {.json = true},
                .value = &result_field_detail::of_omega_n_iteration<&OmegaNIteration::converged>},
    ResultField{.name = "relative_change", .group = "omega_n_fixed_point", .unit = "1",
                .meaning = "`abs(w_k - w_{k-1}) / w_k` at the last iteration", .in = {.json = true},
                .value = &result_field_detail::of_omega_n_iteration<&OmegaNIteration::relative_change>},
    ResultField{.name = "contraction", .group = "omega_n_fixed_point", .unit = "1",
                .meaning = "the last observed `abs(dG) / abs(dw)` (below 1 for a contraction)", .in = {.json = true},
                .value = &result_field_detail::of_omega_n_iteration<&OmegaNIteration::contraction>},
    ResultField{.name = "elastic_rod", .type = ResultType::group,
                .meaning = "only with `--rod-model elastic` ([elastic-rod.md](elastic-rod.md)): [its "
                           "keys](#elastic_rod); the velocities and `e_effective` above are then the centre of mass's",
                .in = {.json = true}, .text_line = 12,
                .value = [](const ImpactSummary& s, const DropTestSetup&) {
                  return s.elastic_rod ? 1.0 : result_field_detail::absent;
                },
                .text = &elastic_rod_text_line},
    ResultField{.name = "elements", .group = "elastic_rod", .type = ResultType::integer,
                .meaning = "finite elements N", .in = {.json = true},
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::elements>},
    ResultField{.name = "first_frequency_hz", .group = "elastic_rod", .unit = "Hz",
                .meaning = "the discrete rod's first free-free longitudinal frequency", .in = {.json = true},
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::first_frequency_hz>},
    ResultField{.name = "wave_round_trip_s", .group = "elastic_rod", .unit = "s", .meaning = "`2 L / c`",
                .in = {.json = true}, .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::wave_round_trip_s>},
    ResultField{.name = "stable_step_s", .group = "elastic_rod", .unit = "s",
                .meaning = "fixed-step integrators only: the stability-limited step", .in = {.json = true},
                .value = &result_field_detail::of_fixed_step_elastic_rod<&ElasticRodReport::stable_step_s>},
    ResultField{.name = "step_used_s", .group = "elastic_rod", .unit = "s",
                .meaning = "fixed-step integrators only: the smaller of `--dt` and `stable_step_s`",
                .in = {.json = true},
                .value = &result_field_detail::of_fixed_step_elastic_rod<&ElasticRodReport::step_used_s>},
    ResultField{.name = "peak_load_cell_force_N", .group = "elastic_rod", .unit = "N",
                .meaning = "largest force the load cell measured", .in = {.json = true, .sweep = true},
                .text_line = 13, .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::peak_load_cell_force_N>},
    ResultField{.name = "energy_in_J", .group = "elastic_rod", .unit = "J",
                .meaning = "`(1/2) m v0^2` plus the work of gravity on the rod during contact",
                .in = {.json = true, .sweep = true}, .text_line = 14,
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_in_J>},
    ResultField{.name = "energy_rigid_body_out_J", .group = "elastic_rod", .unit = "J",
                .meaning = "`(1/2) m v_cm^2` at separation", .in = {.json = true, .sweep = true}, .text_line = 15,
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_rigid_body_out_J>},
    ResultField{.name = "energy_rod_vibration_J", .group = "elastic_rod", .unit = "J",
                .meaning = "the rod's kinetic energy relative to its centre of mass plus its strain energy, at "
                           "separation",
                .in = {.json = true, .sweep = true}, .text_line = 16,
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_rod_vibration_J>},
    ResultField{.name = "energy_cell_J", .group = "elastic_rod", .unit = "J",
                .meaning = "the hemisphere and the cell spring, at separation", .in = {.json = true, .sweep = true},
                .text_line = 17, .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_cell_J>},
    ResultField{.name = "energy_dissipated_contact_J", .group = "elastic_rod", .unit = "J",
                .meaning = "work absorbed by the contact law", .in = {.json = true, .sweep = true}, .text_line = 18,
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_dissipated_contact_J>},
    ResultField{.name = "energy_dissipated_material_J", .group = "elastic_rod", .unit = "J",
                .meaning = "the rod's material damping plus the cell's damping", .in = {.json = true, .sweep = true},
                .text_line = 19,
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_dissipated_material_J>},
    ResultField{.name = "separation_velocity_mps", .group = "elastic_rod", .unit = "m/s",
                .meaning = "the centre of mass's velocity at separation, upward positive; negative: the rod left the "
                           "hemisphere still moving down (warning `no_rebound`)",
                .in = {.json = true},
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::separation_velocity_mps>},
    ResultField{.name = "energy_balance_error_J", .group = "elastic_rod", .unit = "J",
                .meaning = "`energy_in_J` minus the five terms above", .in = {.json = true, .sweep = true},
                .text_line = 20,
                .value = &result_field_detail::of_elastic_rod<&ElasticRodReport::energy_balance_error_J>},
};

/// The fields reported by one front end (`report` a member of ResultReports), in table order.
template <bool ResultReports::*report>
constexpr auto result_fields_reported() {
  constexpr auto n = static_cast<std::size_t>(
      std::ranges::count_if(result_fields, [](const ResultField& f) { return f.in.*report; }));
  std::array<ResultField, n> out{};
  std::ranges::copy_if(result_fields, out.begin(), [](const ResultField& f) { return f.in.*report; });
  return out;
}

namespace result_field_detail {
// The text lines are 1, 2, ... once each.
constexpr bool text_lines_are_a_sequence() {
  int lines = 0;
  for (const ResultField& f : result_fields) lines += f.text_line > 0;
  for (int line = 1; line <= lines; ++line)
    if (std::ranges::count_if(result_fields, [line](const ResultField& f) { return f.text_line == line; }) != 1)
      return false;
  return true;
}
}  // namespace result_field_detail
static_assert(result_field_detail::text_lines_are_a_sequence(), "each text line of simulate once, from 1 up");

}  // namespace hertzdash

#pragma once
// The quantities a sweep can record per run (the `columns` of a case file's [output]), each
// read from the run's ImpactSummary; the names are simulate's summary keys. A quantity a run
// does not have (the elastic rod's energies in a rigid-rod run) is left empty in the CSV.
#include "hertzdash/simulation/impact_summary.hpp"

#include <array>
#include <cmath>
#include <string_view>

namespace hertzdash {

struct SweepOutput {
  std::string_view name;
  std::string_view help;
  double (*value)(const ImpactSummary&);  ///< NaN where the run has no such quantity
};

namespace sweep_output_detail {
inline double elastic(const ImpactSummary& s, double ElasticRodReport::*field) {
  return s.elastic_rod ? (*s.elastic_rod).*field : NAN;
}
}  // namespace sweep_output_detail

inline constexpr std::array<SweepOutput, 19> sweep_output_table{{
    {"e_effective", "rebound / approach speed", [](const ImpactSummary& s) { return s.e_effective; }},
    {"peak_force_N", "largest contact force", [](const ImpactSummary& s) { return s.peak_force_N; }},
    {"contact_time_s", "separation minus onset time", [](const ImpactSummary& s) { return s.contact_time_s; }},
    {"max_deformation_m", "largest deformation x", [](const ImpactSummary& s) { return s.max_deformation_m; }},
    {"peak_contact_pressure_Pa", "Hertz peak pressure at the largest x",
     [](const ImpactSummary& s) { return s.peak_contact_pressure_Pa; }},
    {"impact_velocity_mps", "approach speed at onset", [](const ImpactSummary& s) { return s.impact_velocity_mps; }},
    {"rebound_velocity_mps", "rebound speed at separation", [](const ImpactSummary& s) { return s.rebound_velocity_mps; }},
    {"K_N_per_m_1_5", "Hertz stiffness", [](const ImpactSummary& s) { return s.K; }},
    {"separated", "1 if the rod separated, 0 if it came to rest", [](const ImpactSummary& s) { return s.separated ? 1.0 : 0.0; }},
    {"steps", "integrator steps", [](const ImpactSummary& s) { return static_cast<double>(s.work.steps); }},
    {"rhs_evaluations", "right-hand-side evaluations",
     [](const ImpactSummary& s) { return static_cast<double>(s.work.rhs_evaluations); }},
    {"peak_load_cell_force_N", "elastic rod: largest load cell force",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::peak_load_cell_force_N); }},
    {"energy_in_J", "elastic rod: energy brought in",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_in_J); }},
    {"energy_rigid_body_out_J", "elastic rod: rigid-body kinetic energy at separation",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_rigid_body_out_J); }},
    {"energy_rod_vibration_J", "elastic rod: vibration energy at separation",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_rod_vibration_J); }},
    {"energy_cell_J", "elastic rod: load cell energy at separation",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_cell_J); }},
    {"energy_dissipated_contact_J", "elastic rod: work absorbed by the contact law",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_dissipated_contact_J); }},
    {"energy_dissipated_material_J", "elastic rod: rod and cell damping",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_dissipated_material_J); }},
    {"energy_balance_error_J", "elastic rod: energy in minus the five terms",
     [](const ImpactSummary& s) { return sweep_output_detail::elastic(s, &ElasticRodReport::energy_balance_error_J); }},
}};

/// The output called `name`, or nullptr.
inline const SweepOutput* find_sweep_output(std::string_view name) {
  for (const SweepOutput& o : sweep_output_table)
    if (o.name == name) return &o;
  return nullptr;
}

}  // namespace hertzdash

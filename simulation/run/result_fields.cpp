#include "hertzdash/simulation/run/result_fields.hpp"

#include <fmt/format.h>

namespace hertzdash {

std::string result_text_line(std::string_view name, double value) { return fmt::format("{:<30} {:.6g}", name, value); }

std::string work_text_line(const ImpactSummary& s) {
  return fmt::format("{:<30} {} steps, {} rhs evaluations", "work", s.work.steps, s.work.rhs_evaluations);
}

std::string omega_n_fixed_point_text_line(const ImpactSummary& s) {
  const OmegaNIteration& it = *s.omega_n_iteration;
  return fmt::format("{:<30} {} iterations, {} (last relative change {:.3g}, contraction {:.3g})", "omega_n_fixed_point",
                     it.iterations, it.converged ? "converged" : "NOT converged", it.relative_change, it.contraction);
}

std::string elastic_rod_text_line(const ImpactSummary& s) {
  const ElasticRodReport& e = *s.elastic_rod;
  return fmt::format("elastic rod: {} elements, first longitudinal frequency {:.6g} Hz, 2L/c = {:.6g} s", e.elements,
                     e.first_frequency_hz, e.wave_round_trip_s);
}

std::string_view json_type_name(ResultType type) {
  switch (type) {
    case ResultType::number: return "number";
    case ResultType::number_or_null: return "number or null";
    case ResultType::integer: return "integer";
    case ResultType::boolean: return "boolean";
    case ResultType::integrator: return "string";
    case ResultType::coefficients: return "object";
    case ResultType::warnings: return "array";
    case ResultType::group: return "object";
  }
  return "";
}

}  // namespace hertzdash

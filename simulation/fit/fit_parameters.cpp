// The parameters a fit may fit: those declared fittable (simulation/options/run_options.hpp),
// within their declared ranges, starting from their values in the resolved set-up. Parses a
// --fit list (parse_fit_parameters, fittable_option_names: simulation/fit/fit_engine.hpp) and finds
// the starting values (simulation/fit/fit_parameters.hpp).
#include "hertzdash/simulation/fit/fit_parameters.hpp"

#include "hertzdash/simulation/fit/restitution_fit_model.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"

#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <optional>

namespace hertzdash {

namespace {

const RunOption* find_fittable(const std::string& name) {
  const RunOption* o = find_run_option(name);
  return o && o->decl.fittable ? o : nullptr;
}

void check_bounds(const FitParameter& p, double x) {
  if (!(x > p.lower && x < p.upper))
    throw InvalidParameter("fit", fmt::format("{}:{}:{}", p.option, format_value(p.lower), format_value(p.upper)),
                           fmt::format("bounds around the starting value {} {} (set it inside them)",
                                       key_reference(p.option), format_value(x)));
}

// The material constant of a law that has one (kuwabara-kono's A, lee-herrmann's gamma) whose e at
// `speed` is `e` (the simulator's calibration).
double calibrated_time_constant(const RunOptions& base, const PaperParameters& paper, double speed, double e) {
  RunOptions o = base;
  o.restitution = e;
  o.viscous_time_constant_s.reset();
  if (const ParameterDecl* constant = registered_law(base.damping).material_constant())
    o.law_numbers.erase(std::string(constant->key));
  o.air_density_kg_per_m3.reset();  // one contact: no flight, no drag
  o.drag_coefficient.reset();
  const DropTestSetup s = restitution_fit_detail::restitution_contact(o, paper, speed);
  const LawRuns& runs = law_runs(base.damping);
  return runs.calibrated_time_constant ? *runs.material_constant(runs.calibrated_time_constant(s).damping) : 0.0;
}

}  // namespace

RunOptions fit_detail::FitModel::options_at(const std::vector<double>& values) const {
  RunOptions o = base_;
  for (std::size_t j = 0; j < names_.size(); ++j) set_number(o, *find_run_option(names_[j]), values[j]);
  return o;
}

double fit_detail::mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double fit_detail::median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<double> fit_detail::law_starting_values(const RunOptions& base, const PaperParameters& paper,
                                                    const std::vector<FitParameter>& parameters, double e,
                                                    double speed_mps) {
  std::vector<double> v;
  for (const FitParameter& p : parameters) {
    require_read(base, *find_run_option(p.option), "(fitted)");
    double x;
    if (p.option == "restitution" && !base.restitution) x = e;
    else if (const ParameterDecl* constant = registered_law(base.damping).material_constant();
             constant && p.option == constant->key && !material_constant_given(base))
      x = calibrated_time_constant(base, paper, speed_mps, e);
    else x = initial_values(base, paper, {p}).front();
    check_bounds(p, x);
    v.push_back(x);
  }
  return v;
}

std::vector<double> fit_detail::initial_values(const RunOptions& base, const PaperParameters& paper,
                                                     const std::vector<FitParameter>& parameters) {
  const DropTestSetup s = resolve_setup(base, paper);
  for (const FitParameter& p : parameters) require_read(base, *find_run_option(p.option), "(fitted)");
  std::vector<double> v;
  for (const FitParameter& p : parameters) {
    const std::optional<double> x = find_fittable(p.option)->value_in_setup(s);
    if (!x)
      throw InvalidParameter("fit", p.option,
                             fmt::format("given a starting value: {} is unset and has no default for this run",
                                         key_reference(p.option)));
    check_bounds(p, *x);
    v.push_back(*x);
  }
  return v;
}

std::string fittable_option_names() {
  std::string s;
  for (const RunOption* o : fittable_options()) s += (s.empty() ? "" : ", ") + o->name;
  return s;
}

std::vector<FitParameter> parse_fit_parameters(const std::string& list) {
  std::vector<FitParameter> out;
  for (const std::string& item : split_option_list(list)) {
    const std::size_t colon = item.find(':');
    const RunOption* f = find_fittable(item.substr(0, colon));
    if (!f)
      throw InvalidParameter("fit", list,
                             "a comma-separated list of NAME or NAME:LOWER:UPPER with NAME one of: " + fittable_option_names());
    const double lower = f->decl.range.lo, upper = f->decl.range.hi;
    FitParameter p{f->name, lower, upper};
    if (colon != std::string::npos) {
      const std::string bounds = item.substr(colon + 1);
      const std::size_t mid = bounds.find(':');
      auto number = [&](const std::string& text) {
        const std::optional<double> v = parse_option_number(text);
        if (!v) throw InvalidParameter("fit", item, "NAME:LOWER:UPPER with two decimal numbers, LOWER < UPPER");
        return *v;
      };
      if (mid == std::string::npos) throw InvalidParameter("fit", item, "NAME:LOWER:UPPER with two numbers, LOWER < UPPER");
      p.lower = number(bounds.substr(0, mid));
      p.upper = number(bounds.substr(mid + 1));
      if (!(p.lower < p.upper) || !std::isfinite(p.lower) || p.lower < lower || p.upper > upper)
        throw InvalidParameter("fit", item,
                               fmt::format("NAME:LOWER:UPPER with LOWER < UPPER, LOWER finite, within {}'s range [{}, {}]",
                                           key_reference(f->name), format_value(lower), format_value(upper)));
    }
    for (const FitParameter& q : out)
      if (q.option == p.option) throw InvalidParameter("fit", list, "a list naming each parameter once");
    out.push_back(p);
  }
  return out;
}

}  // namespace hertzdash

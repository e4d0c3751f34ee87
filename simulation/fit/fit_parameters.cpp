// The parameters a trace fit may fit: those declared fittable (simulation/options/run_options.hpp),
// within their declared ranges, starting from their values in the resolved set-up. Parses a
// --fit list (parse_fit_parameters, fittable_option_names: simulation/fit/trace_fit.hpp) and finds
// the starting values (initial_values: simulation/fit/fit_parameters.hpp).
#include "hertzdash/simulation/fit/fit_parameters.hpp"

#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <optional>

namespace hertzdash {

namespace {

const RunOption* find_fittable(const std::string& name) {
  const RunOption* o = find_run_option(name);
  return o && o->decl.fittable ? o : nullptr;
}

}  // namespace

std::vector<double> trace_fit_detail::initial_values(const RunOptions& base, const PaperParameters& paper,
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
    if (!(*x > p.lower && *x < p.upper))
      throw InvalidParameter("fit", fmt::format("{}:{}:{}", p.option, format_value(p.lower), format_value(p.upper)),
                             fmt::format("bounds around the starting value {} {} (set it inside them)",
                                         key_reference(p.option), format_value(*x)));
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

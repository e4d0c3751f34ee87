#include "hertzdash/simulation/sweep/sweep_case.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/options/declared_choice.hpp"
#include "hertzdash/simulation/sweep/sweep_outputs.hpp"

#include <toml++/toml.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>
#include <type_traits>

namespace hertzdash {

namespace {

// Where a node is, for messages: "(case.toml line 7)".
std::string where(const std::string& source, const toml::source_region& r) {
  return fmt::format("({} line {})", source, r.begin.line);
}

class CaseReader {
 public:
  explicit CaseReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& key, const toml::node& node, const std::string& value,
                         const std::string& range) const {
    throw InvalidParameter(key + " " + where(source_, node.source()), value, range);
  }

  std::string describe(const toml::node& node) const {
    std::ostringstream s;
    if (node.is_table()) return "a table";
    if (node.is_array()) return "a list";
    node.visit([&](const auto& v) {
      if constexpr (toml::is_string<decltype(v)>) s << '"' << v.get() << '"';
      else s << v;
    });
    return s.str();
  }

  // A number: a TOML float other than nan (inf is a value: a rigid rod-E, an open distribution
  // bound), or a decimal integer (0x10, 0o7, 0b1 are refused: numbers are decimal).
  double number(const std::string& key, const toml::node& node) const {
    if (const auto* f = node.as_floating_point()) {
      if (std::isnan(f->get())) fail(key, node, describe(node), "a decimal number (nan is not a number)");
      return f->get();
    }
    if (const auto* i = node.as_integer()) {
      if (i->flags() != toml::value_flags::none)  // format_as_binary, _octal or _hexadecimal
        fail(key, node, describe(node), "a decimal number (no hexadecimal, octal or binary)");
      return static_cast<double>(i->get());
    }
    fail(key, node, describe(node), "a number");
  }

  // A count: a decimal integer in [lo, hi].
  std::size_t count(const std::string& key, const toml::node& node, std::size_t lo, std::size_t hi) const {
    const double v = number(key, node);
    if (!node.is_integer() || v < static_cast<double>(lo) || v > static_cast<double>(hi))
      fail(key, node, describe(node), fmt::format("an integer in [{}, {}]", lo, hi));
    return static_cast<std::size_t>(v);
  }

  std::string text(const std::string& key, const toml::node& node) const {
    if (const auto* s = node.as_string()) return s->get();
    fail(key, node, describe(node), "a string in quotes");
  }

  bool boolean(const std::string& key, const toml::node& node) const {
    if (const auto* b = node.as_boolean()) return b->get();
    fail(key, node, describe(node), "true or false");
  }

  const toml::table& table(const std::string& key, const toml::node& node) const {
    if (const auto* t = node.as_table()) return *t;
    fail(key, node, describe(node), "a table");
  }

  // The option a key names (command-line or Python spelling); unknown: the message lists `rig`'s
  // inputs too.
  const RunOption& option(const std::string& section, const toml::key& key, const toml::node& node,
                          const Rig* rig) const {
    const RunOption* o = find_run_option(key.str());
    if (!o) {
      std::string names;
      for (const RunOption& r : run_options()) names += (names.empty() ? "" : ", ") + r.name;
      std::string inputs;
      if (rig)
        for (const ParameterDecl& d : rig->inputs) inputs += (inputs.empty() ? "" : ", ") + std::string(d.key);
      fail(section + "." + std::string(key.str()), node, "an unknown option",
           rig ? fmt::format("an input of the rig {}: {}; or one of the simulate options: {}", rig->name, inputs, names)
               : "one of the simulate options: " + names);
    }
    return *o;
  }

  // One value of an option, typed as the option is.
  // A value of option `o`, checked against its declaration here, before any run (issue 32:
  // `rod = "stel"` in [base] failed every run instead).
  SweepValue value(const ParameterDecl& d, const std::string& key, const toml::node& node) const {
    switch (d.type) {
      case ParameterType::flag: return boolean(key, node);
      case ParameterType::text: {
        const std::string v = text(key, node);
        if (!is_declared_choice(d, v)) fail(key, node, v, "one of: " + std::string(d.choices));
        return v;
      }
      case ParameterType::number: {
        const double v = number(key, node);
        try {
          require_in_range(d, v);
        } catch (const InvalidParameter& e) {
          fail(key, node, e.value, e.valid_range);
        }
        return v;
      }
    }
    return {};
  }

  // Keys of a table in the file's order (toml++ keeps them sorted by name).
  static std::vector<std::pair<const toml::key*, const toml::node*>> in_file_order(const toml::table& t) {
    std::vector<std::pair<const toml::key*, const toml::node*>> items;
    for (const auto& [k, v] : t) items.emplace_back(&k, &v);
    std::sort(items.begin(), items.end(), [](const auto& a, const auto& b) {
      const auto &sa = a.first->source().begin, &sb = b.first->source().begin;
      return std::pair(sa.line, sa.column) < std::pair(sb.line, sb.column);
    });
    return items;
  }

  void check_keys(const std::string& section, const toml::table& t, std::initializer_list<std::string_view> allowed,
                  std::string_view what) const {
    for (const auto& [k, v] : t)
      if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
        fail(section + "." + std::string(k.str()), v, "an unknown key", std::string(what));
  }

  // A grid axis: a list of values, or a range table.
  std::vector<SweepValue> axis(const ParameterDecl& d, const std::string& key, const toml::node& node) const {
    std::vector<SweepValue> values;
    if (const auto* list = node.as_array()) {
      if (list->empty()) fail(key, node, "[]", "a list of at least one value");
      for (const toml::node& v : *list) values.push_back(value(d, key, v));
      return values;
    }
    const auto* range = node.as_table();
    const bool numeric = d.type == ParameterType::number;
    if (!range || !numeric)
      fail(key, node, describe(node),
           numeric ? "a list of values or a range { from, to, count, spacing = \"linear\" | \"log\" }" : "a list of values");
    check_keys(key, *range, {"from", "to", "count", "spacing"}, "from, to, count, spacing");
    for (const char* needed : {"from", "to", "count"})
      if (!range->contains(needed)) fail(key + "." + needed, node, "missing", "given (a range needs from, to and count)");
    const double from = number(key + ".from", *range->get("from")), to = number(key + ".to", *range->get("to"));
    const std::size_t n = count(key + ".count", *range->get("count"), 1, max_sweep_runs);
    std::string spacing = "linear";
    if (const toml::node* s = range->get("spacing")) spacing = text(key + ".spacing", *s);
    if (spacing != "linear" && spacing != "log") fail(key + ".spacing", *range->get("spacing"), spacing, "linear or log");
    for (const auto& [end, v] : {std::pair{"from", from}, std::pair{"to", to}}) {
      if (!std::isfinite(v)) fail(key + "." + end, *range->get(end), format_value(v), "a finite number");
      if (spacing == "log" && !(v > 0)) fail(key + "." + end, *range->get(end), format_value(v), "> 0 (spacing = \"log\")");
    }
    if (n == 1 && from != to) fail(key + ".count", *range->get("count"), "1", "at least 2 when from != to");
    for (std::size_t k = 0; k < n; ++k) {
      const double f = n == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(n - 1);
      // The ends exactly as written; interior points by the spacing's formula.
      const double v = k == 0 ? from : k + 1 == n ? to
                       : spacing == "log" ? from * std::pow(to / from, f)
                                          : from + f * (to - from);
      try {  // each point against the option's declaration, as a list's values are
        require_in_range(d, v);
      } catch (const InvalidParameter& e) {
        fail(key, node, e.value, e.valid_range + fmt::format(" (point {} of the range)", k + 1));
      }
      values.emplace_back(v);
    }
    return values;
  }

  InputDistribution distribution(const std::string& key, const toml::node& node) const {
    const toml::table& t = table(key, node);
    const toml::node* kind_node = t.get("distribution");
    if (!kind_node) fail(key + ".distribution", node, "missing", "given: uniform, normal or lognormal");
    const DistributionKind kind = parse_distribution_kind(text(key + ".distribution", *kind_node), key + " " + where(source_, kind_node->source()));
    auto get = [&](const char* name, std::optional<double> fallback) {
      if (const toml::node* v = t.get(name)) return number(key + "." + name, *v);
      if (!fallback) fail(key + "." + name, node, "missing", fmt::format("given for a {} distribution", to_string(kind)));
      return *fallback;
    };
    InputDistribution d;
    switch (kind) {
      case DistributionKind::uniform:
        check_keys(key, t, {"distribution", "min", "max"}, "distribution, min, max");
        d = uniform_distribution(get("min", {}), get("max", {}));
        break;
      case DistributionKind::normal:
        check_keys(key, t, {"distribution", "mean", "sd", "min", "max"}, "distribution, mean, sd, min, max");
        d = normal_distribution(get("mean", {}), get("sd", {}), get("min", -INFINITY), get("max", INFINITY));
        break;
      case DistributionKind::lognormal:
        check_keys(key, t, {"distribution", "log_mean", "log_sd", "min", "max"}, "distribution, log_mean, log_sd, min, max");
        d = lognormal_distribution(get("log_mean", {}), get("log_sd", {}), get("min", 0.0), get("max", INFINITY));
        break;
    }
    validate(d, key + " " + where(source_, node.source()));
    return d;
  }

  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

/// The input of `rig` spelled `key` (its key or Python keyword), or nullptr.
const ParameterDecl* rig_input(const Rig* rig, std::string_view key) {
  if (rig)
    for (const ParameterDecl& d : rig->inputs)
      if (d.key == key || python_keyword(d.key) == key) return &d;
  return nullptr;
}

void set_input(RigInputs& inputs, const ParameterDecl& d, const SweepValue& v) {
  if (d.type == ParameterType::number) inputs.numbers[std::string(d.key)] = std::get<double>(v);
  else inputs.texts[std::string(d.key)] = std::get<std::string>(v);
}

void set_option(RunOptions& options, const RunOption& o, const SweepValue& v) {
  switch (o.decl.type) {
    case ParameterType::flag: set_flag(options, o, std::get<bool>(v)); break;
    case ParameterType::text: set_text(options, o, std::get<std::string>(v)); break;
    case ParameterType::number: set_number(options, o, std::get<double>(v)); break;
  }
}

// The number of runs from the case's own numbers (each list's length, each range's and the
// sample's count), refused beyond max_sweep_runs before any axis or draw is made: eight axes
// of 1e7 values are refused at once, not after gigabytes of axes. A count that is no integer
// >= 1 counts 1 here; the reader refuses it with its line.
void check_run_count(const toml::table& doc, const std::string& source) {
  auto count_of = [](const toml::node* n) {
    const std::optional<std::int64_t> v = n ? n->value_exact<std::int64_t>() : std::nullopt;
    return v && *v >= 1 ? static_cast<double>(*v) : 1.0;
  };
  double runs = 1;  // a double: no overflow on the way
  if (const toml::table* grid = doc["grid"].as_table())
    for (const auto& axis : *grid) {
      if (const toml::array* list = axis.second.as_array()) runs *= std::max<double>(1, static_cast<double>(list->size()));
      else if (const toml::table* range = axis.second.as_table()) runs *= count_of(range->get("count"));
    }
  if (const toml::table* sample = doc["sample"].as_table()) runs *= count_of(sample->get("count"));
  if (runs > static_cast<double>(max_sweep_runs))
    throw InvalidParameter("the number of runs of " + source, fmt::format("{:g}", runs),
                           fmt::format("at most {} (grid points times sample count; split the case)", max_sweep_runs));
}


}  // namespace

std::size_t SweepCase::size() const {
  std::size_t n = sample ? sample->count : 1;
  for (const SweepAxis& a : grid) n *= a.values.size();
  return n;
}

std::string SweepAxis::column() const {
  if (option) return column_name(*option);
  return input_column(*rig_input);
}

std::vector<std::string> SweepCase::parameter_columns() const {
  std::vector<std::string> columns;
  for (const SweepAxis& a : grid) columns.push_back(a.column());
  if (sample)
    for (const SweepAxis& a : sample->inputs) columns.push_back(a.column());
  return columns;
}

std::vector<SweepValue> SweepCase::parameters(std::size_t run) const {
  std::vector<SweepValue> values(grid.size());
  std::size_t point = run;
  if (sample) point /= sample->count;
  for (std::size_t k = grid.size(); k-- > 0;) {  // the last axis varies fastest
    values[k] = grid[k].values[point % grid[k].values.size()];
    point /= grid[k].values.size();
  }
  if (sample) {
    const std::size_t draw = run % sample->count, d = sample->inputs.size();
    for (std::size_t j = 0; j < d; ++j) values.emplace_back(sample->values[draw * d + j]);
  }
  return values;
}

namespace {

/// f(axis, value) for every option or input run `run` of `c` varies, the grid's first.
template <class F>
void each_varied(const SweepCase& c, std::size_t run, F f) {
  const std::vector<SweepValue> values = c.parameters(run);
  std::size_t k = 0;
  for (const SweepAxis& a : c.grid) f(a, values[k++]);
  if (c.sample)
    for (const SweepAxis& a : c.sample->inputs) f(a, values[k++]);
}

}  // namespace

RunOptions SweepCase::options(std::size_t run) const {
  RunOptions o = base;
  each_varied(*this, run, [&o](const SweepAxis& a, const SweepValue& v) {
    if (a.option) set_option(o, *a.option, v);
  });
  return o;
}

RigInputs SweepCase::rig_inputs(std::size_t run) const {
  RigInputs in = rig_base;
  each_varied(*this, run, [&in](const SweepAxis& a, const SweepValue& v) {
    if (a.rig_input) set_input(in, *a.rig_input, v);
  });
  return in;
}

SweepCase parse_sweep_case(std::string_view text, const std::string& source) {
  toml::table doc;
  try {
    doc = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw DataError(fmt::format("{}:{}:{}: {}", source, e.source().begin.line, e.source().begin.column, e.description()));
  }
  const CaseReader r(source);
  SweepCase c;
  c.source = source;
  c.text = std::string(text);
  r.check_keys("case", doc, {"base", "grid", "sample", "output"}, "one of the sections [base], [grid], [sample], [output]");
  check_run_count(doc, source);
  if (const toml::table* base = doc["base"].as_table())
    if (const toml::node* rig = base->get("rig")) {
      c.rig = find_rig(r.text("base.rig", *rig));
      std::string names;
      for (const Rig& known : rigs()) names += (names.empty() ? "" : ", ") + std::string(known.name);
      if (!c.rig) r.fail("base.rig", *rig, r.describe(*rig), "a registered rig: " + names);
      c.base.integrator = c.rig->default_integrator.empty() ? c.base.integrator : std::string(c.rig->default_integrator);
    }
  // The key `section.key` names an input of the case's rig (its declaration), or else an option.
  std::vector<const void*> given;  // every option and rig input the case sets, once
  std::vector<std::pair<std::string, const toml::node*>> given_at;  // each one's key and value in the file
  auto input = [&](const std::string& section, const toml::key& k, const toml::node& node) -> const ParameterDecl* {
    const ParameterDecl* d = rig_input(c.rig, k.str());
    const std::string key = section + "." + std::string(k.str());
    if (d && std::find(given.begin(), given.end(), d) != given.end())
      r.fail(key, node, "a second value", "given once in the whole case ([base], [grid] and [sample] each set an option once)");
    if (d) {
      given.push_back(d);
      given_at.emplace_back(key, &node);
    }
    return d;
  };
  auto claim = [&](const RunOption& o, const std::string& key, const toml::node& node) {
    if (std::find(given.begin(), given.end(), &o) != given.end())
      r.fail(key, node, "a second value", "given once in the whole case ([base], [grid] and [sample] each set an option once)");
    if (o.readers.trace_only) r.fail(key, node, r.describe(node), trace_only_range("a sweep"));
    if (o.readers.flights_only)
      r.fail(key, node, r.describe(node), "given only with " + o.readers.describe() + "; a sweep runs single impacts");
    given.push_back(&o);
    given_at.emplace_back(key, &node);
  };

  if (const toml::node* base = doc.get("base")) {
    for (const auto& [k, v] : CaseReader::in_file_order(r.table("base", *base))) {
      const std::string key = "base." + std::string(k->str());
      if (k->str() == "rig") continue;
      if (const ParameterDecl* d = input("base", *k, *v)) {
        set_input(c.rig_base, *d, r.value(*d, key, *v));
        continue;
      }
      const RunOption& o = r.option("base", *k, *v, c.rig);
      claim(o, key, *v);
      set_option(c.base, o, r.value(o.decl, key, *v));
    }
  }
  if (const toml::node* grid = doc.get("grid")) {
    for (const auto& [k, v] : CaseReader::in_file_order(r.table("grid", *grid))) {
      const std::string key = "grid." + std::string(k->str());
      if (const ParameterDecl* d = input("grid", *k, *v)) {
        c.grid.push_back({.option = nullptr, .rig_input = d, .values = r.axis(*d, key, *v), .distribution = {}});
        continue;
      }
      const RunOption& o = r.option("grid", *k, *v, c.rig);
      claim(o, key, *v);
      c.grid.push_back({.option = &o, .rig_input = nullptr, .values = r.axis(o.decl, key, *v), .distribution = {}});
    }
  }
  if (const toml::node* sample_node = doc.get("sample")) {
    const toml::table& t = r.table("sample", *sample_node);
    SweepSample s;
    const toml::node* count = t.get("count");
    if (!count) r.fail("sample.count", *sample_node, "missing", "given: the number of draws, an integer >= 1");
    s.count = r.count("sample.count", *count, 1, max_sweep_runs);
    if (const toml::node* m = t.get("method")) s.method = parse_sample_method(r.text("sample.method", *m), "sample.method " + where(source, m->source()));
    if (const toml::node* seed = t.get("seed"))
      s.seed = r.count("sample.seed", *seed, 0, std::size_t{1} << 32);
    for (const auto& [k, v] : CaseReader::in_file_order(t)) {
      if (k->str() == "count" || k->str() == "method" || k->str() == "seed") continue;
      const std::string key = "sample." + std::string(k->str());
      const ParameterDecl* d = input("sample", *k, *v);
      const RunOption* o = d ? nullptr : &r.option("sample", *k, *v, c.rig);
      if ((d ? d->type : o->decl.type) != ParameterType::number)
        r.fail(key, *v, r.describe(*v), "a numeric option (a text option is varied in [grid])");
      if (o) claim(*o, key, *v);
      s.inputs.push_back({.option = o, .rig_input = d, .values = {}, .distribution = r.distribution(key, *v)});
    }
    if (s.inputs.empty())
      r.fail("sample", *sample_node, "no distribution", "at least one option with a distribution, e.g. ball-E = { distribution = \"uniform\", min = 1.2e9, max = 2.9e9 }");
    // The draws once: the quantiles of the unit-cube design, input by input.
    s.values = unit_sample(s.method, s.count, s.inputs.size(), s.seed);
    for (std::size_t i = 0; i < s.values.size(); ++i)
      s.values[i] = s.inputs[i % s.inputs.size()].distribution->quantile(s.values[i]);
    c.sample = std::move(s);
  }
  if (c.rig) {  // the rig's checks before any run: run 0, then each value of each axis in it
    auto check = [&](const RunOptions& o, const RigInputs& in) {
      try {
        check_rig_inputs(*c.rig, o, in);
      } catch (const InvalidParameter& e) {
        const ParameterDecl* d = find_rig_input(*c.rig, e.key);
        const void* what = d ? static_cast<const void*>(d) : static_cast<const void*>(find_run_option(e.key));
        const auto at = std::find(given.begin(), given.end(), what);
        if (at == given.end()) throw InvalidParameter(e.key + " (" + source + ")", e.value, e.valid_range);
        const auto& [key, node] = given_at[static_cast<std::size_t>(at - given.begin())];
        r.fail(key, *node, e.value, e.valid_range);
      }
    };
    const RunOptions options = c.options(0);
    const RigInputs inputs = c.rig_inputs(0);
    check(options, inputs);
    for (const SweepAxis& a : c.grid)
      for (const SweepValue& v : a.values) {
        RunOptions o = options;
        RigInputs in = inputs;
        if (a.option) set_option(o, *a.option, v);
        else set_input(in, *a.rig_input, v);
        check(o, in);
      }
    if (c.sample)
      for (std::size_t i = 0; i < c.sample->values.size(); ++i) {
        const SweepAxis& a = c.sample->inputs[i % c.sample->inputs.size()];
        if (!a.rig_input) continue;  // an option's draw is checked when its run is resolved
        RigInputs in = inputs;
        set_input(in, *a.rig_input, c.sample->values[i]);
        check(options, in);
      }
  }
  if (c.rig) {  // the rig's numeric results but those the varied keys' columns hold
    const std::vector<std::string> varied = c.parameter_columns();
    c.outputs.clear();
    for (const RigField& f : c.rig->results)
      if (f.number && std::find(varied.begin(), varied.end(), flat_name(f.name)) == varied.end())
        c.outputs.push_back(flat_name(f.name));
  }
  if (const toml::node* output = doc.get("output")) {
    const toml::table& t = r.table("output", *output);
    r.check_keys("output", t, {"columns", "file", "summary"}, "columns, file, summary");
    if (const toml::node* columns = t.get("columns")) {
      const toml::array* list = columns->as_array();
      std::string names;
      if (c.rig) {  // a column holds numbers: a text result is none
        for (const RigField& f : c.rig->results)
          if (f.number) names += (names.empty() ? "" : ", ") + flat_name(f.name);
      } else {
        for (const SweepOutput& o : sweep_output_table) names += (names.empty() ? "" : ", ") + std::string(o.name);
      }
      if (!list || list->empty()) r.fail("output.columns", *columns, r.describe(*columns), "a list of at least one of: " + names);
      c.outputs.clear();
      for (const toml::node& v : *list) {
        const std::string name = r.text("output.columns", v);
        const bool known = c.rig ? std::any_of(c.rig->results.begin(), c.rig->results.end(),
                                               [&](const RigField& f) { return f.number && flat_name(f.name) == name; })
                                 : find_sweep_output(name) != nullptr;
        if (!known) r.fail("output.columns", v, name, "one of: " + names);
        if (std::find(c.outputs.begin(), c.outputs.end(), name) != c.outputs.end())
          r.fail("output.columns", v, name, "listed once");
        c.outputs.push_back(name);
      }
    }
    if (const toml::node* file = t.get("file")) {
      c.output_file = r.text("output.file", *file);
      if (c.output_file.empty()) r.fail("output.file", *file, "\"\"", "a file name");
    }
    if (const toml::node* summary = t.get("summary")) c.summary = r.boolean("output.summary", *summary);
  }
  return c;
}

SweepCase read_sweep_case(const std::filesystem::path& path) {
  // Read, not sized first: a FIFO or a process substitution has no size, and a file that grows
  // while it is read is stopped at the limit.
  constexpr std::size_t max_bytes = 1 << 20;
  auto cannot_read = [&path](int error) {
    return DataError(fmt::format("{}: cannot read the case file: {}", path.string(), std::generic_category().message(error)));
  };
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw cannot_read(errno);
  std::string text(max_bytes + 1, '\0');
  errno = 0;
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw cannot_read(errno ? errno : EIO);
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > max_bytes) throw DataError(fmt::format("{}: more than 1 MiB; a case file is at most 1 MiB", path.string()));
  return parse_sweep_case(text, path.string());
}

std::filesystem::path default_sweep_output(const SweepCase& c) {
  const std::filesystem::path source(c.source);
  if (!c.output_file.empty()) return source.parent_path() / c.output_file;
  return std::filesystem::path(source).replace_extension(".csv");
}

}  // namespace hertzdash

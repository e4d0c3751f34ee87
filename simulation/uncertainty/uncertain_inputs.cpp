#include "hertzdash/simulation/uncertainty/uncertain_inputs.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <cmath>
#include <limits>

namespace hertzdash {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// The distribution of row r; every defect a DataError naming the row's file, line and parameter.
InputDistribution row_distribution(const CsvTable& t, std::size_t r, const std::string& kind, const std::string& name) {
  const std::string where = t.row_location(r) + ": parameter " + name + ": ";
  auto fail = [&](const std::string& why) { throw DataError(where + why); };
  auto field = [&](const char* column, double fallback) {
    try {
      return t.number_or(r, column, fallback);
    } catch (const DataError& e) {
      fail(std::string("distribution column '") + column + "': " + e.what());
    }
    return fallback;
  };
  auto required = [&](const char* column) {
    if (t.text(r, column).empty()) fail("a " + kind + " distribution needs column '" + column + "'");
    return field(column, NAN);
  };
  auto unused = [&](const char* column) {
    if (!t.text(r, column).empty()) fail("a " + kind + " distribution takes no '" + column + "' (see the file's header)");
  };

  DistributionKind k{};
  try {
    k = parse_distribution_kind(kind, name);
  } catch (const InvalidParameter&) {
    fail("distribution '" + kind + "' is none of: fixed, uniform, normal, lognormal");
  }
  InputDistribution d;
  switch (k) {
    case DistributionKind::uniform:
      unused("location");
      unused("scale");
      d = uniform_distribution(required("lower"), required("upper"));
      break;
    case DistributionKind::normal:
      d = normal_distribution(required("location"), required("scale"), field("lower", -infinity), field("upper", infinity));
      break;
    case DistributionKind::lognormal: {
      const double median = required("location");
      if (!(median > 0)) fail("a lognormal distribution needs a median (location) > 0");
      d = lognormal_distribution(std::log(median), required("scale"), field("lower", 0.0), field("upper", infinity));
      break;
    }
  }
  try {
    validate(d, name);
  } catch (const InvalidParameter& e) {
    fail(e.what());
  }
  return d;
}

}  // namespace

std::vector<UncertainInput> read_uncertain_inputs(const CsvTable& t) {
  t.require_columns({"parameter", "value", "unit", "distribution", "location", "scale", "lower", "upper",
                     "distribution_reason"});
  std::vector<UncertainInput> inputs;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string& name = t.text(r, "parameter");
    const std::string& kind = t.text(r, "distribution");
    if (t.text(r, "distribution_reason").empty())
      throw DataError(t.row_location(r) + ": parameter " + name + ": column 'distribution_reason' is empty: say why " +
                      (kind == "fixed" ? "it is not varied" : "this distribution"));
    if (kind == "fixed") {
      for (const char* column : {"location", "scale", "lower", "upper"})
        if (!t.text(r, column).empty())
          throw DataError(t.row_location(r) + ": parameter " + name + ": a fixed parameter takes no '" + column + "'");
      continue;
    }
    UncertainInput in{name, t.text(r, "unit"), t.number(r, "value"), row_distribution(t, r, kind, name),
                      t.text(r, "distribution_reason")};
    if (!(in.value >= in.distribution.quantile(0) && in.value <= in.distribution.quantile(1)))
      throw DataError(t.row_location(r) + ": parameter " + name + ": the assumed value " + format_value(in.value) +
                      " lies outside its distribution, " + describe(in.distribution));
    inputs.push_back(std::move(in));
  }
  return inputs;
}

}  // namespace hertzdash

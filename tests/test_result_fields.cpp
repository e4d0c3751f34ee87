// Every front end that shows an impact's result against the one table of result fields
// (simulation/run/result_fields.hpp): the keys and values of `hertzdash simulate --json`, the lines
// of simulate's text block, the columns of a sweep, and the tables of docs/json-output.md.
// (Python's simulate() and simulate_many(): tests/python/test_python_module.py.)
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/result_fields.hpp"
#include "hertzdash/simulation/sweep/sweep_outputs.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {

using hertzdash::ResultField;
using hertzdash::ResultType;
using hertzdash::result_fields;
using hertzdash::test::run_cli;
using json = nlohmann::ordered_json;

// A run given both as command-line arguments and as the library's options, and the group of
// fields it must have (empty: none).
struct Case {
  std::string args;
  hertzdash::RunOptions options;
  std::string group;
};

std::vector<Case> cases() {
  hertzdash::RunOptions rigid;
  rigid.rod = "steel";
  rigid.height_m = 0.02;
  hertzdash::RunOptions elastic = rigid;  // a fixed step: stable_step_s and step_used_s are reported
  elastic.rod_model = "elastic";
  elastic.integrator = "rk4";
  hertzdash::RunOptions iterated = rigid;
  iterated.omega_n = "self-consistent";
  hertzdash::RunOptions unchecked = rigid;  // no yield check: yield_onset_pressure_Pa is null
  unchecked.ball_yield_stress_Pa = INFINITY;
  return {{"--rod steel --height 0.02", rigid, ""},
          {"--rod steel --height 0.02 --rod-model elastic --integrator rk4", elastic, "elastic_rod"},
          {"--rod steel --height 0.02 --omega-n self-consistent", iterated, "omega_n_fixed_point"},
          {"--rod steel --height 0.02 --ball-yield-stress inf", unchecked, ""}};
}

hertzdash::SimulateRun run_in_process(const Case& c) {
  return hertzdash::run_simulate(c.options, hertzdash::load_paper_parameters());
}

json simulate_json(const std::string& args) {
  const auto r = run_cli("simulate " + args + " --json");
  REQUIRE(r.exit_code == 0);
  return json::parse(r.out);
}

std::vector<std::string> keys(const json& object) {
  std::vector<std::string> k;
  for (const auto& [key, value] : object.items()) k.push_back(key);
  return k;
}

// Whether the run has the field: a number or a group with a NaN value is left out, a field of
// an absent group likewise.
bool present(const ResultField& f, const hertzdash::SimulateRun& run) {
  if (!f.group.empty()) {
    const auto group = std::ranges::find(result_fields, f.group, &ResultField::name);
    if (!present(*group, run)) return false;
  }
  const bool may_be_absent = f.type == ResultType::number || f.type == ResultType::group;
  return !may_be_absent || !std::isnan(f.value(run.summary, run.setup));
}

// The JSON keys the table gives `group` ("" for the top level) in this run.
std::vector<std::string> table_keys(std::string_view group, const hertzdash::SimulateRun& run) {
  std::vector<std::string> k;
  for (const ResultField& f : result_fields)
    if (f.in.json && f.group == group && present(f, run)) k.emplace_back(f.name);
  return k;
}

// The JSON value of a field of the program's report.
const json& reported(const json& report, const ResultField& f) {
  return f.group.empty() ? report.at(std::string(f.name)) : report.at(std::string(f.group)).at(std::string(f.name));
}

}  // namespace

TEST_CASE("simulate --json prints the table's fields in its order, each with the impact's value", "[result_fields]") {
  for (const Case& c : cases()) {
    INFO(c.args);
    const json j = simulate_json(c.args);
    const hertzdash::SimulateRun run = run_in_process(c);
    std::vector<std::string> expected{"schema_version"};
    for (const std::string& k : table_keys("", run)) expected.push_back(k);
    expected.insert(expected.end(), {"inputs", "git_revision"});
    CHECK(keys(j) == expected);
    if (!c.group.empty()) {
      REQUIRE(j.contains(c.group));
      CHECK(keys(j.at(c.group)) == table_keys(c.group, run));
    }
    if (c.options.ball_yield_stress_Pa) CHECK(j.at("yield_onset_pressure_Pa").is_null());
    for (const ResultField& f : result_fields) {
      if (!f.in.json || !present(f, run)) continue;
      INFO(f.name);
      const json& v = reported(j, f);
      switch (f.type) {
        case ResultType::number: CHECK(v.get<double>() == f.value(run.summary, run.setup)); break;
        case ResultType::number_or_null: {
          const double expected_value = f.value(run.summary, run.setup);
          if (std::isfinite(expected_value)) CHECK(v.get<double>() == expected_value);
          else CHECK(v.is_null());
          break;
        }
        case ResultType::integer: CHECK(v.get<long>() == static_cast<long>(f.value(run.summary, run.setup))); break;
        case ResultType::boolean: CHECK(v.get<bool>() == (f.value(run.summary, run.setup) != 0)); break;
        case ResultType::integrator: CHECK(v.get<std::string>() == to_string(run.summary.integrator_used)); break;
        case ResultType::coefficients:
          REQUIRE(v.size() == run.summary.law_coefficients.size());
          for (const hertzdash::NamedValue& coefficient : run.summary.law_coefficients)
            CHECK(v.at(coefficient.name).get<double>() == coefficient.value);
          break;
        case ResultType::warnings: CHECK(v.is_array()); break;
        case ResultType::group: CHECK(v.is_object()); break;
      }
    }
  }
}

TEST_CASE("simulate's text block is the table's text lines in their order, with the JSON's values", "[result_fields]") {
  std::vector<const ResultField*> lines;
  for (const ResultField& f : result_fields)
    if (f.text_line > 0) lines.push_back(&f);
  std::ranges::sort(lines, {}, &ResultField::text_line);
  REQUIRE(!lines.empty());
  for (const Case& c : cases()) {
    INFO(c.args);
    const json j = simulate_json(c.args);
    const hertzdash::SimulateRun run = run_in_process(c);
    const auto text = run_cli("simulate " + c.args);
    REQUIRE(text.exit_code == 0);
    std::string expected;
    for (const ResultField* f : lines) {
      if (!present(*f, run)) continue;
      if (f->type == ResultType::coefficients) {
        for (const auto& [name, value] : j.at("law_coefficients").items())
          expected += "  " + hertzdash::result_text_line(name, value.get<double>()) + "\n";
      } else if (f->text) {
        expected += "  " + f->text(run.summary) + "\n";
      } else {
        expected += "  " + hertzdash::result_text_line(f->name, reported(j, *f).get<double>()) + "\n";
      }
    }
    const std::size_t heading_end = text.out.find('\n');
    REQUIRE(heading_end != std::string::npos);
    CHECK(text.out.substr(heading_end + 1) == expected);
    if (c.group == "elastic_rod") CHECK_THAT(expected, Catch::Contains("energy_balance_error_J"));
  }
}

TEST_CASE("a sweep's columns are the table's sweep fields, with simulate --json's values", "[result_fields][sweep]") {
  const hertzdash::test::ScratchDir dir;
  std::string columns;
  for (const ResultField& f : hertzdash::sweep_output_table) columns += (columns.empty() ? "\"" : ", \"") + std::string(f.name) + "\"";
  dir.write("fields.toml", "[base]\nrod = \"steel\"\nheight = 0.02\n[grid]\nrod-model = [\"rigid\", \"elastic\"]\n"
                           "[output]\ncolumns = [" + columns + "]\n");
  const auto r = hertzdash::test::run_cli_program("cd " + dir.path.string() + " && " HERTZDASH_BIN, "sweep fields.toml --quiet");
  REQUIRE(r.exit_code == 0);
  const hertzdash::CsvTable csv = hertzdash::CsvTable::read(dir.path / "fields.csv");
  std::vector<std::string> expected{"run", "rod_model"};
  for (const ResultField& f : result_fields)
    if (f.in.sweep) expected.emplace_back(f.name);
  expected.insert(expected.end(), {"warnings", "error"});
  CHECK(csv.columns() == expected);
  REQUIRE(csv.rows() == 2);
  int empty_cells = 0;
  for (std::size_t row = 0; row < csv.rows(); ++row) {
    const std::string model = csv.text(row, "rod_model");
    INFO(model);
    const json j = simulate_json("--rod steel --height 0.02 --rod-model " + model);
    for (const ResultField& f : hertzdash::sweep_output_table) {
      INFO(f.name);
      const std::string name(f.name);
      const bool in_json = f.group.empty() ? j.contains(name) : j.contains(f.group) && j.at(f.group).contains(name);
      if (!in_json) {
        CHECK(csv.text(row, name).empty());
        ++empty_cells;
        continue;
      }
      const json& v = reported(j, f);
      CHECK(csv.number(row, name) == (v.is_boolean() ? static_cast<double>(v.get<bool>()) : v.get<double>()));
    }
  }
  CHECK(empty_cells > 0);  // the rigid rod has no elastic-rod fields
}

namespace {

// The rows of docs/json-output.md for the fields of `group` ("" for the top level).
std::string docs_rows(std::string_view group) {
  std::string rows;
  for (const ResultField& f : result_fields)
    if (f.in.json && f.group == group)
      rows += fmt::format("| `{}` | {} | {} | {} |\n", f.name, hertzdash::json_type_name(f.type),
                          f.unit.empty() ? "-" : f.unit, f.meaning);
  return rows;
}

// The keys (first cells) of the first table after `heading` in `page`.
std::vector<std::string> table_keys_after(const std::string& page, const std::string& heading) {
  std::istringstream in(page.substr(page.find(heading)));
  std::vector<std::string> k;
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `", 0) == 0) {
      in_table = true;
      k.push_back(line.substr(3, line.find('`', 3) - 3));
    } else if (in_table) {
      break;
    }
  }
  return k;
}

}  // namespace

TEST_CASE("docs/json-output.md's simulate tables are the table's rows", "[result_fields][readme]") {
  const std::string page = hertzdash::test::slurp(std::filesystem::path(HERTZDASH_SOURCE_DIR) / "docs" / "json-output.md");
  for (const std::string_view group : {"", "omega_n_fixed_point", "elastic_rod"}) {
    const std::string heading = group.empty() ? "## `simulate`" : fmt::format("### `{}`", group);
    INFO(heading << "; the rows the table gives:\n" << docs_rows(group));
    REQUIRE_THAT(page, Catch::Contains(heading + "\n"));
    const std::string section = page.substr(page.find(heading));
    CHECK_THAT(section, Catch::Contains(docs_rows(group)));
    std::vector<std::string> expected;
    for (const ResultField& f : result_fields)
      if (f.in.json && f.group == group) expected.emplace_back(f.name);
    if (group.empty()) {  // the report's own keys around the impact's
      expected.insert(expected.begin(), "schema_version");
      expected.insert(expected.end(), {"inputs", "git_revision"});
    }
    CHECK(table_keys_after(page, heading) == expected);
  }
}

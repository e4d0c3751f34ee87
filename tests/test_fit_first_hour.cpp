// Issue 46, the experimentalist's first hour: a SYNTHETIC five-drop ping-pong recording (the
// suite's own: run_bounce's onsets with air drag, tests/bounce_recording_synthetic.hpp; no
// measured recording ships) fitted by one command gives the physical e with its error first, a
// verdict, and a figure whose data are the JSON's; e per bounce, drag-corrected, is the model's
// e on noise-free data where the interval ratios carry the drag's bias; a stated timing
// precision far below the scatter is a poor fit; a drop height in cm is flagged; ties share a rank.
#include "bounce_recording_synthetic.hpp"
#include "cli_runner.hpp"
#include "scratch_dir.hpp"
#include "virtual_drop_fit.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/fit_verdict.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

using namespace hertzdash;
using namespace hertzdash::test;

namespace {

// A 2.7 g ping-pong ball (R = 20 mm, a celluloid shell taken as a solid sphere of E = 2.4 GPa)
// on a steel table in air, the paper's law at input e = 0.9.
RunOptions ping_pong() {
  RunOptions o;
  o.mass_kg = 2.7e-3, o.ball_radius_m = 0.02, o.ball_E_Pa = 2.4e9, o.ball_nu = 0.35;
  o.ball_yield_stress_Pa = std::numeric_limits<double>::infinity();
  o.rod_E_Pa = 200e9, o.rod_nu = 0.3;
  o.air_density_kg_per_m3 = 1.204;
  o.restitution = 0.9;
  return o;
}
const std::string ball_options = "--mass 2.7e-3 --ball-radius 0.02 --ball-E 2.4e9 --ball-nu 0.35 --ball-yield-stress inf "
                                 "--rod-E 200e9 --rod-nu 0.3";

// Five drops of eight impacts from 0.9 to 3.1 m/s (drops of 4 to 50 cm).
const std::vector<SyntheticDrop> five_drops{{"1", 0.9, 0.1}, {"2", 1.5, 0.2}, {"3", 2.0, 0.3}, {"4", 2.6, 0.4}, {"5", 3.1, 0.5}};

// The five drops, timing jitter sigma_s.
std::string five_drops_csv(double sigma_s, unsigned seed, const std::string& height_column = "") {
  const std::vector<SyntheticDrop>& drops = five_drops;
  const BounceRecording r = synthetic_recording(ping_pong(), drops, 8, sigma_s, seed);
  std::ostringstream csv;
  csv << "drop,impact_time_s" << (height_column.empty() ? "" : ",drop_height_m") << "\n"
      << "# synthetic: true\n# source: SYNTHETIC ping-pong recording written by tests/test_fit_first_hour.cpp\n";
  for (const RecordedDrop& d : r.drops)
    for (std::size_t k = 0; k < d.impact_time_s.size(); ++k)
      csv << d.label << "," << fmt::format("{}", d.impact_time_s[k])
          << (height_column.empty() ? "" : "," + (k == 0 && d.label == "1" ? height_column : std::string())) << "\n";
  return csv.str();
}

// A column of numbers ("nan" where the writer had none).
std::vector<double> numbers(const CsvTable& c, const std::string& column) {
  std::vector<double> v;
  for (std::size_t i = 0; i < c.rows(); ++i) v.push_back(std::strtod(c.text(i, column).c_str(), nullptr));
  return v;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

TEST_CASE("a recording's fit says the physical e with its error first, a verdict, and draws e per bounce",
          "[bounce_fit][first_hour]") {
  ScratchDir dir;
  const auto rec = dir.write("ping-pong.csv", five_drops_csv(0, 0));
  const std::string fit = "fit --bounce-times " + rec.string() + " " + ball_options + " --air-density 1.204";
  const CliResult text = run_cli(fit + " --figure " + (dir.path / "e.png").string() + " --curves " +
                                 (dir.path / "e.csv").string());
  REQUIRE(text.exit_code == 0);
  const std::vector<std::string> out = lines(text.out);
  REQUIRE(out.size() > 3);
  // Line 1 names the data; no default-body notice (the ball is given).
  CHECK(out[0].find("the paper's") == std::string::npos);
  CHECK(out[1].rfind("  e_effective 0.9", 0) == 0);
  CHECK(out[1].find(" +- ") != std::string::npos);
  CHECK(out[1].find("(1 sigma)") != std::string::npos);
  CHECK(out[2].rfind("  verdict: ", 0) == 0);

  const CliResult js = run_cli(fit + " --json");
  REQUIRE(js.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(js.out);
  const double e = j["e_effective"]["value"].get<double>(), se = j["e_effective"]["standard_error"].get<double>();
  CHECK(j["fits"][0]["e_effective"] == j["e_effective"]);
  CHECK(out[1].find(fmt::format("{:.4f} +- {:.2g}", e, se)) != std::string::npos);
  CHECK(out[2] == "  verdict: " + spell_key_references(j["verdict"].get<std::string>(), KeySpelling::command_line));
  CHECK(j["default_body"].is_null());
  // Noise-free data recover the truth's e_effective (the mean velocity ratio of its impacts) to
  // the fit's accuracy: the input e to ~1e-8 (test_bounce_recording_fit's derivation), which
  // moves e by about as much; the model's gbs8 and the truth's CVODE agree to ~1e-10. And the
  // physical e is not the input e a student would otherwise report.
  CHECK(e == Approx(true_e_effective(ping_pong(), five_drops, 8)).margin(1e-7));
  CHECK(std::abs(j["fits"][0]["parameters"][0]["estimate"].get<double>() - 0.9) < 1e-7);
  CHECK(e - 0.9 > 0.01);

  // The figure is drawn (a PNG) from the curves, whose data are the JSON's: each impact's
  // residual in time, and the mean of the model's e over the impacts is e_effective.
  const std::string png = slurp(dir.path / "e.png");
  CHECK(png.rfind("\x89PNG", 0) == 0);
  const CsvTable c = CsvTable::read(dir.path / "e.csv");
  const std::vector<double> e_model = numbers(c, "e_model"), e_measured = numbers(c, "e_measured");
  const std::vector<double> residual = numbers(c, "residual_s"), t = numbers(c, "impact_time_s");
  REQUIRE(e_model.size() == j["fits"][0]["points"].size());
  double mean = 0;
  for (double x : e_model) mean += x / static_cast<double>(e_model.size());
  CHECK(mean == Approx(e).epsilon(1e-12));
  for (std::size_t i = 0; i < residual.size(); ++i) CHECK(residual[i] == j["fits"][0]["points"][i]["residual"].get<double>());

  // Drag-corrected e per bounce: on noise-free data made by the same law, e_measured is the
  // model's e to the fit's accuracy (~1e-8 in e: onsets to 1e-12 s, the estimate to 1e-8);
  // the interval ratio of two flights, which a hand-drawn figure plots, is lower by the drag's
  // loss over them: about 4 % at 3 m/s for this ball (v_t = 8.6 m/s).
  int measured = 0;
  double largest_ratio_bias = 0;
  std::string unmeasured;
  for (std::size_t i = 0; i < e_model.size(); ++i)
    if (std::isnan(e_measured[i])) unmeasured += c.text(i, "drop") + ":" + c.text(i, "impact_number") + " ";
  INFO("without e_measured: " << unmeasured);
  for (std::size_t i = 0; i < e_model.size(); ++i) {
    if (std::isnan(e_measured[i])) continue;
    ++measured;
    CHECK(std::abs(e_measured[i] - e_model[i]) < 1e-6);
    if (i + 2 >= e_model.size()) continue;
    const double ratio = (t[i + 2] - t[i + 1]) / (t[i + 1] - t[i]);
    if (c.text(i, "drop") == c.text(i + 2, "drop")) largest_ratio_bias = std::max(largest_ratio_bias, e_model[i + 1] - ratio);
  }
  INFO(c.rows() << " rows");
  CHECK(measured == 5 * 7);  // every impact but each drop's last
  CHECK(largest_ratio_bias > 0.01);
}

// Issue 46: a microphone's timing sd is about 0.2 ms; a fit whose times scatter by 13 ms about
// it is not explained by that precision: reduced chi-square about (13 / 0.2)^2 = 4e3, whose
// probability under the stated sd is nil. A recording with 1 ms of jitter fitted at its own sd is
// not poor: its reduced chi-square is chi^2_29 / 29 (40 times, 11 parameters), above 2 with
// probability 1e-3 (seeded: this draw). (13 ms on flights of 0.1-0.5 s is dirty data too: the
// check cuts drops that stop shrinking, so the 13 ms recording is no test of the good case.)
TEST_CASE("a recording whose times scatter far beyond --timing-sd is a poor fit", "[bounce_fit][first_hour]") {
  ScratchDir dir;
  const std::string fit = ball_options + " --air-density 1.204 --timing-sd ";
  const auto noisy = dir.write("noisy.csv", five_drops_csv(0.013, 7));
  const CliResult poor = run_cli("fit --bounce-times " + noisy.string() + " " + fit + "2e-4");
  INFO(poor.out << poor.err);
  REQUIRE(poor.exit_code == 0);
  CHECK(poor.err.find("warning: the model does not explain the bounce recording to its stated precision") != std::string::npos);
  CHECK(poor.out.find("poor fit: the residuals are") != std::string::npos);
  const auto clean = dir.write("clean.csv", five_drops_csv(1e-3, 7));
  const CliResult fine = run_cli("fit --bounce-times " + clean.string() + " " + fit + "1e-3");
  INFO(fine.out << fine.err);
  REQUIRE(fine.exit_code == 0);
  CHECK(fine.err.find("stated precision") == std::string::npos);
  CHECK(fine.out.find("the fit explains the data to --timing-sd 0.001 s") != std::string::npos);
  const CliResult bad = run_cli("fit --bounce-times " + clean.string() + " " + fit + "-1");
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("invalid --timing-sd = -1") != std::string::npos);
}

// A first drop 0.0405 m high (0.9 m/s) whose drop_height_m says 4.05: the height in cm written
// in metres. The fitted speed falls from 100 times less: flagged, naming the column and cm.
TEST_CASE("a drop height a hundred times the fall the times show is flagged as cm written as m",
          "[bounce_fit][first_hour]") {
  ScratchDir dir;
  const auto rec = dir.write("cm.csv", five_drops_csv(0, 0, "4.05"));
  const CliResult r = run_cli("fit --bounce-times " + rec.string() + " " + ball_options + " --air-density 1.204");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("drop '1': its drop_height_m 4.05") != std::string::npos);
  CHECK(r.err.find("a height in cm written in drop_height_m") != std::string::npos);
}

// Times in ms written in the column of seconds: a first flight of 362 "s" is no bounce; the
// refusal of the speed it implies (1965 m/s) says which column to use.
TEST_CASE("times in ms in impact_time_s are refused with a hint naming impact_time_ms", "[bounce_fit][first_hour]") {
  ScratchDir dir;
  const auto rec = dir.write("ms.csv", "drop,impact_time_s\n# source: a stopwatch\n1,203\n1,565\n1,892\n1,1187\n1,1455\n");
  const CliResult r = run_cli("fit --bounce-times " + rec.string());
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("times in ms in the column impact_time_s? name it impact_time_ms") != std::string::npos);
}

// Laws that make the same e tie in AIC to the model's accuracy, and a ranking that numbered them
// 5 to 13 was arbitrary: within aic_rank_tie of the first of a group they share its rank.
TEST_CASE("fits tied in AIC share a rank, failed fits come last", "[fit][first_hour]") {
  std::vector<FitResult> fits(5);
  const double aic[] = {-10.0, -9.995, -9.991, -5.0, 3.0};
  for (std::size_t i = 0; i < fits.size(); ++i) fits[i].aic = aic[i];
  fits[4].failed = true;
  CHECK(aic_ranks(fits) == std::vector<std::size_t>{1, 1, 1, 4, 5});
  fits[1].aic = -9.98;  // 0.02 from the first: a rank of its own, the next tied with it
  CHECK(aic_ranks(fits) == std::vector<std::size_t>{1, 2, 2, 4, 5});
}

// --figure on every fit kind and on a sweep of one key: the file is the format its extension
// names (PNG, PDF, SVG signatures), drawn whole or not at all; another extension, or a sweep of
// two keys, is refused before any work (exit 2) and leaves no file.
TEST_CASE("every fit kind and a one-key sweep draw their figure, in the format the extension names",
          "[fit][sweep][first_hour]") {
  ScratchDir dir;
  const auto trace = dir.path / "trace.csv";
  REQUIRE(run_cli("simulate --trace " + trace.string() + " --trace-format measured --noise 0.01 --integrator rk4 --dt 2e-7")
              .exit_code == 0);
  const CliResult t = run_cli("fit --trace " + trace.string() + " --figure " + (dir.path / "trace.pdf").string());
  CHECK(t.exit_code == 0);
  CHECK(slurp(dir.path / "trace.pdf").rfind("%PDF", 0) == 0);
  const auto table = dir.write("table.csv", "impact_speed_m_per_s,e\n# synthetic: true\n# source: SYNTHETIC, written by "
                                            "tests/test_fit_first_hour.cpp\n0.5,0.86\n1,0.84\n2,0.83\n4,0.80\n");
  const CliResult e = run_cli("fit --restitution-table " + table.string() + " --damping kuwabara-kono --figure " +
                              (dir.path / "table.svg").string());
  CHECK(e.exit_code == 0);
  CHECK(slurp(dir.path / "table.svg").find("<svg") != std::string::npos);
  const CliResult jpg = run_cli("fit --restitution-table " + table.string() + " --figure " + (dir.path / "t.jpg").string());
  CHECK(jpg.exit_code == 2);
  CHECK(jpg.err.find("must be a file ending in .png, .pdf or .svg") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.path / "t.jpg"));

  const auto diagram = dir.write("diagram.toml", "[base]\nrig = \"shaker\"\nimpact-model = \"instantaneous\"\nrestitution = "
                                                 "0.5\ntransient = 200\nimpacts = 8\n[grid]\ngamma = { from = 1.2, to = "
                                                 "2.0, count = 9 }\n");
  const CliResult d = run_cli("sweep " + diagram.string() + " --quiet --figure " + (dir.path / "diagram.png").string());
  CHECK(d.exit_code == 0);
  CHECK(slurp(dir.path / "diagram.png").rfind("\x89PNG", 0) == 0);
  const auto two = dir.write("two.toml", "[base]\nrestitution = 0.8\n[grid]\nheight = { from = 0.01, to = 0.02, count = "
                                         "2 }\nmass = { from = 0.5, to = 1, count = 2 }\n");
  const CliResult refused = run_cli("sweep " + two.string() + " --quiet --figure " + (dir.path / "two.png").string());
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("given for a sweep of one varied key") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.path / "two.csv"));
}

// The README's first screen is a user's own bodies: a ball on a plate, the pages they need.
TEST_CASE("the README's first screen shows a ball on a plate and links the user's pages", "[docs][first_hour]") {
  const std::string readme = slurp(std::filesystem::path(HERTZDASH_SOURCE_DIR) / "README.md");
  CHECK(readme.size() < 12000);
  std::string first_screen;
  std::istringstream in(readme);
  for (std::string line; first_screen.size() < 4000 && std::getline(in, line);) first_screen += line + "\n";
  for (const char* page : {"docs/balls.md", "docs/shaker.md", "docs/fit.md", "docs/sweep.md", "docs/python.md"})
    CHECK(first_screen.find(page) != std::string::npos);
  CHECK(first_screen.find("ball on a plate") != std::string::npos);
  CHECK(readme.find("pandas.read_csv(f, comment='#')") != std::string::npos);
}

TEST_CASE("a trace's fit reports its law's constants: those simulate gives at the fitted inputs", "[fit][first_hour]") {
  // `fit` reported the fitted ball-E and e, but the paper's c_e (or kuwabara-kono's A) only by a
  // second run of simulate. Now law_coefficients is the run at the estimate's: the same numbers
  // simulate prints for fitted_inputs (to the JSON's 17 digits, the same run).
  const ScratchDir dir;
  const auto fit = fit_json_of_virtual_drop(dir)["fits"][0];
  const auto& constants = fit["law_coefficients"];
  REQUIRE(constants.contains("c_e_coefficient_N_s_per_m_1_5"));
  const auto& in = fit["fitted_inputs"];
  const CliResult again = run_cli(fmt::format("simulate --json --ball-E {:.17g} --restitution {:.17g}",
                                              in["ball_E_Pa"].get<double>(), in["restitution"].get<double>()));
  REQUIRE(again.exit_code == 0);
  const auto simulated = nlohmann::json::parse(again.out)["law_coefficients"];
  for (const auto& [name, value] : constants.items()) {
    INFO(name);
    CHECK(value.get<double>() == Approx(simulated[name].get<double>()).epsilon(1e-12));
  }
}

// Soft against rigid impact orbits: what a finite contact time changes in their stability.
//
// The instantaneous map's multipliers come from saltation matrices; a soft contact's from the
// contact's own variational equations (simulation/orbits/stroboscopic_map.hpp, docs/orbits.md).
// The law is hunt-crossley, F = K x^{3/2} (1 + chi xdot) with chi = 3 (1 - e)/(2 v0): its
// restitution e* depends on e alone, so as the contact stiffens the soft rig tends to the
// instantaneous one with restitution e*. The contact is the paper's steel rod on a steel
// hemisphere whose moduli are multiplied by k = 1, 10, 100 (its contact time t_c ~ k^{-2/5}).
//   1. The shaker's first period doubling, by continuation in Gamma from 1.1 (e = 0.5, f = 20 Hz):
//      the soft threshold against the closed form Gamma_2(e*) of the instantaneous map, the gap
//      over t_c/T (first order in the contact time: a constant gap/(t_c/T) as k grows).
//   2. The impact oscillator near grazing (the rig's defaults, e = 0.7), by continuation in the
//      force amplitude from 10 N down through the fold and back up to grazing: the largest
//      multiplier's modulus against the orbit's impact speed. The instantaneous map's saltation
//      matrix grows like 1/(impact speed), so its multipliers diverge at grazing; a soft contact
//      has no such singularity, and its multipliers turn over where the impact speed is small
//      enough for the contact's time to matter.
//
// Writes: OUT/orbit_soft_rigid_grazing.csv (model, stiffening, force_N, impact_speed_mps,
// max_multiplier_modulus, contact_time_s), GENERATED/orbit_soft_rigid.tex (macros \softRigid...),
// GENERATED/orbit_soft_rigid_table.tex (part 1); orbit_soft_rigid.gp draws part 2.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/simulation/orbits/continuation.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"
#include "hertzdash/simulation/rigs/oscillator_rig.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "validation/common/latex_macros.hpp"
#include "validation/common/steel_rod_setups.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double frequency_Hz = 20;
constexpr const char* law = "hunt-crossley";

SolverSettings solver() { return gbs8_regularized_solver(1e-10); }

/// hunt-crossley's restitution e* at e: a contact with nothing else acting (e* does not depend on
/// the speed or the stiffness).
double restitution_of_law(double e) {
  const ContactTangent c = make_contact_tangent<HarmonicForcing>(law, stiffened_steel_pair(1, e), solver())(HarmonicForcing{}, 0.3, 1.0);
  if (!c.separated) throw std::runtime_error("the free contact did not separate");
  return c.rebound_speed_mps / 0.3;
}

/// The branches of `family` from its attractor at `from` towards `to`, the state in `scale`, and
/// the section phase they use.
struct Branches {
  Continuation continuation;
  double section_phase;
};
Branches branches(const SequenceFamily& family, double from, double to, const Eigen::Vector2d& scale) {
  const SectionGuess g = section_guess(family(from), std::nullopt, std::nullopt);
  if (!g.failure.empty()) throw std::runtime_error(fmt::format("no start at {}: {}", from, g.failure));
  return {continue_periodic_orbits(family, {.from = from, .to = to, .period = g.period, .section_phase = g.section_phase,
                                            .start = g.state, .scale = scale, .max_period = 1}),
          g.section_phase};
}

/// The contact time of the first impact of the orbit at branch point `p` [s] (0 for instantaneous impacts).
double contact_time_s(const SequenceFamily& family, const Branches& b, const BranchPoint& p) {
  const SectionImage image = StroboscopicMap(family(p.parameter), b.section_phase, p.period)(p.state);
  if (!image.failure.empty() || image.impacts.empty()) throw std::runtime_error("a branch point without its impacts");
  return image.impacts.front().contact_time_s;
}

/// The shaker at Gamma, soft (k > 0) or instantaneous with restitution e (k = 0).
SequenceFamily shaker_family(double k, double e) {
  return [k, e](double gamma) {
    ShakerOptions o;
    const DropTestSetup s = stiffened_steel_pair(k > 0 ? k : 1, e);
    o.wall = {.amplitude_m = shaker_amplitude_m(gamma, frequency_Hz, s.gravity_mps2), .frequency_Hz = frequency_Hz};
    o.impact_model = k > 0 ? ShakerImpactModel::soft : ShakerImpactModel::instantaneous;
    return make_shaker_sequence(s, law, solver(), o).spec;
  };
}

/// The oscillator at force amplitude F, soft (k > 0) or instantaneous with restitution e (k = 0).
SequenceFamily oscillator_family(double k, double e) {
  return [k, e](double force_N) {
    OscillatorOptions o;
    o.force_amplitude_N = force_N;
    o.impact_model = k > 0 ? ShakerImpactModel::soft : ShakerImpactModel::instantaneous;
    o.transient = 400;
    o.impacts = 20;
    return make_oscillator_sequence(stiffened_steel_pair(k > 0 ? k : 1, e), law, solver(), o).spec;
  };
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const double e_shaker = 0.5, e_oscillator = 0.7;
  const Parameters provenance{{"damping", law}, {"frequency_Hz", fmt::format("{}", frequency_Hz)},
                              {"restitution_shaker", fmt::format("{}", e_shaker)},
                              {"restitution_oscillator", fmt::format("{}", e_oscillator)}};
  const std::vector<double> stiffenings = args.reduced ? std::vector<double>{1} : std::vector<double>{1, 10, 100};
  LatexMacros macros("validation/orbit_soft_rigid: soft against rigid impact orbits", provenance);
  const auto start = std::chrono::steady_clock::now();

  // 1. The shaker's first period doubling, soft against the instantaneous map's closed form.
  const double e_star = restitution_of_law(e_shaker);
  const double gamma_1 = std::numbers::pi * (1 - e_star) / (1 + e_star);
  const double gamma_2 = std::hypot(gamma_1, 2 * (1 + e_star * e_star) / ((1 + e_star) * (1 + e_star)));
  macros.add("softRigidShakerRestitution", e_shaker, "{:.1f}");
  macros.add("softRigidShakerLawRestitution", e_star, "{:.4f}");
  macros.add("softRigidShakerGammaTwo", gamma_2, "{:.6f}");
  const double g = stiffened_steel_pair(1, e_shaker).gravity_mps2, T = 1 / frequency_Hz;
  std::string table = "% Generated by validation/orbit_soft_rigid; do not edit.\n"
                      "\\begin{tabular}{ccccc}\n\\toprule\n"
                      "$k$ & $t_c/T$ & $\\Gamma_2$, soft & $\\Gamma_2 - \\Gamma_2(e^*)$ & "
                      "$(\\Gamma_2 - \\Gamma_2(e^*))/(t_c/T)$ \\\\\n\\midrule\n";
  std::vector<double> gap_per_contact_time;
  for (const double k : stiffenings) {
    const SequenceFamily family = shaker_family(k, e_shaker);
    const Branches b = branches(family, 1.1, 1.35, Eigen::Vector2d(g * T * T, g * T));
    const std::vector<BranchEvent>& events = b.continuation.events;
    const auto doubling =
        std::ranges::find_if(events, [](const BranchEvent& ev) { return ev.type == BranchEventType::period_doubling; });
    if (doubling == events.end())
      throw std::runtime_error(fmt::format("no period doubling at k = {}: {}", k, b.continuation.ends.front()));
    const BranchPoint& near = *std::ranges::min_element(
        b.continuation.points, {}, [&](const BranchPoint& p) { return std::abs(p.parameter - doubling->parameter); });
    const double tc = contact_time_s(family, b, near) / T, gap = doubling->parameter - gamma_2;
    gap_per_contact_time.push_back(gap / tc);
    table += fmt::format("{:g} & {} & {:.6f} & {} & ${:.3f}$ \\\\\n", k, latex_scientific(tc), doubling->parameter,
                         latex_scientific(gap), gap / tc);
  }
  table += "\\bottomrule\n\\end{tabular}\n";
  macros.add("softRigidShakerGapPerContactTimeFirst", gap_per_contact_time.front(), "{:.3f}");
  macros.add("softRigidShakerGapPerContactTimeLast", gap_per_contact_time.back(), "{:.3f}");
  macros.add("softRigidStiffeningLast", stiffenings.back(), "{:.0f}");

  // 2. The oscillator near grazing: one row per branch point on the way back up to grazing
  // (after the fold), where the orbit is unstable and its impact speed falls to zero.
  const double e_star_oscillator = restitution_of_law(e_oscillator);
  macros.add("softRigidOscillatorRestitution", e_oscillator, "{:.1f}");
  macros.add("softRigidOscillatorLawRestitution", e_star_oscillator, "{:.4f}");
  CsvWriter grazing("hertzdash validation/orbit_soft_rigid: the impact oscillator's period-1 orbit from its fold up to "
                    "grazing, soft (hunt-crossley, steel stiffened k-fold) and instantaneous (e*), by continuation in "
                    "the force amplitude",
                    provenance,
                    {"model", "stiffening", "force_N", "impact_speed_mps", "max_multiplier_modulus", "contact_time_s"});
  std::vector<double> models{0};
  models.insert(models.end(), stiffenings.begin(), stiffenings.end());
  for (const double k : models) {
    const SequenceFamily family = oscillator_family(k, k > 0 ? e_oscillator : e_star_oscillator);
    const double v = family(10).speed_scale_mps, f = frequency_Hz;
    const Branches b = branches(family, 10, 0.5, Eigen::Vector2d(v / f, v));
    // In arclength order the branch runs down to the fold (its least force) and back up.
    const std::vector<BranchPoint>& points = b.continuation.points;
    const auto fold = std::ranges::min_element(points, {}, &BranchPoint::parameter);
    double least_speed = INFINITY, modulus_there = 0, peak = 0, peak_speed = 0;
    for (auto p = fold; p != points.end(); ++p) {
      if (p->impacts != 1) continue;
      const double modulus = std::abs(p->multipliers.front());
      grazing.add_row({std::string(k > 0 ? "soft" : "instantaneous"), k, p->parameter, p->min_impact_speed_mps, modulus,
                       k > 0 ? contact_time_s(family, b, *p) : 0.0});
      if (p->min_impact_speed_mps < least_speed) least_speed = p->min_impact_speed_mps, modulus_there = modulus;
      if (modulus > peak) peak = modulus, peak_speed = p->min_impact_speed_mps;
    }
    // Macros for the instantaneous map, the softest and the stiffest contact (one and the same in
    // a reduced run).
    std::vector<std::string> names;
    if (k == 0) names.push_back("Rigid");
    if (k > 0 && k == stiffenings.front()) names.push_back("SoftFirst");
    if (k > 0 && k == stiffenings.back()) names.push_back("SoftLast");
    for (const std::string& name : names) {
      macros.add_text("softRigidGrazing" + name + "LeastSpeed", latex_scientific(least_speed));
      macros.add("softRigidGrazing" + name + "Modulus", modulus_there, "{:.3g}");
      if (k > 0) {  // the soft curve's turning point
        macros.add("softRigidGrazing" + name + "Peak", peak, "{:.3g}");
        macros.add_text("softRigidGrazing" + name + "PeakSpeed", latex_scientific(peak_speed));
      }
    }
  }
  macros.add("softRigidSeconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), "{:.1f}");
  return save_study_outputs(args, "orbit_soft_rigid", {{"orbit_soft_rigid_grazing.csv", grazing}}, table, macros);
} catch (const std::exception& ex) {
  return study_failed(argv[0], ex);
}

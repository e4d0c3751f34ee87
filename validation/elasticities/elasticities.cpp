// Local sensitivities of the paper's impact: which input moves which result, and by how much.
//
// What it computes and why. The paper's inputs are uncertain in different degrees: the
// nylon modulus is only a catalogue range (1.2-2.9 GPa), the Poisson ratios are not given
// at all (data/assumptions.csv), e is measured, m, h and R are known well. An elasticity
// d ln y / d ln p says what a 1 % change of p does to y in per cent, so it ranks them.
// It is computed by CVODES forward sensitivity analysis of the contact phase and the
// chain rule through eqs. (3), (6), (11) (validation/common/paper_law_elasticities.hpp),
// cross-checked against central differences of the full simulation in
// tests/test_elasticities.cpp (agreement to ~1e-7).
//
// For the steel rod and duralumin rod C at h = 20 mm with their Table 2 e, zeta by eq. (6)
// and by the exact relation. Outputs:
//   elasticities.csv                         every elasticity
//   ../generated/elasticities.tex            \sensEl... macros
//   ../generated/elasticities_table.tex      the table for the paper
// What to expect (and what the output shows): without gravity the paper's e_effective
// depends on e alone (X* = (m v0^2/K)^{2/5} scales out and tau*omega_n is a function of e),
// so its elasticities to E, nu, m, h, R are of the order of g t_c / v0 ~ 1e-3; peak force and
// contact time follow the Hertz scalings K^{2/5} m^{3/5} v0^{6/5} and K^{-2/5} m^{2/5} v0^{-1/5}
// up to the same small corrections.
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "validation/common/paper_law_elasticities.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using namespace hertzdash;

namespace {

// LaTeX symbol and macro tag of each parameter.
const char* symbol(int p) {
  constexpr const char* s[] = {"$E_s$ (nylon)", "$\\nu_s$ (nylon)", "$e$", "$m$", "$h$", "$R$"};
  return s[p];
}
const char* tag(int p) {
  constexpr const char* s[] = {"BallE", "BallNu", "Restitution", "Mass", "Height", "Radius"};
  return s[p];
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);  // --reduced changes nothing: six solves
  const PaperParameters paper = load_paper_parameters();
  const ContactSensitivityOptions options;  // CVODES Adams rtol 1e-10

  const Parameters params{{"height_m", "0.02"},
                          {"restitution", "Table 2 value of each rod"},
                          {"method", "CVODES forward sensitivities (simultaneous), rtol 1e-10, event-time "
                                     "corrected; chain rule through eqs. (3), (6), (11)"},
                          {"omega_n_variant", "paper"}};
  CsvWriter csv("elasticities d ln y / d ln p of the paper's impact (validation/elasticities)", params,
                {"rod", "zeta_form", "parameter", "parameter_value", "e_effective_elasticity",
                 "peak_force_elasticity", "contact_time_elasticity"});
  LatexMacros tex("elasticities of the paper's impact (validation/elasticities)", params);

  std::string provenance = provenance_header("elasticities d ln y / d ln p, h = 20 mm, Table 2 e, zeta eq. (6) "
                                             "(validation/elasticities)",
                                             params);
  std::replace(provenance.begin(), provenance.end(), '#', '%');
  std::string table = provenance +
                      "\\begin{tabular}{lrrrrrr}\n\\toprule\n"
                      "& \\multicolumn{3}{c}{steel rod} & \\multicolumn{3}{c}{duralumin rod C}\\\\\n"
                      "\\cmidrule(lr){2-4}\\cmidrule(lr){5-7}\n"
                      "$p$ & $e_\\mathrm{eff}$ & $P_\\mathrm{max}$ & $t_c$ & $e_\\mathrm{eff}$ & $P_\\mathrm{max}$ & "
                      "$t_c$\\\\\n\\midrule\n";
  PaperLawElasticities steel_paper, dural_paper;
  for (const std::string rod : {"steel", "duralumin-c"})
    for (ZetaForm z : {ZetaForm::paper, ZetaForm::exact}) {
      DropTestSetup s = paper_setup(paper, rod, 0.020);
      s.damping.zeta_form = z;
      const PaperLawElasticities el = paper_law_elasticities(s, options);
      if (z == ZetaForm::paper) (rod == "steel" ? steel_paper : dural_paper) = el;
      for (int p = 0; p < elasticity_parameter_count; ++p) {
        csv.add_row({rod, to_string(z), std::string(elasticity_parameter_name(p)), elasticity_parameter(s, p),
                     el.e_effective_el[p], el.peak_force_el[p], el.contact_time_el[p]});
        if (z != ZetaForm::paper) continue;
        const std::string t = std::string("sensEl") + (rod == "steel" ? "Steel" : "DurC") + tag(p);
        tex.add(t + "Eeff", el.e_effective_el[p], "{:.2g}");
        tex.add(t + "Peak", el.peak_force_el[p], "{:.3f}");
        tex.add(t + "Contact", el.contact_time_el[p], "{:.3f}");
      }
    }
  for (int p = 0; p < elasticity_parameter_count; ++p) {
    auto cells = [](const PaperLawElasticities& el, int k) {
      return fmt::format("${:.2g}$ & ${:.3f}$ & ${:.3f}$", el.e_effective_el[k], el.peak_force_el[k],
                         el.contact_time_el[k]);
    };
    table += fmt::format("{} & {} & {}\\\\\n", symbol(p), cells(steel_paper, p), cells(dural_paper, p));
  }
  table += "\\bottomrule\n\\end{tabular}\n";

  // The nylon modulus is the least known input: what its catalogue range does, to first order.
  const BallData& ball = paper.ball;
  const double span = std::log(ball.E_max_Pa / ball.E_min_Pa);  // ln(2.9/1.2)
  tex.add("sensElNylonRangeLogSpan", span, "{:.2f}");
  tex.add("sensElNylonEMinGPa", 1e-9 * ball.E_min_Pa, "{:.1f}");
  tex.add("sensElNylonEMaxGPa", 1e-9 * ball.E_max_Pa, "{:.1f}");
  double largest = 0;  // e_effective's largest elasticity to anything but e
  for (const PaperLawElasticities* el : {&steel_paper, &dural_paper})
    for (int p = 0; p < elasticity_parameter_count; ++p)
      if (p != p_restitution) largest = std::max(largest, std::abs(el->e_effective_el[p]));
  tex.add("sensElEeffLargestOtherThanE", largest, "{:.2g}");
  tex.add("sensElSteelPeakOverNylonRangePct", 100.0 * (std::exp(steel_paper.peak_force_el[p_ball_E] * span) - 1.0),
          "{:.0f}");
  tex.add("sensElSteelContactOverNylonRangePct",
          100.0 * (std::exp(steel_paper.contact_time_el[p_ball_E] * span) - 1.0), "{:.0f}");

  csv.save(args.out_dir / "elasticities.csv");
  tex.save(args.generated_dir / "elasticities.tex");
  write_file_atomically(args.generated_dir / "elasticities_table.tex", table);
  std::cout << "elasticities: written to " << args.out_dir.string() << " and " << args.generated_dir.string() << "\n";
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}

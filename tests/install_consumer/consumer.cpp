// A user's program against an installed hertzdash: a damping law defined here, in no
// registry, run with simulate<MyLaw>; the installed data tables found by the library;
// a registered law by name. Exits non-zero, saying why, if a check fails.
//
// The law is the undamped Hertz contact F = K x^{3/2} written by the user, so its
// impact has closed forms (Johnson, Contact Mechanics, sec. 11.1) to check against: with
// no gravity during contact the rebound speed equals the approach speed v0 (e = 1), the
// largest deformation is x_max = (5 m v0^2 / (4 K))^{2/5}, and the contact lasts
// t_c = c x_max / v0 with c = 2 int_0^1 dz / sqrt(1 - z^{5/2}) = (4/5) B(2/5, 1/2) = 2.94325.
#include <hertzdash/simulation/run/calibrate_restitution.hpp>
#include <hertzdash/simulation/run/impact_simulator_run.hpp>  // run<Law> for a law of your own
#include <hertzdash/simulation/paper/paper_parameters.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

class MyHertzSpring {
 public:
  static constexpr hertzdash::LawInfo info{"my-hertz-spring", "a user's law", "F = K x^{3/2}", "none",
                                           "any impact", true};
  MyHertzSpring(const hertzdash::ImpactConditions& c, const hertzdash::DampingSettings&) : K_(c.K) {}
  double force(double x, double) const noexcept { return K_ * x * std::sqrt(x); }
  template <class T>  // polynomial in u = x^{1/2}, over any scalar type (double, power series)
  auto force_of_root(const T& u, const T&) const noexcept { return K_ * u * u * u; }
  std::vector<hertzdash::NamedValue> coefficients() const { return {}; }

 private:
  double K_;
};

int failures = 0;

void check(const char* what, double got, double expected, double rel_tol) {
  const bool ok = std::abs(got - expected) <= rel_tol * std::abs(expected);
  std::printf("%-40s %.12g (expected %.12g, rel. tol %g) %s\n", what, got, expected, rel_tol, ok ? "ok" : "FAILED");
  failures += !ok;
}

}  // namespace

int main() {
  using namespace hertzdash;
  const PaperParameters paper = load_paper_parameters();  // PREFIX/share/hertzdash/data
  const DropTestSetup setup = contact_phase_setup(paper_setup(paper, "steel", 0.02));
  const double K = hertz_stiffness(setup), m = setup.mass_kg, v0 = *setup.impact_velocity_mps;
  const double x_max = std::pow(5 * m * v0 * v0 / (4 * K), 0.4);
  const double c = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);

  // Tolerances: the adaptive integrators at rtol 1e-10 locate separation to ~1e-9 relative.
  for (const IntegratorKind k : {IntegratorKind::cvode, IntegratorKind::gbs8_regularized}) {
    const ImpactSummary s = simulate<MyHertzSpring>(setup, {.integrator = k, .rtol = 1e-10, .atol = 1e-14});
    std::printf("integrator %s:\n", to_string(s.integrator_used));
    check("  e_effective", s.e_effective, 1.0, 1e-6);
    check("  max_deformation_m", s.max_deformation_m, x_max, 1e-6);
    check("  contact_time_s", s.contact_time_s, c * x_max / v0, 1e-6);
  }

  // A registered law by name, through the installed registry: the paper's law. Only that it
  // separates with 0 < e_effective < 1 is asserted here; the library's own tests check its value.
  ImpactSimulator simulator(SolverSettings{});
  const double e = simulator.run(setup, "hongo").e_effective;
  std::printf("hongo e_effective %.6f\n", e);
  failures += !(e > 0.5 && e < 1.0);
  return failures == 0 ? 0 : 1;
}

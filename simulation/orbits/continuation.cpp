// Pseudo-arclength continuation of periodic orbits (simulation/orbits/continuation.hpp).
#include "hertzdash/simulation/orbits/continuation.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/orbits/section_algebra.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace hertzdash {

const char* to_string(BranchEventType type) {
  switch (type) {
    case BranchEventType::fold: return "fold";
    case BranchEventType::period_doubling: return "period-doubling";
    case BranchEventType::neimark_sacker: return "neimark-sacker";
    case BranchEventType::grazing: return "grazing";
  }
  return "";
}

namespace {

// x = (zeta, mu) of n + 1 entries for a section of dimension n, and F's n x (n + 1) Jacobian.
using Vector = Eigen::VectorXd;
using Jacobian = Eigen::MatrixXd;

constexpr double residual_tolerance = 1e-10, step_tolerance = 1e-9, mu_step = 1e-6;
constexpr double h_first = 0.01, h_most = 0.03, h_least = 1e-7, h_approach = 1e-5, h_located = 1e-12;
constexpr int max_corrector_steps = 12, located_bisections = 60;
const double most_turn_cos = std::cos(25.0 * std::numbers::pi / 180.0);
constexpr double section_margin = 1e-3;
constexpr double grazing_close = 1e-6;  // of the rig's scales: a located grazing
constexpr double grazing_near = 1e-2;   // of the rig's scales: a grazing approached, extrapolated

/// A corrected point: x, its image, Jacobian and tangent.
struct Point {
  Vector x;
  SectionImage image;
  Jacobian J;
  Vector tangent;
  int corrector_steps = 0;
};

/// A branch to follow: its start and first tangent.
struct BranchStart {
  int period;
  Point point;
  bool from_branch_point;  // a doubled branch: no events on its first step
};

class Tracer {
 public:
  Tracer(const SequenceFamily& family, const ContinuationOptions& o) : family_(family), o_(o), s_(o.scale), n_(o.scale.size()) {}

  Continuation run() {
    // Newton at mu = 0 first (natural parameter), then the tangent towards mu = 1.
    const PeriodicOrbit first = find_periodic_orbit(map(0.0, o_.period), o_.start, s_);
    if (!first.converged) throw std::runtime_error("no periodic orbit at the start: " + first.failure);
    std::optional<Point> p = point_at(scaled(first.state, 0.0), o_.period);
    if (!p) throw std::runtime_error("the start's Jacobian cannot be evaluated");
    if (p->tangent(n_) < 0) p->tangent = -p->tangent;
    std::deque<BranchStart> queue{{o_.period, *p, false}};
    for (int branch = 0; !queue.empty(); ++branch) {
      follow(branch, queue.front(), queue);
      queue.pop_front();
    }
    return std::move(out_);
  }

 private:
  double lambda(double mu) const { return o_.from + mu * (o_.to - o_.from); }
  StroboscopicMap map(double mu, int period) const { return StroboscopicMap(family_(lambda(mu)), o_.section_phase, period); }

  /// x = (z / scale, mu), and z back from x.
  Vector scaled(const Eigen::VectorXd& z, double mu) const {
    Vector x(n_ + 1);
    x << z.cwiseQuotient(s_), mu;
    return x;
  }
  Eigen::VectorXd state(const Vector& x) const { return x.head(n_).cwiseProduct(s_); }
  double mu(const Vector& x) const { return x(n_); }

  /// The image of x, or its failure (a parameter outside its range included).
  SectionImage image(const Vector& x, int period) const {
    try {
      return map(mu(x), period)(state(x));
    } catch (const InvalidParameter& e) {
      SectionImage failed;
      failed.failure = e.what();
      return failed;
    }
  }
  Eigen::VectorXd residual(const Vector& x, const SectionImage& im) const {
    return im.state.cwiseQuotient(s_) - x.head(n_);
  }
  /// The Jacobian at x (its image given), or nothing where a neighbour in mu fails.
  std::optional<Jacobian> jacobian(const Vector& x, const SectionImage& im, int period) const {
    Jacobian J(n_, n_ + 1);
    J.leftCols(n_) = s_.cwiseInverse().asDiagonal() * (im.monodromy - Eigen::MatrixXd::Identity(n_, n_)) * s_.asDiagonal();
    // Central, or one-sided where a neighbour lies past a grazing (other impacts) or its range.
    Vector up = x, down = x;
    up(n_) += mu_step, down(n_) -= mu_step;
    const SectionImage a = image(up, period), b = image(down, period);
    auto same = [&](const SectionImage& n) { return n.failure.empty() && n.impacts.size() == im.impacts.size(); };
    if (same(a) && same(b)) J.col(n_) = (residual(up, a) - residual(down, b)) / (2 * mu_step);
    else if (same(a)) J.col(n_) = (residual(up, a) - residual(x, im)) / mu_step;
    else if (same(b)) J.col(n_) = (residual(x, im) - residual(down, b)) / mu_step;
    else return std::nullopt;
    return J;
  }
  std::optional<Point> point_at(const Vector& x, int period) const {
    SectionImage im = image(x, period);
    if (!im.failure.empty()) return std::nullopt;
    const std::optional<Jacobian> J = jacobian(x, im, period);
    if (!J) return std::nullopt;
    const Vector t = section::null_vector(*J);
    if (!t.allFinite()) return std::nullopt;
    return Point{x, std::move(im), *J, t, 0};
  }

  /// The corrector from a + h t (bordered Newton), with the tangent oriented along a's; or nothing.
  std::optional<Point> correct(const Point& a, double h, int period, const Vector& direction) const {
    const Vector predicted = a.x + h * direction;
    Vector x = predicted;
    for (int k = 0; k < max_corrector_steps; ++k) {
      const SectionImage im = image(x, period);
      if (!im.failure.empty()) return std::nullopt;
      const std::optional<Jacobian> J = jacobian(x, im, period);
      if (!J) return std::nullopt;
      Eigen::MatrixXd A(n_ + 1, n_ + 1);
      A.topRows(n_) = *J;
      A.row(n_) = direction.transpose();
      Vector rhs(n_ + 1);
      rhs << -residual(x, im), -direction.dot(x - predicted);
      const Vector dx = section::solve(A, rhs);
      if (!dx.allFinite()) return std::nullopt;
      x += dx;
      if (dx.norm() < step_tolerance) {
        std::optional<Point> p = point_at(x, period);
        if (!p || residual(x, p->image).lpNorm<Eigen::Infinity>() > residual_tolerance) return std::nullopt;
        if (p->tangent.dot(direction) < 0) p->tangent = -p->tangent;
        p->corrector_steps = k + 1;
        return p;
      }
    }
    return std::nullopt;
  }

  /// Test functions of an event at a point: fold det(M - I), period doubling det(M + I),
  /// Neimark-Sacker the product of |lambda|^2 - 1 over the complex pairs (NaN without one; in two
  /// dimensions det M - 1), then the number of complex pairs: the product's sign change is a
  /// crossing only between points with as many pairs (a pair that turns real inside the circle
  /// flips it too).
  static std::array<double, 4> tests(const SectionImage& im) {
    const Eigen::MatrixXd& M = im.monodromy;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(M.rows(), M.cols());
    double product = 1;
    int pairs = 0;
    for (const std::complex<double> l : section::eigenvalues(M)) {
      if (!(l.imag() > 0)) continue;
      const double d = std::norm(l) - 1;
      // Only where it is more than round-off (e = 1 without damping: |lambda| = 1 exactly).
      if (std::abs(d) > 1e-12) product *= d, ++pairs;
    }
    return {section::det(M - I), section::det(M + I), pairs > 0 ? product : std::nan(""), static_cast<double>(pairs)};
  }

  /// Bisection on the step from a for the point where `good` turns false; the last good point.
  template <class Good>
  std::optional<Point> locate(const Point& a, double h, int period, Good&& good) const {
    double lo = 0, hi = h;
    std::optional<Point> best;
    for (int i = 0; i < located_bisections && hi - lo > h_located; ++i) {
      const double mid = 0.5 * (lo + hi);
      const std::optional<Point> p = correct(a, mid, period, a.tangent);
      if (p && good(*p)) lo = mid, best = p;
      else hi = mid;
    }
    return best ? best : std::optional<Point>(a);
  }

  void add_point(int branch, int period, const Point& p) {
    const SectionImage& im = p.image;
    BranchPoint row{.branch = branch, .period = period, .parameter = lambda(mu(p.x)),
                    .state = state(p.x),
                    .multipliers = floquet_multipliers(im.monodromy), .stable = false,
                    .impacts = static_cast<int>(im.impacts.size()), .impact_phases = {},
                    .min_impact_speed_mps = im.min_impact_speed_mps,
                    .min_flight_gap_m = im.min_flight_gap_m};
    row.stable = is_stable(row.multipliers);
    for (const SequenceImpact& i : im.impacts) row.impact_phases.push_back(i.phase);
    out_.points.push_back(std::move(row));
  }
  void add_event(BranchEventType type, int branch, int period, const Point& p) {
    out_.events.push_back({type, lambda(mu(p.x)), branch, period, state(p.x)});
  }
  /// How close an orbit is to grazing, in the rig's scales: its slowest impact, or its closest
  /// approach to a wall in flight, whichever is smaller.
  double grazing_measure(const SectionImage& im) const {
    return std::min(im.min_impact_speed_mps / s_(1), im.min_flight_gap_m / s_(0));
  }
  bool near_section(const SectionImage& im) const {
    for (const SequenceImpact& i : im.impacts) {
      const double d = std::abs(i.phase - o_.section_phase);
      if (std::min(d, 1 - d) < section_margin) return true;
    }
    return false;
  }

  void follow(int branch, const BranchStart& start, std::deque<BranchStart>& queue) {
    const int period = start.period;
    Point a = start.point;
    if (!a.image.failure.empty())
      return out_.ends.push_back(fmt::format("branch {} (period {}): no start: {}", branch, period, a.image.failure));
    add_point(branch, period, a);
    double h = h_first;
    bool first_step = start.from_branch_point, approaching = false;
    std::optional<Point> previous;
    auto end = [&](std::string why) { out_.ends.push_back(fmt::format("branch {} (period {}): {}", branch, period, why)); };
    for (;;) {
      if (static_cast<int>(out_.points.size()) >= o_.max_points) return end(fmt::format("{} points reached", o_.max_points));
      std::optional<Point> b = correct(a, h, period, a.tangent);
      const bool turned = b && b->tangent.dot(a.tangent) < most_turn_cos;
      const std::size_t n = a.image.impacts.size();
      // Grazing at a corrected point: its impacts per period differ from a's. Located by bisection
      // on the step (the side without the grazing impact converges up to it), and taken where the
      // located orbit is within grazing_close of grazing (else the corrector jumped to another
      // branch with other impacts: a shorter step follows).
      if (b && b->image.impacts.size() != n) {
        const Point g = *locate(a, h, period, [n](const Point& p) { return p.image.impacts.size() == n; });
        if (grazing_measure(g.image) < grazing_close) {
          add_point(branch, period, g);
          add_event(BranchEventType::grazing, branch, period, g);
          return end(fmt::format("grazing at {:.9g}", lambda(mu(g.x))));
        }
      }
      // Where the corrector fails and the predicted point has other impacts, grazing lies ahead on
      // the side where the map's Jacobian grows like 1/(impact speed): the steps shrink towards
      // it, and below the least step the grazing is the secant of the closest approach
      // (grazing_measure) to zero through the last two points.
      if (!b) {
        const SectionImage predicted = image(a.x + h * a.tangent, period);
        approaching = approaching || (predicted.failure.empty() && predicted.impacts.size() != n);
      }
      approaching = approaching || (b && b->image.impacts.size() != n);
      if (!b || turned || b->image.impacts.size() != n) {
        h /= 2;
        if (h >= (approaching ? h_approach : h_least)) continue;
        const double qa = grazing_measure(a.image), qp = previous ? grazing_measure(previous->image) : qa;
        // A grazing only where a predicted point had other impacts, and the orbit is near grazing
        // and nearing it (else the corrector failed for another reason).
        if (!approaching || !(qa < grazing_near) || !(qp > qa))
          return end(fmt::format("the step fell below {} at {} = {:.9g} (a corrector that does not converge)", h_least,
                                 "the parameter", lambda(mu(a.x))));
        const double mu_g = mu(a.x) - qa * (mu(a.x) - mu(previous->x)) / (qa - qp);
        Point g = a;
        g.x(n_) = mu_g;
        add_event(BranchEventType::grazing, branch, period, g);
        return end(fmt::format("grazing at {:.9g} (the secant of the slowest impact or closest flight to zero; the "
                               "last point, at {:.9g}, {:.3g} of the rig's scale from it)",
                               lambda(mu_g), lambda(mu(a.x)), qa));
      }
      if (!first_step) {
        const std::array<double, 4> ta = tests(a.image), tb = tests(b->image);
        for (int k = 0; k < 3; ++k) {
          if (!(ta[k] * tb[k] < 0)) continue;  // NaN: no complex pair at one end
          if (k == 2 && ta[3] != tb[3]) continue;  // a pair turned real or complex on the way
          const double sign_a = ta[k] < 0 ? -1 : 1;
          const Point e = *locate(a, h, period, [k, sign_a](const Point& p) { return tests(p.image)[k] * sign_a > 0; });
          const BranchEventType type = k == 0 ? BranchEventType::fold
                                       : k == 1 ? BranchEventType::period_doubling
                                                : BranchEventType::neimark_sacker;
          if (mu(e.x) < 0 || mu(e.x) > 1) continue;
          add_event(type, branch, period, e);
          if (type == BranchEventType::period_doubling && 2 * period <= o_.max_period) queue.push_back(doubled(e, period));
        }
      }
      first_step = false;
      // The range: land on mu = 1 by Newton at lambda = to, or end where the branch leaves it.
      if (mu(b->x) > 1 || mu(b->x) < 0) {
        if (mu(b->x) > 1) {
          const double f = (1 - mu(a.x)) / (mu(b->x) - mu(a.x));
          const Vector guess = a.x + f * (b->x - a.x);
          const PeriodicOrbit last = find_periodic_orbit(map(1.0, period), state(guess), s_);
          if (last.converged)
            if (std::optional<Point> p = point_at(scaled(last.state, 1.0), period))
              add_point(branch, period, *p);
          return end(fmt::format("reached {:.9g}", o_.to));
        }
        return end(fmt::format("turned back past {:.9g}", o_.from));
      }
      add_point(branch, period, *b);
      if (near_section(b->image))
        return end(fmt::format("an impact reached the section phase {:.6g} at {:.9g}: another section phase follows it further",
                               o_.section_phase, lambda(mu(b->x))));
      if (b->corrector_steps <= 3) h = std::min(1.3 * h, h_most);
      previous = std::move(a);
      a = std::move(*b);
    }
  }

  /// The branch of period 2N from a period doubling at e: along (v, 0), v the eigenvector of -1
  /// (the null vector of M + I there).
  BranchStart doubled(const Point& e, int period) const {
    const Eigen::VectorXd v = section::null_vector(e.image.monodromy + Eigen::MatrixXd::Identity(n_, n_));
    // At the branch point P^{2N}'s Jacobian has a two-dimensional null space (the old branch's
    // tangent and (v, 0)): its tangent is set, not computed.
    Point start{e.x, image(e.x, 2 * period), e.J, scaled(v, 0.0).normalized(), 0};
    return {2 * period, start, true};  // an image that failed ends the branch at once (follow)
  }

  const SequenceFamily& family_;
  const ContinuationOptions& o_;
  Eigen::VectorXd s_;
  Eigen::Index n_;  // the section's dimension
  Continuation out_;
};

}  // namespace

Continuation continue_periodic_orbits(const SequenceFamily& family, const ContinuationOptions& options) {
  if (options.start.size() != options.scale.size() || options.scale.size() < 2 || !(options.scale.array() > 0).all())
    throw std::invalid_argument("continue_periodic_orbits: a start and positive scales of the section, of one dimension");
  return Tracer(family, options).run();
}

}  // namespace hertzdash

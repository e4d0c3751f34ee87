// Pseudo-arclength continuation of periodic orbits (simulation/orbits/continuation.hpp).
#include "hertzdash/simulation/orbits/continuation.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/orbits/planar_algebra.hpp"

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

using Vector3 = Eigen::Vector3d;
using Jacobian = Eigen::Matrix<double, 2, 3>;

constexpr double residual_tolerance = 1e-10, step_tolerance = 1e-9, mu_step = 1e-6;
constexpr double h_first = 0.01, h_most = 0.03, h_least = 1e-7, h_approach = 1e-5, h_located = 1e-12;
constexpr int max_corrector_steps = 12, located_bisections = 60;
const double most_turn_cos = std::cos(25.0 * std::numbers::pi / 180.0);
constexpr double section_margin = 1e-3;
constexpr double grazing_close = 1e-6;  // of the rig's scales: a located grazing
constexpr double grazing_near = 1e-2;   // of the rig's scales: a grazing approached, extrapolated

/// A corrected point: x, its image, Jacobian and tangent.
struct Point {
  Vector3 x;
  SectionImage image;
  Jacobian J;
  Vector3 tangent;
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
  Tracer(const SequenceFamily& family, const ContinuationOptions& o) : family_(family), o_(o), s_(o.scale) {}

  Continuation run() {
    // Newton at mu = 0 first (natural parameter), then the tangent towards mu = 1.
    const PeriodicOrbit first = find_periodic_orbit(map(0.0, o_.period), o_.start, s_);
    if (!first.converged) throw std::runtime_error("no periodic orbit at the start: " + first.failure);
    std::optional<Point> p = point_at(Vector3(first.state(0) / s_(0), first.state(1) / s_(1), 0.0), o_.period);
    if (!p) throw std::runtime_error("the start's Jacobian cannot be evaluated");
    if (p->tangent(2) < 0) p->tangent = -p->tangent;
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

  /// The image of x, or its failure (a parameter outside its range included).
  SectionImage image(const Vector3& x, int period) const {
    try {
      return map(x(2), period)(Eigen::Vector2d(x(0) * s_(0), x(1) * s_(1)));
    } catch (const InvalidParameter& e) {
      SectionImage failed;
      failed.failure = e.what();
      return failed;
    }
  }
  Eigen::Vector2d residual(const Vector3& x, const SectionImage& im) const {
    return {im.state(0) / s_(0) - x(0), im.state(1) / s_(1) - x(1)};
  }
  /// The Jacobian at x (its image given), or nothing where a neighbour in mu fails.
  std::optional<Jacobian> jacobian(const Vector3& x, const SectionImage& im, int period) const {
    Jacobian J;
    J.leftCols<2>() = s_.cwiseInverse().asDiagonal() * (im.monodromy - Eigen::MatrixXd::Identity(2, 2)) * s_.asDiagonal();
    // Central, or one-sided where a neighbour lies past a grazing (other impacts) or its range.
    Vector3 up = x, down = x;
    up(2) += mu_step, down(2) -= mu_step;
    const SectionImage a = image(up, period), b = image(down, period);
    auto same = [&](const SectionImage& n) { return n.failure.empty() && n.impacts.size() == im.impacts.size(); };
    if (same(a) && same(b)) J.col(2) = (residual(up, a) - residual(down, b)) / (2 * mu_step);
    else if (same(a)) J.col(2) = (residual(up, a) - residual(x, im)) / mu_step;
    else if (same(b)) J.col(2) = (residual(x, im) - residual(down, b)) / mu_step;
    else return std::nullopt;
    return J;
  }
  std::optional<Point> point_at(const Vector3& x, int period) const {
    SectionImage im = image(x, period);
    if (!im.failure.empty()) return std::nullopt;
    const std::optional<Jacobian> J = jacobian(x, im, period);
    if (!J) return std::nullopt;
    Vector3 t = planar::cross(J->row(0).transpose(), J->row(1).transpose());
    if (!(t.norm() > 0)) return std::nullopt;
    return Point{x, std::move(im), *J, t.normalized(), 0};
  }

  /// The corrector from a + h t (bordered Newton), with the tangent oriented along a's; or nothing.
  std::optional<Point> correct(const Point& a, double h, int period, const Vector3& direction) const {
    const Vector3 predicted = a.x + h * direction;
    Vector3 x = predicted;
    for (int k = 0; k < max_corrector_steps; ++k) {
      const SectionImage im = image(x, period);
      if (!im.failure.empty()) return std::nullopt;
      const std::optional<Jacobian> J = jacobian(x, im, period);
      if (!J) return std::nullopt;
      Eigen::Matrix3d A;
      A.topRows<2>() = *J;
      A.row(2) = direction.transpose();
      Vector3 rhs;
      rhs << -residual(x, im), -direction.dot(x - predicted);
      const Vector3 dx = planar::solve(A, rhs);
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
  /// Neimark-Sacker det M - 1 (NaN unless the multipliers are complex).
  static std::array<double, 3> tests(const SectionImage& im) {
    const Eigen::Matrix2d M = im.monodromy, I = Eigen::Matrix2d::Identity();
    const double tr = M.trace(), det = planar::det(M);
    // det M - 1 only where it is more than round-off (e = 1 without damping: det M = 1 exactly).
    const bool complex = tr * tr < 4 * det && std::abs(det - 1) > 1e-12;
    return {planar::det(M - I), planar::det(M + I), complex ? det - 1 : std::nan("")};
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
    BranchPoint row{.branch = branch, .period = period, .parameter = lambda(p.x(2)),
                    .state = Eigen::Vector2d(p.x(0) * s_(0), p.x(1) * s_(1)),
                    .multipliers = floquet_multipliers(im.monodromy), .stable = false,
                    .impacts = static_cast<int>(im.impacts.size()), .impact_phases = {},
                    .min_impact_speed_mps = im.min_impact_speed_mps,
                    .min_flight_gap_m = im.min_flight_gap_m};
    row.stable = is_stable(row.multipliers);
    for (const SequenceImpact& i : im.impacts) row.impact_phases.push_back(i.phase);
    out_.points.push_back(std::move(row));
  }
  void add_event(BranchEventType type, int branch, int period, const Point& p) {
    out_.events.push_back({type, lambda(p.x(2)), branch, period, Eigen::Vector2d(p.x(0) * s_(0), p.x(1) * s_(1))});
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
          return end(fmt::format("grazing at {:.9g}", lambda(g.x(2))));
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
                                 "the parameter", lambda(a.x(2))));
        const double mu = a.x(2) - qa * (a.x(2) - previous->x(2)) / (qa - qp);
        Point g = a;
        g.x(2) = mu;
        add_event(BranchEventType::grazing, branch, period, g);
        return end(fmt::format("grazing at {:.9g} (the secant of the slowest impact or closest flight to zero; the "
                               "last point, at {:.9g}, {:.3g} of the rig's scale from it)",
                               lambda(mu), lambda(a.x(2)), qa));
      }
      if (!first_step) {
        const std::array<double, 3> ta = tests(a.image), tb = tests(b->image);
        for (int k = 0; k < 3; ++k) {
          if (!(ta[k] * tb[k] < 0)) continue;  // NaN: no complex pair at one end
          const double sign_a = ta[k] < 0 ? -1 : 1;
          const Point e = *locate(a, h, period, [k, sign_a](const Point& p) { return tests(p.image)[k] * sign_a > 0; });
          const BranchEventType type = k == 0 ? BranchEventType::fold
                                       : k == 1 ? BranchEventType::period_doubling
                                                : BranchEventType::neimark_sacker;
          const double mu = e.x(2);
          if (mu < 0 || mu > 1) continue;
          add_event(type, branch, period, e);
          if (type == BranchEventType::period_doubling && 2 * period <= o_.max_period) queue.push_back(doubled(e, period));
        }
      }
      first_step = false;
      // The range: land on mu = 1 by Newton at lambda = to, or end where the branch leaves it.
      if (b->x(2) > 1 || b->x(2) < 0) {
        if (b->x(2) > 1) {
          const double f = (1 - a.x(2)) / (b->x(2) - a.x(2));
          const Vector3 guess = a.x + f * (b->x - a.x);
          const PeriodicOrbit last = find_periodic_orbit(map(1.0, period), Eigen::Vector2d(guess(0) * s_(0), guess(1) * s_(1)), s_);
          if (last.converged)
            if (std::optional<Point> p = point_at(Vector3(last.state(0) / s_(0), last.state(1) / s_(1), 1.0), period))
              add_point(branch, period, *p);
          return end(fmt::format("reached {:.9g}", o_.to));
        }
        return end(fmt::format("turned back past {:.9g}", o_.from));
      }
      add_point(branch, period, *b);
      if (near_section(b->image))
        return end(fmt::format("an impact reached the section phase {:.6g} at {:.9g}: another section phase follows it further",
                               o_.section_phase, lambda(b->x(2))));
      if (b->corrector_steps <= 3) h = std::min(1.3 * h, h_most);
      previous = std::move(a);
      a = std::move(*b);
    }
  }

  /// The branch of period 2N from a period doubling at e: along (v, 0), v the eigenvector of -1
  /// (the null vector of M + I there).
  BranchStart doubled(const Point& e, int period) const {
    const Eigen::Vector2d v = planar::null_vector(e.image.monodromy + Eigen::Matrix2d::Identity());
    // At the branch point P^{2N}'s Jacobian has a two-dimensional null space (the old branch's
    // tangent and (v, 0)): its tangent is set, not computed.
    Point start{e.x, image(e.x, 2 * period), e.J, Vector3(v(0) / s_(0), v(1) / s_(1), 0.0).normalized(), 0};
    return {2 * period, start, true};  // an image that failed ends the branch at once (follow)
  }

  const SequenceFamily& family_;
  const ContinuationOptions& o_;
  Eigen::Vector2d s_;
  Continuation out_;
};

}  // namespace

Continuation continue_periodic_orbits(const SequenceFamily& family, const ContinuationOptions& options) {
  if (options.start.size() != 2 || options.scale.size() != 2 || !(options.scale.array() > 0).all())
    throw std::invalid_argument("continue_periodic_orbits: a start and positive scales of the 2-dimensional section");
  return Tracer(family, options).run();
}

}  // namespace hertzdash

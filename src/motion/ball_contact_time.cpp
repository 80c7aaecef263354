#include "ball_contact_time.hpp"

#include <algorithm>
#include <boost/container/static_vector.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// The ends of [0, horizon] and the real roots of a cubic, a quadratic and a linear function.
using Breakpoints = boost::container::static_vector<double, 8>;

/// The relative motion d(t) = p + v t + ½ a t² and the derivatives of ½|d|²: its rate d·d' (a cubic, negative while
/// the balls approach), the rate's slope |d'|² + d·a (a quadratic) and that one's slope 3 d'·a (linear). Each is
/// evaluated from the vectors at t rather than from polynomial coefficients, which lose the gap to cancellation
/// when |dp| is close to the contact distance.
struct RelativeMotion
{
  Eigen::Vector3d p, v, a;

  Eigen::Vector3d position(double t) const { return p + t * (v + (0.5 * t) * a); }
  Eigen::Vector3d velocity(double t) const { return v + t * a; }
  double rate(double t) const { return position(t).dot(velocity(t)); }
  double rateSlope(double t) const { return velocity(t).squaredNorm() + position(t).dot(a); }
  double rateCurvature(double t) const { return 3.0 * velocity(t).dot(a); }
};

/// The final bracket of the root of f between lo and hi (f_lo and f_hi of opposite signs, or one of them zero),
/// found with TOMS 748 to four ulps.
template <class Function>
std::pair<double, double> bracketRoot(Function f, double lo, double hi, double f_lo, double f_hi)
{
  std::uintmax_t iterations = 200;
  return boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(),
                                           iterations);
}

/// `points` with the roots at which f changes sign inserted: f is monotone between consecutive points (they hold
/// the roots of its derivative), so each such piece holds at most one root and a change of sign brackets it. Even a
/// double root is not lost: it is an extremum of f, already one of the points. The points stay, so that the next
/// function up is monotone on the finer pieces as well.
template <class Function>
Breakpoints withRoots(Function f, const Breakpoints& points)
{
  Breakpoints out{points.front()};
  double f_lo = f(points.front());
  for (std::size_t i = 1; i < points.size(); ++i)
  {
    const double f_hi = f(points[i]);
    if ((f_lo < 0.0 && f_hi > 0.0) || (f_lo > 0.0 && f_hi < 0.0))
    {
      const auto bracket = bracketRoot(f, points[i - 1], points[i], f_lo, f_hi);
      out.push_back(0.5 * (bracket.first + bracket.second));
    }
    out.push_back(points[i]);
    f_lo = f_hi;
  }
  return out;
}

/// Whether the balls approach right after t = 0: the first derivative of ½|d|² there that is not zero is negative
/// (the fourth, 3|a|², never is). A derivative within the round-off of its terms is zero: its sign is noise, such
/// as the normal speed of balls that slide past each other.
bool approachesAtStart(const RelativeMotion& m)
{
  const double round_off = 8.0 * std::numeric_limits<double>::epsilon();
  const double p = m.p.norm(), v = m.v.norm(), a = m.a.norm();
  const std::pair<double, double> derivatives[] = {
      {m.p.dot(m.v), p * v}, {m.v.squaredNorm() + m.p.dot(m.a), v * v + p * a}, {m.v.dot(m.a), v * a}};
  for (const auto& [derivative, size] : derivatives)
    if (std::abs(derivative) > round_off * size)
      return derivative < 0.0;
  return false;
}

/// A bound on the moduli of the roots of |d|² − distance² (Fujiwara's, 2 max |c_(n−k) / c_n|^(1/k) with c_0 halved,
/// from its coefficients, with a margin for their round-off). By the Gauss–Lucas theorem it bounds the roots of the
/// derivatives too, so past it the gap only grows: no contact begins there.
double rootBound(const RelativeMotion& m, double distance)
{
  const double c4 = 0.25 * m.a.squaredNorm(), c3 = m.v.dot(m.a), c2 = m.v.squaredNorm() + m.p.dot(m.a);
  const double c1 = 2.0 * m.p.dot(m.v), c0 = m.p.squaredNorm() - distance * distance;
  const double margin = 2.0 * 1.001;
  if (c4 > 0.0)
    return margin * std::max({std::abs(c3 / c4), std::sqrt(std::abs(c2 / c4)), std::cbrt(std::abs(c1 / c4)),
                              std::sqrt(std::sqrt(std::abs(c0 / (2.0 * c4))))});
  if (!m.a.isZero())
    return std::numeric_limits<double>::infinity();  // |a|² underflows: no bound
  if (c2 > 0.0)                                      // a = 0: a quadratic
    return margin * std::max(std::abs(c1 / c2), std::sqrt(std::abs(c0 / (2.0 * c2))));
  return 0.0;  // at rest relative to each other: the gap is constant
}

/// Whether the gap stays above the tolerance over [0, horizon] by the triangle inequality alone, with a margin for
/// the round-off of the bound: most pairs on a table, which need no root isolation.
bool tooFarApart(const RelativeMotion& m, double distance, double horizon)
{
  const double reach = horizon * (m.v.norm() + 0.5 * horizon * m.a.norm());
  const double gap = m.p.norm() - distance;
  return gap - BALL_TOUCHING_TOLERANCE > reach * (1.0 + 1e-9) + 1e-12 * (m.p.norm() + distance);
}

/// The contact along the pieces between `points`, on each of which the gap is monotone: the balls approach on a
/// piece if the rate is negative inside it (the gap's values cannot tell on a piece shorter than their round-off),
/// except on the first if `separating_start` (touching at 0 and not approaching). Consecutive approaching pieces
/// form one approach.
std::optional<double> contactAlong(const RelativeMotion& m, double distance, const Breakpoints& points,
                                   bool separating_start)
{
  auto gap = [&](double t) { return m.position(t).norm() - distance; };
  bool was_approaching = false;
  double g_lo = gap(points.front());
  for (std::size_t i = 1; i < points.size(); ++i)
  {
    const double lo = points[i - 1], hi = points[i], g_hi = gap(hi);
    const bool approaching = m.rate(0.5 * (lo + hi)) < 0.0 && !(i == 1 && separating_start);
    if (approaching && !was_approaching && g_lo <= BALL_TOUCHING_TOLERANCE)
      return lo;  // touching as they begin to approach
    if (approaching && g_hi <= 0.0)
      return bracketRoot(gap, lo, hi, g_lo, g_hi).second;  // the end at which the gap has closed
    if (!approaching && was_approaching && g_lo <= BALL_TOUCHING_TOLERANCE)
      return lo;  // a graze: the approach ends within the tolerance
    was_approaching = approaching;
    g_lo = g_hi;
  }
  if (was_approaching && g_lo <= BALL_TOUCHING_TOLERANCE)
    return points.back();  // the approach ends at the horizon within the tolerance
  return std::nullopt;
}
}  // namespace

double ballGap(const Eigen::Vector3d& dp, const Eigen::Vector3d& dv, const Eigen::Vector3d& da, double contact_distance,
               double t)
{
  return RelativeMotion{dp, dv, da}.position(t).norm() - contact_distance;
}

std::optional<double> earliestBallContact(const Eigen::Vector3d& dp, const Eigen::Vector3d& dv,
                                          const Eigen::Vector3d& da, double contact_distance, double horizon)
{
  const RelativeMotion m{dp, dv, da};
  if (!(horizon >= 0.0) || !dp.allFinite() || !dv.allFinite() || !da.allFinite() || !std::isfinite(contact_distance))
    return std::nullopt;
  const bool touching = dp.norm() - contact_distance <= BALL_TOUCHING_TOLERANCE;
  if (touching && approachesAtStart(m))
    return 0.0;
  const double end = std::min(horizon, rootBound(m, contact_distance));
  if (!std::isfinite(end) || (!touching && tooFarApart(m, contact_distance, end)))
    return std::nullopt;
  // The gap is monotone between the roots of the rate, the rate between those of its slope, and so on down to the
  // linear function: isolate each level's roots on the pieces of the level below.
  Breakpoints points{0.0, end};
  points = withRoots([&](double t) { return m.rateCurvature(t); }, points);
  points = withRoots([&](double t) { return m.rateSlope(t); }, points);
  points = withRoots([&](double t) { return m.rate(t); }, points);
  return contactAlong(m, contact_distance, points, touching);
}

}  // namespace detail
}  // namespace billiard_shot_planner

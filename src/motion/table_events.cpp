#include "table_events.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Times below this (s) after a segment start are the event that started it.
constexpr double MIN_EVENT_SEPARATION = 1e-12;

/// The zero of f in the bracket [lo, hi] (f changes sign between them), located with TOMS 748 to 1e-13 s: the upper
/// end of the final bracket, so that the event has numerically happened.
template <class Function>
double locateEvent(Function f, double lo, double hi, double f_lo, double f_hi)
{
  std::uintmax_t iterations = 100;
  auto tolerance = [](double a, double b) { return b - a <= 1e-13 * std::max(1.0, b); };
  return boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, tolerance, iterations).second;
}

/// The smallest root in (lo, hi] of c + b τ + ½ a τ² = 0 at which the function rises through zero, if any.
std::optional<double> firstRisingRoot(double c, double b, double a, double lo, double hi)
{
  std::optional<double> best;
  auto consider = [&](double tau)
  {
    if (tau > lo && tau <= hi && b + a * tau >= 0.0 && (!best || tau < *best))
      best = tau;
  };
  if (std::abs(a) < 1e-300)
  {
    if (b != 0.0)
      consider(-c / b);
    return best;
  }
  const double discriminant = b * b - 2.0 * a * c;
  if (discriminant < 0.0)
    return best;
  // Numerically stable pair of roots of ½a τ² + b τ + c.
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q != 0.0)
  {
    consider(q / a);
    consider(2.0 * c / q);
  }
  else
  {
    consider(0.0);
  }
  return best;
}
}  // namespace

double cushionReach(const Table& table, double radius)
{
  const double sin_theta = std::clamp((table.cushion_height - radius) / radius, -1.0, 1.0);
  return radius * std::sqrt(1.0 - sin_theta * sin_theta);
}

namespace
{
/// Guard samples of an airborne ball's approach to a nose, over the stretch where its centre is within a radius
/// of the nose line horizontally (a ball at 5 m/s covers a radius in under 6 ms).
constexpr int NOSE_SAMPLES = 32;

/// One cushion nose: the line `cushion_height` above the cloth along the edge of the playing surface, at
/// side · x(axis) = edge.
struct Nose
{
  int axis;
  double side;
  double edge;
};

Nose noseOf(int rail, const Table& table)
{
  const int axis = rail / 2;
  return {axis, rail % 2 == 0 ? -1.0 : 1.0, 0.5 * (axis == 0 ? table.length : table.width)};
}

/// On the cloth the ball's centre stays at height R, so it touches the nose exactly when its centre reaches the
/// line at `cushionReach` from the edge: a root of a quadratic.
std::optional<double> onClothContact(const MotionSegment& segment, const Nose& nose, double reach, double horizon)
{
  // g(τ) = side·x(τ) − (edge − reach): rises through zero when the ball reaches the nose moving towards it.
  const double c = nose.side * segment.start.position(nose.axis) - (nose.edge - reach);
  const double b = nose.side * segment.start.velocity(nose.axis);
  const double a = nose.side * segment.acceleration(nose.axis);
  return firstRisingRoot(c, b, a, MIN_EVENT_SEPARATION, horizon);
}

/// In the air the ball touches the nose when its centre comes within R of the nose line, which can only happen
/// while the centre is within R of the edge horizontally: the overlap R² − u² − w² (u the centre's horizontal
/// distance inside the edge, w its height above the nose) is sampled there and its rise located with TOMS 748. If
/// the centre crosses the edge first, the ball has passed over the nose (its bottom above it): that instant is
/// returned too, and the hit it reports leaves the table.
std::optional<double> airborneContact(const MotionSegment& segment, const Nose& nose, const Table& table, double radius,
                                      double horizon)
{
  const double c = nose.side * segment.start.position(nose.axis) - nose.edge;
  const double b = nose.side * segment.start.velocity(nose.axis);
  const double a = nose.side * segment.acceleration(nose.axis);
  const auto passes = firstRisingRoot(c, b, a, MIN_EVENT_SEPARATION, horizon);
  const double end = passes ? *passes : horizon;
  double start = MIN_EVENT_SEPARATION;
  if (c + radius < 0.0)
  {
    const auto near = firstRisingRoot(c + radius, b, a, MIN_EVENT_SEPARATION, end);
    if (!near)
      return passes;
    start = *near;
  }
  if (start >= end)  // a segment shorter than the events' resolution
    return passes;
  auto overlap = [&](double tau)
  {
    const Eigen::Vector3d centre = segment.at(segment.start_time + tau).position;
    const double u = nose.edge - nose.side * centre(nose.axis), w = centre.z() - table.cushion_height;
    return radius * radius - u * u - w * w;
  };
  double lo = start, f_lo = overlap(start);
  for (int k = 1; k <= NOSE_SAMPLES; ++k)
  {
    const double hi = start + (end - start) * k / NOSE_SAMPLES, f_hi = overlap(hi);
    if (f_lo <= 0.0 && f_hi > 0.0)
      return locateEvent(overlap, lo, hi, f_lo, f_hi);
    lo = hi;
    f_lo = f_hi;
  }
  return passes;
}
}  // namespace

Eigen::Vector3d cushionNormal(int rail, const Table& table, const Eigen::Vector3d& centre)
{
  const Nose nose = noseOf(rail, table);
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  normal(nose.axis) = centre(nose.axis) - nose.side * nose.edge;  // from the nose line, into the table
  normal.z() = centre.z() - table.cushion_height;
  return normal.normalized();
}

std::optional<Crossing> firstCushionHit(const MotionSegment& segment, const Table& table, double radius, double horizon)
{
  const double reach = cushionReach(table, radius);
  std::optional<Crossing> best;
  for (int rail = 0; rail < 4; ++rail)
  {
    const Nose nose = noseOf(rail, table);
    const auto tau = segment.phase == MotionPhase::Airborne ? airborneContact(segment, nose, table, radius, horizon)
                                                            : onClothContact(segment, nose, reach, horizon);
    if (tau && (!best || *tau < best->time))
      best = Crossing{*tau, rail};
  }
  return best;
}

std::optional<Crossing> firstPocketEntry(const MotionSegment& segment, const Table& table, double horizon)
{
  std::optional<Crossing> best;
  const double speed = segment.start.velocity.head<2>().norm() + segment.acceleration.head<2>().norm() * horizon;
  for (std::size_t i = 0; i < table.pockets.size(); ++i)
  {
    const Pocket& pocket = table.pockets[i];
    // Distance to the capture circle, sampled finely enough (a quarter radius of travel) to bracket an entry.
    auto outside = [&](double tau)
    { return (segment.at(segment.start_time + tau).position.head<2>() - pocket.centre).norm() - pocket.radius; };
    const double end = best ? best->time : horizon;
    const int samples = std::clamp(static_cast<int>(std::ceil(speed * end / (0.25 * pocket.radius))), 4, 100000);
    double a = 0.0, fa = outside(0.0);
    if (fa <= 0.0)
      return Crossing{0.0, static_cast<int>(i)};
    for (int k = 1; k <= samples; ++k)
    {
      const double b = end * k / samples, fb = outside(b);
      if (fb <= 0.0)
      {
        best = Crossing{locateEvent(outside, a, b, fa, fb), static_cast<int>(i)};
        break;
      }
      a = b;
      fa = fb;
    }
  }
  return best;
}

}  // namespace detail
}  // namespace billiard_shot_planner

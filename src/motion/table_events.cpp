#include "table_events.hpp"

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

Eigen::Vector3d cushionNormal(int rail, const Table& table, double radius, double z)
{
  const double sin_theta = std::clamp((table.cushion_height - z) / radius, -0.99, 0.99);
  const double cos_theta = std::sqrt(1.0 - sin_theta * sin_theta);
  Eigen::Vector3d horizontal = Eigen::Vector3d::Zero();
  horizontal(rail / 2) = rail % 2 == 0 ? 1.0 : -1.0;  // away from the rail, into the table
  return cos_theta * horizontal - sin_theta * Eigen::Vector3d::UnitZ();
}

std::optional<Crossing> firstCushionHit(const MotionSegment& segment, const Table& table, double radius, double horizon)
{
  const double reach = cushionReach(table, radius);
  const double half[2] = {0.5 * table.length - reach, 0.5 * table.width - reach};
  std::optional<Crossing> best;
  for (int rail = 0; rail < 4; ++rail)
  {
    const int axis = rail / 2;
    const double side = rail % 2 == 0 ? -1.0 : 1.0;
    // g(τ) = side·x(τ) − half: rises through zero when the ball reaches the rail moving towards it.
    const double c = side * segment.start.position(axis) - half[axis];
    const double b = side * segment.start.velocity(axis);
    const double a = side * segment.acceleration(axis);
    const auto tau = firstRisingRoot(c, b, a, MIN_EVENT_SEPARATION, horizon);
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
        std::uintmax_t iterations = 100;
        auto tolerance = [](double lo, double hi) { return hi - lo <= 1e-13 * std::max(1.0, hi); };
        const auto root = boost::math::tools::toms748_solve(outside, a, b, fa, fb, tolerance, iterations);
        best = Crossing{root.second, static_cast<int>(i)};
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

// When a ball's centre on its closed-form path first comes within a radius of a point (a pocket's capture region),
// against independent computations: the line–circle intersection of a ball in uniform motion, the stopping distance
// of a ball decelerating along a line, and a dense brute-force search along a curved (sliding, spinning) path.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "../../src/motion/table_events.hpp"

namespace bsp = billiard_shot_planner;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace
{
bsp::MotionSegment pathFrom(const Vector2d& position, const Vector2d& velocity, const Vector2d& acceleration)
{
  bsp::MotionSegment segment;
  segment.phase = bsp::MotionPhase::Sliding;
  segment.start_time = 0.0;
  segment.start.position = Vector3d(position.x(), position.y(), 0.028575);
  segment.start.velocity = Vector3d(velocity.x(), velocity.y(), 0.0);
  segment.acceleration = Vector3d(acceleration.x(), acceleration.y(), 0.0);
  return segment;
}

}  // namespace

TEST(CircleEntry, AUniformMotionEntersWhereTheLineMeetsTheCircle)
{
  // From (0, 0) at (2, 0.5) m/s towards a circle of 0.06 m around (1, 0.3): |p + v t − c| = r, a quadratic.
  const Vector2d p(0.0, 0.0), v(2.0, 0.5), c(1.0, 0.3);
  const double r = 0.06;
  const Vector2d d = p - c;
  const double qa = v.squaredNorm(), qb = 2.0 * d.dot(v), qc = d.squaredNorm() - r * r;
  const double expected = (-qb - std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
  const auto entry = bsp::detail::firstCircleEntry(pathFrom(p, v, Vector2d::Zero()), c, r, 5.0);
  ASSERT_TRUE(entry);
  EXPECT_NEAR(*entry, expected, 1e-12);
  // A horizon that ends before it: none.
  EXPECT_FALSE(bsp::detail::firstCircleEntry(pathFrom(p, v, Vector2d::Zero()), c, r, 0.9 * expected));
}

TEST(CircleEntry, ABallSlowingAlongALineEntersAtItsDistanceOrStopsShort)
{
  // Rolling along +x at 1.5 m/s, slowing at 0.15 m/s²: it covers s(t) = 1.5 t − 0.075 t² and stops after 7.5 m.
  // A circle of 0.06 m centred 2.03 m ahead, 0.02 m off the line, is first met where the line enters it.
  const Vector2d p(-1.0, 0.0), v(1.5, 0.0), a(-0.15, 0.0), c(1.03, 0.02);
  const double r = 0.06;
  const double ahead = (c.x() - p.x()) - std::sqrt(r * r - c.y() * c.y());
  const double expected = (1.5 - std::sqrt(1.5 * 1.5 - 4.0 * 0.075 * ahead)) / (2.0 * 0.075);
  const auto entry = bsp::detail::firstCircleEntry(pathFrom(p, v, a), c, r, 10.0);
  ASSERT_TRUE(entry);
  EXPECT_NEAR(*entry, expected, 1e-12);
  // The same ball slowing at 2 m/s² stops after 0.5625 m, short of it (the path turns back beyond, as the segment's
  // closed form does not: the horizon ends at the stop).
  const double stop = 1.5 / 2.0;
  EXPECT_FALSE(bsp::detail::firstCircleEntry(pathFrom(p, v, Vector2d(-2.0, 0.0)), c, r, stop));
}

TEST(CircleEntry, ACurvedPathsEntryAgreesWithADenseSearchAndGrazesAreNotStepOver)
{
  // Sliding with spin: the acceleration across the velocity bends the path (a massé curve).
  std::mt19937 random(38);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int entered = 0;
  for (int draw = 0; draw < 200; ++draw)
  {
    const Vector2d p(unit(random), 0.5 * unit(random)), v(3.0 * unit(random), 3.0 * unit(random)),
        a(2.0 * unit(random), 2.0 * unit(random));
    const double r = 0.06, horizon = 1.5;
    const bsp::MotionSegment path = pathFrom(p, v, a);
    // A region near a point of the path: about half the paths pass through it, some only just.
    const Vector2d c = path.at(horizon * (0.5 + 0.5 * unit(random))).position.head<2>() +
                       Vector2d(0.08 * unit(random), 0.08 * unit(random));
    auto outside = [&](double t) { return (path.at(t).position.head<2>() - c).norm() - r; };
    if (outside(0.0) <= 0.0)
      continue;
    // Brute force: the first of 200 000 samples inside, refined by bisection.
    std::optional<double> expected;
    const int samples = 200000;
    for (int k = 1; k <= samples && !expected; ++k)
      if (outside(horizon * k / samples) <= 0.0)
      {
        double lo = horizon * (k - 1) / samples, hi = horizon * k / samples;
        for (int i = 0; i < 60; ++i)
          (outside(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
        expected = hi;
      }
    const auto entry = bsp::detail::firstCircleEntry(path, c, r, horizon);
    ASSERT_EQ(entry.has_value(), expected.has_value()) << draw;
    if (entry)
    {
      ++entered;
      EXPECT_NEAR(*entry, *expected, 1e-12) << draw;
      EXPECT_LE(outside(*entry), 1e-15) << draw;  // it has happened, a graze within the touching gap aside
    }
  }
  EXPECT_GT(entered, 50);

  // A straight path passing 1e-8 m inside the circle's edge enters it (a chord of 69 µm, less than a tenth of the
  // travel in the 0.5 ms between the samples of a search at 2 m/s); 1e-8 m outside, beyond the touching gap, it
  // does not.
  const Vector2d c(0.5, 0.06 - 1e-8);
  const auto graze = bsp::detail::firstCircleEntry(pathFrom({0.0, 0.0}, {2.0, 0.0}, {0.0, 0.0}), c, 0.06, 1.0);
  ASSERT_TRUE(graze);
  EXPECT_NEAR(*graze, (0.5 - std::sqrt(0.06 * 0.06 - (0.06 - 1e-8) * (0.06 - 1e-8))) / 2.0, 1e-12);
  const Vector2d beside(0.5, 0.06 + 1e-8);
  EXPECT_FALSE(bsp::detail::firstCircleEntry(pathFrom({0.0, 0.0}, {2.0, 0.0}, {0.0, 0.0}), beside, 0.06, 1.0));
}

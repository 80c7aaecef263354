// Infinite state sequences (paper §7): over random collisions the solver always finishes, reports the limit of a
// chattering sequence as converged, and obeys Theorem 12 and the energy bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"

namespace bsp = billiard_shot_planner;

TEST(Chatter, RandomCollisionsTerminateAndObeyTheorem12)
{
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> mass(0.2, 5.0), restitution(0.3, 1.0), unit(-1.0, 1.0);
  int converged = 0;
  const int trials = 200;
  for (int k = 0; k < trials; ++k)
  {
    bsp::BallBallTable c;
    c.m1 = mass(rng);
    c.m2 = mass(rng);
    c.e1 = restitution(rng);
    c.e2 = restitution(rng);
    const double e = std::min(c.e1, c.e2);
    c.stiffness_ratio = std::pow(e, 2.0 * unit(rng));  // from e^2 to e^-2
    const auto result = bsp::solve(c);
    ASSERT_TRUE(result.ok()) << "trial " << k << ": " << result.error().describe();
    const auto& r = result.value();
    const double v1 = r.velocity(0), v2 = r.velocity(1);
    // Every collision ends with nothing approaching (Theorem 12: v1 ≥ v2 ≥ 0).
    EXPECT_GE(v1 - v2, -1e-9) << "trial " << k;
    EXPECT_GE(v2, -1e-9) << "trial " << k;
    EXPECT_LE(r.final_kinetic_energy, r.initial_kinetic_energy * (1.0 + 1e-12)) << "trial " << k;
    if (r.converged)
    {
      ++converged;
      // The limit is a plastic-like outcome on a compression line: v1 = v2 or v2 = 0.
      EXPECT_LT(std::min(std::abs(v1 - v2), std::abs(v2)), 1e-6) << "trial " << k;
    }
  }
  // The estimate: about one collision in five chatters.
  EXPECT_GT(converged, trials / 20);
  EXPECT_LT(converged, trials / 2);
}

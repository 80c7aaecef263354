// Infinite state sequences (paper §7): over random collisions the solver always finishes, reports the limit of a
// chattering sequence as converged, and obeys Theorem 12 and the energy bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ball_ball_table_reference.hpp"
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

namespace
{
bsp::BallBallTable randomCollision(std::mt19937& rng)
{
  std::uniform_real_distribution<double> log_mass(std::log(0.2), std::log(5.0)), restitution(0.3, 1.0), unit(-1.0, 1.0),
      speed(0.5, 2.0);
  bsp::BallBallTable c;
  c.m1 = std::exp(log_mass(rng));
  c.m2 = std::exp(log_mass(rng));
  c.e1 = restitution(rng);
  c.e2 = restitution(rng);
  c.stiffness_ratio = std::pow(10.0, unit(rng));  // 0.1 to 10
  c.v0 = -speed(rng);
  return c;
}

reference::BallBallTableOutcome referenceSolution(const bsp::BallBallTable& c)
{
  return reference::solve({c.m1, c.m2, c.stiffness_ratio, c.e1, c.e2, c.v0});
}
}  // namespace

TEST(ChatterReference, ReproducesTheConvergedValuesOfThePapersCollisions)
{
  // docs/validation.md: the paper's collisions solved in the time domain with event location (5 digits).
  const double m2 = 2.0 / std::sqrt(3.0);
  const auto table1 = referenceSolution({1.0, m2, 1.0, 0.9, 0.7, -1.0});
  EXPECT_NEAR(static_cast<double>(table1.v1), 0.61395, 5e-6);
  EXPECT_NEAR(static_cast<double>(table1.v2), 0.20972, 5e-6);
  EXPECT_EQ(table1.states, (std::vector<std::string>{"S1", "S2", "S1", "S3", "S4"}));
  const auto elastic = referenceSolution({1.0, m2, 1.0, 1.0, 1.0, -1.0});
  EXPECT_NEAR(static_cast<double>(elastic.v1), 0.94511, 5e-6);
  EXPECT_NEAR(static_cast<double>(elastic.v2), 0.30406, 5e-6);
  const double energy = 0.5 * elastic.v1 * elastic.v1 + 0.5 * m2 * elastic.v2 * elastic.v2;
  EXPECT_NEAR(energy, 0.5, 1e-15);  // nothing is lost at e = 1
  const auto restart = referenceSolution({1.0, 0.5, 1.0, 0.9, 0.7, -1.0});
  EXPECT_NEAR(static_cast<double>(restart.v1), 0.63684, 5e-6);
  EXPECT_NEAR(static_cast<double>(restart.v2), 0.15581, 5e-6);
  EXPECT_EQ(restart.states, (std::vector<std::string>{"S1", "S2", "S4"}));
  const auto ping_pong = referenceSolution({1.0, 1.0, 2.25, 0.950043, 0.846529, -2.5});
  EXPECT_NEAR(static_cast<double>(ping_pong.v1) / 2.5, 0.77799, 5e-6);
  EXPECT_NEAR(static_cast<double>(ping_pong.v2) / 2.5, 0.35104, 5e-6);
  EXPECT_EQ(ping_pong.states, (std::vector<std::string>{"S1", "S3", "S4"}));
}

TEST(ChatterReference, EngineMatchesTheExtendedPrecisionReferenceOnRandomCollisions)
{
  // The engine (closed forms in double precision) against the reference (the same model, series and bisection in
  // long double): final velocities within 1e-9 of the cue speed, chattering collisions included, and the two
  // near-ties where a chatter ends at a guard that touches zero nearly tangentially.
  std::vector<bsp::BallBallTable> collisions = {{0.7445701166465388, 0.7333162515966738, 0.5484104959910449,
                                                 0.4352675225021643, 0.5231094637743532, -1.974669286548985},
                                                {3.1127486850161477, 1.4599681378356624, 0.17218651053185755,
                                                 0.614831350220032, 0.5410660380162491, -0.9679309238210905}};
  std::mt19937 rng(2027);
  for (int k = 0; k < 300; ++k)
    collisions.push_back(randomCollision(rng));
  int chatters = 0;
  for (std::size_t k = 0; k < collisions.size(); ++k)
  {
    const bsp::BallBallTable& c = collisions[k];
    const auto exact = referenceSolution(c);
    ASSERT_TRUE(exact.finished) << "collision " << k;
    chatters += exact.chatter_limit;
    const auto solved = bsp::solve(c);
    ASSERT_TRUE(solved.ok()) << "collision " << k << ": " << solved.error().describe();
    const double scale = std::abs(c.v0);
    EXPECT_NEAR(solved.value().velocity(0), static_cast<double>(exact.v1), 1e-9 * scale)
        << "collision " << k << " (m1 " << c.m1 << ", m2 " << c.m2 << ", ratio " << c.stiffness_ratio << ", e1 " << c.e1
        << ", e2 " << c.e2 << ", v0 " << c.v0 << ")";
    EXPECT_NEAR(solved.value().velocity(1), static_cast<double>(exact.v2), 1e-9 * scale) << "collision " << k;
  }
  EXPECT_GT(chatters, 10);  // the sweep holds chattering collisions
}

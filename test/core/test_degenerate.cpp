// Degenerate collisions (docs/impact_model.md, Chatter limits and rigid links): plastic contacts and extreme
// stiffness ratios approach their closed-form limits.
#include <gtest/gtest.h>

#include <cmath>

#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
bsp::BallBallTable collision(double ratio, double e1, double e2)
{
  bsp::BallBallTable c;
  c.m2 = 2.0 / std::sqrt(3.0);
  c.stiffness_ratio = ratio;
  c.e1 = e1;
  c.e2 = e2;
  return c;
}

/// The same collision as the engine's problem with any k2/k1: the limits below go past the ratios the scenario
/// accepts ([0.01, 100], MAX_STIFFNESS_RATIO), which the engine itself does not bound.
bsp::ImpactProblem engineCollision(double ratio, double e1, double e2)
{
  bsp::ImpactProblem problem = bsp::makeImpactProblem(collision(1.0, e1, e2)).value();
  problem.contacts[1].law.stiffness = ratio;
  return problem;
}

/// k2/k1 → 0, derived from the model: the ball–ball impact completes instantly (a free two-ball impact with e1);
/// ball 2 then compresses the soft table alone and rebounds. The model reactivates a contact when its bodies
/// approach again, not when a gap closes, so as soon as ball 2 catches ball 1 (while the table spring is still
/// loaded) the ball–ball contact, infinitely stiff by comparison, carries ball 1 along: both leave with the
/// velocity that the table spring's remaining energy gives their combined mass, not as a sequence of completed
/// pairwise impacts. Valid when ball 1 rebounds and is caught.
Eigen::Vector2d softTableLimit(double m1, double m2, double e1, double e2, double v0)
{
  const double vc = m1 * v0 / (m1 + m2);
  const double v1 = vc - e1 * v0 * m2 / (m1 + m2);
  const double v2 = vc + e1 * v0 * m1 / (m1 + m2);
  const double released = e2 * e2 * 0.5 * m2 * v2 * v2;  // table energy left after its end of compression
  const double at_catch = released - 0.5 * m2 * v1 * v1;
  EXPECT_GT(v1, 0.0);
  EXPECT_GT(at_catch, 0.0);
  const double v = std::sqrt(v1 * v1 + 2.0 * at_catch / (m1 + m2));
  return {v, v};
}
}  // namespace

TEST(Degenerate, InfinitelyStiffTableMakesASingleImpact)
{
  // k2/k1 → ∞: ball 2 is part of the table, v1 = −e1 v0, v2 = 0 (the paper's footnote 16). Error shrinks with the
  // ratio.
  double previous_error = 1.0;
  for (double ratio : {1e2, 1e4, 1e6})
  {
    const auto r = bsp::solveMultipleImpact(engineCollision(ratio, 0.9, 0.7)).value();
    const double error = std::hypot(r.velocity(0) - 0.9, r.velocity(1));
    EXPECT_LT(error, previous_error) << "ratio " << ratio;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-6);
}

TEST(Degenerate, InfinitelySoftTableCarriesBothBallsTogether)
{
  const double m2 = 2.0 / std::sqrt(3.0);
  const Eigen::Vector2d limit = softTableLimit(1.0, m2, 0.9, 0.7, -1.0);
  double previous_error = 1.0;
  for (double ratio : {1e-2, 1e-4, 1e-6})
  {
    const auto r = bsp::solveMultipleImpact(engineCollision(ratio, 0.9, 0.7)).value();
    const double error = (r.velocity - limit).norm();
    EXPECT_LT(error, previous_error) << "ratio " << ratio;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-5);
}

TEST(Degenerate, PlasticContactIsTheLimitOfSmallRestitution)
{
  const auto plastic = bsp::solve(collision(1.0, 0.0, 0.7)).value();
  EXPECT_FALSE(plastic.converged);  // e = 0 is exact, not the limit of an infinite sequence
  for (double e1 : {1e-2, 1e-3})
  {
    const auto r = bsp::solve(collision(1.0, e1, 0.7)).value();
    EXPECT_LT((r.velocity - plastic.velocity).norm(), 20.0 * e1) << "e1 " << e1;
  }
  // After a plastic ball–ball compression the balls move together while pressing: the upper ball never leaves
  // faster than the lower one.
  EXPECT_GE(plastic.velocity(1) - plastic.velocity(0), -1e-12);
  EXPECT_LE(plastic.final_kinetic_energy, plastic.initial_kinetic_energy);
}

TEST(Degenerate, BothPlasticStopsEverything)
{
  const auto r = bsp::solve(collision(1.0, 0.0, 0.0)).value();
  EXPECT_NEAR(r.velocity(0), 0.0, 1e-10);
  EXPECT_NEAR(r.velocity(1), 0.0, 1e-10);
}

TEST(Degenerate, PlasticWallAbsorbsTheBall)
{
  bsp::BallChain chain{{1.0}, {2.0}, {1.0}, {0.0}, true};
  const auto r = bsp::solve(chain).value();
  EXPECT_NEAR(r.velocity(0), 0.0, 1e-12);
  EXPECT_NEAR(r.impulses[0].normal, 2.0, 1e-12);
}

// The whole prediction (strike and path) over random cue placements: every shot the cue can make is predicted,
// every other one is refused as an invalid shot, and none takes long.
#include <gtest/gtest.h>

#include <random>

#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace bsp = billiard_shot_planner;

TEST(ShotPrediction, RandomCuePlacementsArePredictedOrRefusedAsInvalidShots)
{
  // Cue tips 1 mm off the ball anywhere it faces the ball, any elevation, 0.3–7.3 m/s, anywhere on the table, for
  // cushion noses above, at and below the ball's centre height.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  int predicted = 0;
  for (int k = 0; k < 600; ++k)
  {
    bsp::ShotConfiguration configuration;
    if (k % 4 == 1)
      configuration.table.cushion_height = configuration.ball_radius;
    if (k % 4 == 2)
      configuration.table.cushion_height = 0.9 * configuration.ball_radius;
    bsp::CuePlacement cue;
    cue.ball = Eigen::Vector2d(1.1 * u(rng), 0.55 * u(rng));
    const Eigen::Vector3d centre(cue.ball.x(), cue.ball.y(), configuration.ball_radius);
    const Eigen::Vector3d normal = Eigen::Vector3d(u(rng), u(rng), unit(rng)).normalized();
    Eigen::Vector3d direction = Eigen::Vector3d(u(rng), u(rng), -unit(rng) * (k % 3 == 0 ? 1.0 : 0.3)).normalized();
    if (normal.dot(direction) > -0.05)
      direction = -normal;
    cue.direction = direction;
    cue.tip = centre + configuration.ball_radius * normal - 0.001 * direction;
    cue.speed = 0.3 + 7.0 * unit(rng);
    const auto outcome = bsp::predictShot(cue, configuration);
    if (!outcome.ok())
    {
      EXPECT_EQ(outcome.error().code, bsp::ErrorCode::InvalidShot) << k << ": " << outcome.error().describe();
      continue;
    }
    ++predicted;
    EXPECT_NE(outcome.value().trajectory.outcome, bsp::MotionOutcome::TimeLimit) << k;
  }
  EXPECT_GT(predicted, 450);
}

// Shared by the table tests: a ball's state from its place on the cloth, and a cue placed for a stroke as
// predictShot places it.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/cue_stroke.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace table_helpers
{
namespace bsp = billiard_shot_planner;

/// A ball of `radius` on the cloth at (x, y), moving with v and spinning with w.
inline bsp::BallState stateOnCloth(double radius, double x, double y,
                                   const Eigen::Vector3d& v = Eigen::Vector3d::Zero(),
                                   const Eigen::Vector3d& w = Eigen::Vector3d::Zero())
{
  bsp::BallState s;
  s.position = {x, y, radius};
  s.velocity = v;
  s.angular_velocity = w;
  return s;
}

/// A stroke on the ball of `radius` at `ball`: the tip on the ball's surface at the hit point, moving along the cue.
inline bsp::CuePlacement strokeAt(const Eigen::Vector2d& ball, double radius, const bsp::CueStroke& stroke,
                                  double speed)
{
  const auto geometry = bsp::strokeGeometry(stroke);
  EXPECT_TRUE(geometry.ok());
  bsp::CuePlacement cue;
  cue.ball = ball;
  cue.direction = geometry.value().cue_direction;
  cue.tip = Eigen::Vector3d(ball.x(), ball.y(), radius) + radius * geometry.value().hit_normal;
  cue.speed = speed;
  return cue;
}
}  // namespace table_helpers

// animationFrame(): where each ball is drawn at a time after the strike, checked against the paths it is given
// (linear interpolation between samples, a pocketed ball's free fall under gravity, rviz's DELETEALL first).
#include <gtest/gtest.h>

#include <cmath>

#include "shot_animation.hpp"

namespace bsp = billiard_shot_planner;
using visualization_msgs::Marker;

namespace
{
constexpr double RADIUS = 0.028575;

bsp::PathSample sample(double time, double x, double y)
{
  bsp::PathSample s;
  s.time = time;
  s.position.x = x;
  s.position.y = y;
  s.position.z = RADIUS;
  return s;
}

/// The cue ball rolls from (0, 0) to (1, 0) in 1 s and stops; ball "one" is knocked from (1, 0) into a pocket at
/// (1.5, 0.5), reaching it at 1.5 s.
bsp::ShotPrediction twoBalls()
{
  bsp::ShotPrediction prediction;
  prediction.header.frame_id = "table";
  bsp::BallPrediction cue;
  cue.id = "cue";
  cue.outcome = "rest";
  cue.path = {sample(0.0, 0.0, 0.0), sample(0.5, 0.6, 0.0), sample(1.0, 1.0, 0.0)};
  bsp::BallPrediction one;
  one.id = "one";
  one.outcome = "pocketed";
  one.path = {sample(0.0, 1.05, 0.0), sample(1.0, 1.05, 0.0), sample(1.5, 1.5, 0.5)};
  prediction.balls = {cue, one};
  return prediction;
}

const Marker* ballAt(const visualization_msgs::MarkerArray& frame, int index)
{
  for (const Marker& m : frame.markers)
    if (m.ns == "animation" && m.id == index)
      return &m;
  return nullptr;
}
}  // namespace

TEST(ShotAnimation, AFrameClearsThenDrawsEveryBallOnTheTable)
{
  const auto frame = bsp::animationFrame(twoBalls(), 0.0, RADIUS);
  ASSERT_EQ(frame.markers.size(), 3u);
  EXPECT_EQ(frame.markers.front().action, Marker::DELETEALL);
  const Marker* cue = ballAt(frame, 0);
  ASSERT_NE(cue, nullptr);
  EXPECT_EQ(cue->type, Marker::SPHERE);
  EXPECT_EQ(cue->header.frame_id, "table");
  EXPECT_DOUBLE_EQ(cue->scale.x, 2.0 * RADIUS);
  EXPECT_FLOAT_EQ(cue->color.b, 1.0f);  // the cue ball white
  EXPECT_LT(ballAt(frame, 1)->color.b, 0.5f);
}

TEST(ShotAnimation, BallsMoveLinearlyBetweenTheirSamplesAndHoldAtTheEnds)
{
  const bsp::ShotPrediction prediction = twoBalls();
  // At a sample: the sample; between two: the weighted mean; after the last: the last.
  EXPECT_DOUBLE_EQ(ballAt(bsp::animationFrame(prediction, 0.5, RADIUS), 0)->pose.position.x, 0.6);
  EXPECT_NEAR(ballAt(bsp::animationFrame(prediction, 0.25, RADIUS), 0)->pose.position.x, 0.3, 1e-12);
  EXPECT_NEAR(ballAt(bsp::animationFrame(prediction, 0.75, RADIUS), 0)->pose.position.x, 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(ballAt(bsp::animationFrame(prediction, 5.0, RADIUS), 0)->pose.position.x, 1.0);
  EXPECT_DOUBLE_EQ(ballAt(bsp::animationFrame(prediction, -1.0, RADIUS), 0)->pose.position.x, 0.0);
  const Marker* one = ballAt(bsp::animationFrame(prediction, 1.25, RADIUS), 1);
  EXPECT_NEAR(one->pose.position.x, 1.275, 1e-12);
  EXPECT_NEAR(one->pose.position.y, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(one->pose.position.z, RADIUS);
}

TEST(ShotAnimation, APocketedBallFallsUnderGravityThenVanishes)
{
  const bsp::ShotPrediction prediction = twoBalls();
  const double fall = 0.1;
  const Marker* one = ballAt(bsp::animationFrame(prediction, 1.5 + fall, RADIUS), 1);
  ASSERT_NE(one, nullptr);
  EXPECT_NEAR(one->pose.position.z, RADIUS - 0.5 * 9.81 * fall * fall, 1e-12);
  EXPECT_DOUBLE_EQ(one->pose.position.x, 1.5);
  EXPECT_EQ(ballAt(bsp::animationFrame(prediction, 1.5 + bsp::DROP_DURATION + 0.01, RADIUS), 1), nullptr);
  // A ball at rest does not fall.
  EXPECT_DOUBLE_EQ(ballAt(bsp::animationFrame(prediction, 3.0, RADIUS), 0)->pose.position.z, RADIUS);
}

TEST(ShotAnimation, TheLengthIsTheLongestPathAndAFall)
{
  EXPECT_DOUBLE_EQ(bsp::animationLength(twoBalls()), 1.5 + bsp::DROP_DURATION);
  EXPECT_DOUBLE_EQ(bsp::animationLength(bsp::ShotPrediction{}), 0.0);
}

TEST(ShotAnimation, ABallWithoutAPathIsLeftOut)
{
  bsp::ShotPrediction prediction = twoBalls();
  prediction.balls[1].path.clear();
  const auto frame = bsp::animationFrame(prediction, 0.2, RADIUS);
  EXPECT_EQ(frame.markers.size(), 2u);
  EXPECT_EQ(ballAt(frame, 1), nullptr);
}

TEST(ShotAnimation, PathsThatCannotBePlayedAreRefusedNamingTheBall)
{
  EXPECT_TRUE(bsp::checkAnimation(twoBalls()).ok());
  bsp::ShotPrediction backwards = twoBalls();
  backwards.balls[1].path[2].time = 0.5;
  ASSERT_FALSE(bsp::checkAnimation(backwards).ok());
  EXPECT_EQ(bsp::checkAnimation(backwards).error().field, "prediction.balls[1].path");
  bsp::ShotPrediction not_finite = twoBalls();
  not_finite.balls[0].path[1].position.y = std::nan("");
  EXPECT_EQ(bsp::checkAnimation(not_finite).error().field, "prediction.balls[0].path");
  bsp::ShotPrediction endless = twoBalls();
  endless.balls[0].path[2].time = 1e9;
  EXPECT_EQ(bsp::checkAnimation(endless).error().field, "prediction");
}

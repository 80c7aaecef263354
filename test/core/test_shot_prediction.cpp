// The whole prediction (strike and path) over random cue placements: every shot the cue can make is predicted,
// every other one is refused as an invalid shot, and none takes long.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "billiard_shot_planner/scenarios/cue_stroke.hpp"
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
      EXPECT_EQ(outcome.error().code, bsp::ErrorKind::InvalidShot) << k << ": " << outcome.error().describe();
      continue;
    }
    ++predicted;
    EXPECT_NE(outcome.value().trajectory.outcome, bsp::MotionOutcome::TimeLimit) << k;
  }
  EXPECT_GT(predicted, 450);
}

namespace
{
struct StraightIn
{
  Eigen::Vector3d arriving_velocity, arriving_spin;  ///< the cue ball's just before the collision
  double rolling_speed;                              ///< its velocity along x when it first rolls after it
};

/// A level straight-in shot along +x from the cue ball at (−0.5, 0) onto an object ball `gap` ahead of it, the tip
/// `b` radii above the centre, at cue speed `speed`.
StraightIn straightIn(double gap, double b, double speed)
{
  const bsp::ShotConfiguration configuration;
  const double R = configuration.ball_radius;
  const auto stroke = bsp::strokeGeometry({0.0, 0.0, 0.0, b});
  EXPECT_TRUE(stroke.ok());
  bsp::CuePlacement cue;
  cue.ball = Eigen::Vector2d(-0.5, 0.0);
  cue.direction = stroke.value().cue_direction;
  cue.tip = Eigen::Vector3d(cue.ball.x(), cue.ball.y(), R) + R * stroke.value().hit_normal;
  cue.speed = speed;
  bsp::BallState object;
  object.position = Eigen::Vector3d(cue.ball.x() + 2.0 * R + gap, 0.0, R);
  const auto outcome = bsp::predictShot(cue, configuration, {{"one", object}});
  EXPECT_TRUE(outcome.ok()) << outcome.error().describe();
  const bsp::BallTrajectory& cue_ball = outcome.value().table.balls[0];
  const auto& events = cue_ball.events;
  const auto hit =
      std::find_if(events.begin(), events.end(),
                   [](const bsp::MotionEvent& e) { return e.type == bsp::MotionEventType::BallCollision; });
  const auto rolls = std::find_if(
      hit, events.end(), [](const bsp::MotionEvent& e) { return e.type == bsp::MotionEventType::SlideToRoll; });
  EXPECT_TRUE(hit != events.end() && rolls != events.end());
  if (hit == events.end() || rolls == events.end())
    return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), NAN};
  const bsp::BallState arriving = cue_ball.at(std::nextafter(hit->time, 0.0));
  return {arriving.velocity, arriving.angular_velocity, rolls->state.velocity.x()};
}
}  // namespace

// The three classic straight-in shots. Right after a head-on collision of equal balls the cue ball keeps (1 − e)/2
// of its speed v and its spin ω (the normal impulse passes through its centre), and the cloth then turns that into
// rolling at (5v' + 2Rω)/7 — independent of the code: Alciatore's stun, draw and follow. The ball–ball friction on
// the contact's vertical slip Rω changes Rω by at most (5/2)μ(1 + e)/2·v (an impulse μP_n at lever R, I = 2/5 mR²)
// with μ ≤ 0.118 (Alciatore's fit at zero slip), which bounds the difference. A centre hit 1 cm away arrives with
// almost no spin and stops nearly dead; 0.6 R below the centre the ball comes back, 0.6 R above it follows through
// (at cue speeds of 2.5 and 4 m/s: slower, the cloth uses most of the back spin up over the 0.3 m).
TEST(ShotPrediction, StunStopsDrawComesBackFollowFollowsThrough)
{
  const double e = bsp::BallContactSettings{}.ball_ball.restitution, R = bsp::ShotConfiguration{}.ball_radius;
  for (double speed : {2.5, 4.0})
    for (const auto& [gap, b] : {std::pair{0.01, 0.0}, {0.3, -0.6}, {0.3, 0.6}})
    {
      const StraightIn shot = straightIn(gap, b, speed);
      const double v = shot.arriving_velocity.x(), spin = R * shot.arriving_spin.y();
      const double classical = (5.0 * 0.5 * (1.0 - e) * v + 2.0 * spin) / 7.0;
      const double bound = 2.0 / 7.0 * 2.5 * 0.118 * 0.5 * (1.0 + e) * v;
      EXPECT_NEAR(shot.rolling_speed, classical, bound) << "b " << b << ", " << speed << " m/s";
      if (b == 0.0)
        EXPECT_LE(std::abs(shot.rolling_speed), 0.03 * v) << speed << " m/s";  // stun: stops nearly dead
      else
        EXPECT_GT(b * shot.rolling_speed, 0.15 * v) << "b " << b << ", " << speed << " m/s";  // back or through
    }
}

// predictShot is strikeBall followed by predictShotAfter: the two parts give the whole prediction bit for bit, and a
// strike solved once serves every motion constant (the paths after it change, the strike does not).
TEST(ShotPrediction, TheStrikeSolvedOnceGivesTheWholePrediction)
{
  bsp::ShotConfiguration configuration;
  const double R = configuration.ball_radius;
  const auto stroke = bsp::strokeGeometry({0.4, 0.2, 0.3, -0.4});
  ASSERT_TRUE(stroke.ok());
  bsp::CuePlacement cue;
  cue.ball = Eigen::Vector2d(-0.3, 0.1);
  cue.direction = stroke.value().cue_direction;
  cue.tip = Eigen::Vector3d(cue.ball.x(), cue.ball.y(), R) + R * stroke.value().hit_normal;
  cue.speed = 2.5;
  bsp::BallState object;
  object.position = Eigen::Vector3d(0.4, 0.35, R);
  const std::vector<bsp::TableBall> others = {{"one", object}};
  const auto struck = bsp::strikeBall(cue, configuration);
  ASSERT_TRUE(struck.ok());
  for (double sliding : {0.152479, 0.25})
  {
    configuration.motion.sliding_friction = sliding;
    const auto whole = bsp::predictShot(cue, configuration, others);
    const auto after = bsp::predictShotAfter(cue, struck.value(), configuration, others);
    ASSERT_TRUE(whole.ok() && after.ok());
    ASSERT_EQ(whole->table.balls.size(), after->table.balls.size());
    for (std::size_t b = 0; b < whole->table.balls.size(); ++b)
      EXPECT_EQ(whole->table.balls[b].finalState().position, after->table.balls[b].finalState().position) << b;
    EXPECT_EQ(whole->hit_point, after->hit_point);
  }
}

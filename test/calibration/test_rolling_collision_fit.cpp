// Ball–ball collisions against a measurement of real balls: Mathavan, Jackson & Parkin 2009 (Am. J. Phys. 77(9),
// Table I), five oblique collisions of a rolling snooker cue ball with a ball at rest, both speeds measured once
// the balls roll again (test/data/measurements/). The goals: both speeds within 3 % on average and none worse than
// 10 %, with the snooker table's ball–ball contact (config/tables/snooker_mathavan.yaml).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/rolling_collision_fit.hpp"
#include "billiard_shot_planner/io/table_yaml.hpp"
#include "converging_fit.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// The paper's stated uncertainty of a speed.
constexpr double SPEED_SIGMA = 0.06;

std::vector<bsp::RollingCollision> measuredCollisions()
{
  std::ifstream file(std::string(MEASUREMENTS_DIR) + "/ball_ball_mathavan2009.csv");
  std::vector<bsp::RollingCollision> collisions;
  std::string line;
  while (std::getline(file, line))
  {
    if (line.empty() || line[0] == '#' || line[0] == 's')
      continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    int shot = 0;
    double cut_deg = 0.0;
    bsp::RollingCollision c;
    std::istringstream(line) >> shot >> c.speed_in >> cut_deg >> c.cue_speed_out >> c.object_speed_out;
    c.cut = cut_deg * M_PI / 180.0;
    collisions.push_back(c);
  }
  return collisions;
}

bsp::RollingCollisionTable snookerTable()
{
  const auto file = bsp::loadTableFile(std::string(CONFIG_DIR) + "/tables/snooker_mathavan.yaml");
  EXPECT_TRUE(file.ok()) << file.error().describe();
  bsp::RollingCollisionTable table;
  table.ball = file.value().ball;
  table.cloth = file.value().table.cloth;
  table.motion = file.value().motion;
  table.contact = file.value().ball_contact;
  return table;
}

struct RelativeErrors
{
  double mean = 0.0;
  double worst = 0.0;
  std::size_t worst_shot = 0;
};

RelativeErrors relativeErrors(const bsp::RollingCollisionTable& table,
                              const std::vector<bsp::RollingCollision>& collisions)
{
  RelativeErrors errors;
  for (std::size_t i = 0; i < collisions.size(); ++i)
  {
    const auto out = bsp::predictRollingCollision(table, collisions[i].speed_in, collisions[i].cut);
    EXPECT_TRUE(out.ok()) << out.error().describe();
    for (double error : {out.value().first / collisions[i].cue_speed_out - 1.0,
                         out.value().second / collisions[i].object_speed_out - 1.0})
    {
      errors.mean += std::abs(error) / (2.0 * static_cast<double>(collisions.size()));
      if (std::abs(error) > errors.worst)
      {
        errors.worst = std::abs(error);
        errors.worst_shot = i + 1;
      }
    }
  }
  return errors;
}
}  // namespace

TEST(RollingCollisions, TheMeasurementIsTheOnePublished)
{
  const auto collisions = measuredCollisions();
  ASSERT_EQ(collisions.size(), 5u);
  EXPECT_DOUBLE_EQ(collisions[0].speed_in, 1.539);
  EXPECT_DOUBLE_EQ(collisions[4].object_speed_out, 0.581);
}

TEST(RollingCollisions, TheSnookerTableMeetsTheMeasuredSpeeds)
{
  const RelativeErrors errors = relativeErrors(snookerTable(), measuredCollisions());
  RecordProperty("mean", std::to_string(errors.mean));
  RecordProperty("worst", std::to_string(errors.worst));
  EXPECT_LE(errors.mean, 0.03);
  EXPECT_LE(errors.worst, 0.10) << "shot " << errors.worst_shot;
}

TEST(RollingCollisions, TheVelocityDependentFrictionMissesShotOne)
{
  // Alciatore's μ(v), the pool default, on the same table: within 3 % on average but 12.5 % above the cue ball's
  // measured speed in shot 1, as pooltool's published model is (12 %).
  bsp::RollingCollisionTable table = snookerTable();
  table.contact.friction_model = bsp::BallBallFriction::Alciatore;
  table.contact.ball_ball.restitution = 0.95;
  const RelativeErrors errors = relativeErrors(table, measuredCollisions());
  EXPECT_EQ(errors.worst_shot, 1u);
  EXPECT_GT(errors.worst, 0.10);
}

TEST(RollingCollisions, TheFitFindsTheShippedContactFromAFarStart)
{
  const bsp::RollingCollisionTable shipped = snookerTable();
  bsp::RollingCollisionTable start = shipped;
  const auto fit = bsp::fitRollingCollisions(
      start, {{"ball_ball.restitution", 0.9, 0.5, 1.0}, {"ball_ball.friction", 0.02, 0.0, 0.5}}, measuredCollisions(),
      SPEED_SIGMA, convergingFit());
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  EXPECT_NEAR(fit.value().parameters[0].value, shipped.contact.ball_ball.restitution, 0.01);
  EXPECT_NEAR(fit.value().parameters[1].value, shipped.contact.ball_ball.friction, 0.005);
  EXPECT_TRUE(fit.value().explains_data) << "chi2/dof " << fit.value().chi2_per_dof;
}

TEST(RollingCollisions, BadInputNamesTheField)
{
  const bsp::RollingCollisionTable table;
  EXPECT_EQ(bsp::predictRollingCollision(table, 1.0, 2.0).error().field, "cut");
  EXPECT_EQ(bsp::predictRollingCollision(table, -1.0, 0.2).error().field, "speed_in");
  const auto unknown = bsp::fitRollingCollisions(table, {{"ball_ball.stiffness", 1.0}}, {{1.0, 0.3, 0.5, 0.5}}, 0.06);
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().field, "ball_ball.stiffness");
  const auto bad_cut = bsp::fitRollingCollisions(table, {{"ball_ball.restitution", 0.9, 0.0, 1.0}},
                                                 {{1.0, 0.3, 0.5, 0.5}, {1.0, 1.7, 0.5, 0.5}}, 0.06);
  ASSERT_FALSE(bad_cut.ok());
  EXPECT_EQ(bad_cut.error().field, "collisions[1].cut");
}

TEST(SnookerCloth, DeceleratesAsMeasured)
{
  // Mathavan et al. 2009, Fig. 6 (test/data/measurements/cloth_mathavan2009.md): a sliding ball decelerates at
  // 1.75–2.40 m/s², a rolling one at 0.124–0.126 m/s². Measured here on the engine's paths of the shipped table.
  const auto file = bsp::loadTableFile(std::string(CONFIG_DIR) + "/tables/snooker_mathavan.yaml");
  ASSERT_TRUE(file.ok()) << file.error().describe();
  const double r = file.value().ball.radius;
  bsp::BallState start;
  start.position = Eigen::Vector3d(0.0, 0.0, r);
  start.velocity = Eigen::Vector3d(1.5, 0.0, 0.0);  // a stun: sliding without spin
  auto sliding = bsp::predictTrajectory(start, file.value().ball, file.value().table, file.value().motion);
  ASSERT_TRUE(sliding.ok()) << sliding.error().describe();
  const bsp::MotionEvent& rolls = sliding.value().events.at(1);
  ASSERT_EQ(rolls.type, bsp::MotionEventType::SlideToRoll);
  const double sliding_deceleration = (1.5 - rolls.state.velocity.x()) / rolls.time;
  EXPECT_GE(sliding_deceleration, 1.75);
  EXPECT_LE(sliding_deceleration, 2.40);

  start.position.x() = -1.5;  // rolling at 0.5 m/s: it stops 1 m on, short of the far cushion
  start.velocity.x() = 0.5;
  start.angular_velocity = Eigen::Vector3d(0.0, 0.5 / r, 0.0);
  auto rolling = bsp::predictTrajectory(start, file.value().ball, file.value().table, file.value().motion);
  ASSERT_TRUE(rolling.ok()) << rolling.error().describe();
  const bsp::MotionEvent& stops = rolling.value().events.at(1);
  ASSERT_EQ(stops.type, bsp::MotionEventType::RollToSpin);
  const double rolling_deceleration = 0.5 / stops.time;
  EXPECT_GE(rolling_deceleration, 0.124);
  EXPECT_LE(rolling_deceleration, 0.126);
}

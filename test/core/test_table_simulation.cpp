// The table with N balls (motion/table_simulation.hpp): one event queue for every ball; a lone ball is
// predictTrajectory's case; input errors name the ball.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"

namespace bsp = billiard_shot_planner;
using Type = bsp::MotionEventType;

namespace
{
const double R = 0.0286;

bsp::BallState at(double x, double y, Eigen::Vector3d v = Eigen::Vector3d::Zero(),
                  Eigen::Vector3d w = Eigen::Vector3d::Zero())
{
  bsp::BallState s;
  s.position = {x, y, R};
  s.velocity = v;
  s.angular_velocity = w;
  return s;
}

void expectSameTrajectory(const bsp::BallTrajectory& a, const bsp::BallTrajectory& b)
{
  ASSERT_EQ(a.events.size(), b.events.size());
  ASSERT_EQ(a.segments.size(), b.segments.size());
  EXPECT_EQ(a.outcome, b.outcome);
  for (std::size_t k = 0; k < a.events.size(); ++k)
  {
    EXPECT_EQ(a.events[k].type, b.events[k].type);
    EXPECT_EQ(a.events[k].time, b.events[k].time);
    EXPECT_EQ(a.events[k].state.position, b.events[k].state.position);
    EXPECT_EQ(a.events[k].state.velocity, b.events[k].state.velocity);
    EXPECT_EQ(a.events[k].state.angular_velocity, b.events[k].state.angular_velocity);
  }
}
}  // namespace

// Balls whose paths never come within 2R of each other move as each would alone: the same events at the same
// times, to the last bit, and the ball at rest stays where it is.
TEST(TableSimulation, BallsThatNeverMeetMoveAsEachAlone)
{
  const bsp::Table table;
  const bsp::Ball ball;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k)
  {
    // The moving ball runs along y = -0.4 (parallel to the long rails), the resting one sits at y = +0.3.
    const bsp::BallState mover = at(0.5 * u(rng), -0.4, {2.0 * u(rng), 0.0, 0.0}, {0.0, 30.0 * u(rng), 0.0});
    const bsp::BallState rester = at(0.8 * u(rng), 0.3);
    const auto alone = bsp::predictTrajectory(mover, ball, table);
    const auto both = bsp::simulateTable({{"cue", mover}, {"one", rester}}, ball, table);
    ASSERT_TRUE(alone.ok() && both.ok());
    expectSameTrajectory(both.value().balls[0], alone.value());
    const bsp::BallTrajectory& still = both.value().balls[1];
    ASSERT_EQ(still.events.size(), 2u);
    EXPECT_EQ(still.events[1].type, Type::Rest);
    EXPECT_EQ(still.events[1].state.position, rester.position);
    EXPECT_TRUE(both.value().ball_impacts.empty());
    EXPECT_EQ(both.value().duration(), alone.value().duration());
  }
}

TEST(TableSimulation, ALoneBallIsTheOneBallCaseOfTheTable)
{
  const bsp::Table table;
  const bsp::Ball ball;
  const bsp::BallState start = at(-0.6, 0.1, {1.5, 0.7, 0.0}, {-20.0, 40.0, 15.0});
  const auto alone = bsp::predictTrajectory(start, ball, table);
  const auto table_run = bsp::simulateTable({{"cue", start}}, ball, table);
  ASSERT_TRUE(alone.ok() && table_run.ok());
  expectSameTrajectory(table_run.value().balls[0], alone.value());
  EXPECT_EQ(table_run.value().ids, std::vector<std::string>{"cue"});
}

TEST(TableSimulation, BadTablesAreRefusedNamingTheBall)
{
  const bsp::Table table;
  const bsp::Ball ball;
  auto fieldOf = [&](const std::vector<bsp::TableBall>& balls)
  {
    auto r = bsp::simulateTable(balls, ball, table);
    return r.ok() ? std::string("accepted") : r.error().field;
  };
  EXPECT_EQ(fieldOf({}), "balls");
  EXPECT_EQ(fieldOf({{"", at(0, 0)}}), "balls[0].id");
  EXPECT_EQ(fieldOf({{"a", at(0, 0)}, {"a", at(0.5, 0)}}), "balls[1].id");
  EXPECT_EQ(fieldOf({{"a", at(0, 0)}, {"b", at(1.9 * R, 0)}}), "balls[1].position");  // overlap
  EXPECT_EQ(fieldOf({{"a", at(0, 0)}, {"b", at(2.0 * R, 0)}}), "accepted");           // touching is allowed
  EXPECT_EQ(fieldOf({{"a", at(0, 0)}, {"b", at(5.0, 0)}}), "balls[1].position");      // off the table
  EXPECT_EQ(fieldOf({{"a", at(0, 0)}, {"b", at(0.5 * table.length, 0.5 * table.width)}}), "balls[1].position");
  EXPECT_EQ(fieldOf({{"a", at(0, 0)}, {"b", at(0.5, std::nan(""))}}), "balls[1].position");
  EXPECT_EQ(fieldOf({{"a", at(0, 0, {1e6, 0, 0})}}), "balls[0].v");
  std::vector<bsp::TableBall> crowd;
  for (std::size_t i = 0; i <= bsp::MAX_TABLE_BALLS; ++i)
    crowd.push_back({"b" + std::to_string(i), at(-1.0 + 0.07 * double(i % 28), i < 28 ? -0.3 : 0.3)});
  EXPECT_EQ(fieldOf(crowd), "balls");
}

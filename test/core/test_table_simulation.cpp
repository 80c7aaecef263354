// The table with N balls (motion/table_simulation.hpp): one event queue for every ball; a lone ball is
// predictTrajectory's case; input errors name the ball.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "table_helpers.hpp"

namespace bsp = billiard_shot_planner;
using Type = bsp::MotionEventType;

namespace
{
const double R = 0.0286;

bsp::BallState at(double x, double y, const Eigen::Vector3d& v = Eigen::Vector3d::Zero(),
                  const Eigen::Vector3d& w = Eigen::Vector3d::Zero())
{
  return table_helpers::stateOnCloth(R, x, y, v, w);
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
  const bsp::BallProperties ball;
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
  const bsp::BallProperties ball;
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
  const bsp::BallProperties ball;
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

namespace
{
const double G = 9.81, MU_S = 0.152479;

/// Kinetic and potential energy of every ball still on the table at time t (J; potential from the cloth).
double tableEnergy(const bsp::TableTrajectory& run, const bsp::BallProperties& ball, double t)
{
  double energy = 0.0;
  for (const bsp::BallTrajectory& b : run.balls)
  {
    if (b.outcome != bsp::MotionOutcome::Rest && t >= b.duration())
      continue;  // pocketed or off the table by now
    const bsp::BallState s = b.at(t);
    const double inertia = 0.4 * ball.mass * ball.radius * ball.radius;
    energy += 0.5 * ball.mass * s.velocity.squaredNorm() + 0.5 * inertia * s.angular_velocity.squaredNorm() +
              ball.mass * G * (s.position.z() - ball.radius);
  }
  return energy;
}

bool onTable(const bsp::BallTrajectory& b, double t)
{
  return b.outcome == bsp::MotionOutcome::Rest || t < b.duration();
}

/// The deepest overlap of two balls on the table over [0, duration], sampled every `step` seconds (m; ≤ 0 none).
double deepestOverlap(const bsp::TableTrajectory& run, const bsp::BallProperties& ball, double step)
{
  double deepest = 0.0;
  for (double t = 0.0; t <= run.duration(); t += step)
    for (std::size_t i = 0; i < run.balls.size(); ++i)
      for (std::size_t j = i + 1; j < run.balls.size(); ++j)
        if (onTable(run.balls[i], t) && onTable(run.balls[j], t))
        {
          const double gap = (run.balls[i].at(t).position - run.balls[j].at(t).position).norm() - 2.0 * ball.radius;
          deepest = std::max(deepest, -gap);
        }
  return deepest;
}
}  // namespace

// A cue ball sliding without spin straight at a resting ball: they meet when the sliding ball has covered the gap,
// x(t) = V t − ½ μ_s g t² (closed form), and the object ball leaves along the line of centres at (1 + e)/2 of the
// cue ball's speed then. The cue ball has gathered top spin Rω = (5/2) μ_s g t (1 % of V after 1 cm), whose slip at
// the contact is vertical; what it changes of the object ball's speed stays below 0.2 %.
TEST(TableSimulation, AStunShotMeetsTheObjectBallWhenTheGapIsCovered)
{
  const bsp::Table table;
  const bsp::BallProperties ball;
  const double V = 2.0, gap = 0.01;
  const auto run =
      bsp::simulateTable({{"cue", at(-0.4, 0.0, {V, 0, 0})}, {"one", at(-0.4 + 2 * R + gap, 0.0)}}, ball, table);
  ASSERT_TRUE(run.ok()) << run.error().describe();
  ASSERT_FALSE(run.value().ball_impacts.empty());
  const double a = MU_S * G;
  const double meet = (V - std::sqrt(V * V - 2.0 * a * gap)) / a;
  EXPECT_NEAR(run.value().ball_impacts[0].time, meet, 1e-12);
  const double cue_speed = V - a * meet;  // still sliding: slide-to-roll takes 2V/(7 μ g) = 0.37 s
  const bsp::BallTrajectory& one = run.value().balls[1];
  const auto hit = std::find_if(one.events.begin(), one.events.end(),
                                [](const bsp::MotionEvent& e) { return e.type == Type::BallCollision; });
  ASSERT_NE(hit, one.events.end());
  EXPECT_NEAR(hit->state.velocity.x(), 0.5 * (1.0 + bsp::BallCollision{}.ball_ball.restitution) * cue_speed,
              0.002 * cue_speed);
  EXPECT_NEAR(hit->state.velocity.y(), 0.0, 1e-9);
  EXPECT_EQ(hit->ball, 0);
}

// A ball frozen to a rail and hit, head-on and at a cut: the rail is part of the ball impact, so the frozen ball
// leaves the impact not moving into the rail (no separate cushion hit at the same instant), no ball ever crosses a
// nose line, and the table's energy never rises.
TEST(TableSimulation, ABallFrozenToARailIsHitTogetherWithTheRail)
{
  const bsp::Table table;
  const bsp::BallProperties ball;
  const double sin_nose = (table.cushion_height - R) / R;
  const double nose_line = 0.5 * table.length - R * std::sqrt(1.0 - sin_nose * sin_nose);
  for (double cut_deg : {0.0, 30.0})
  {
    const double cut = cut_deg * M_PI / 180.0;
    const Eigen::Vector2d frozen(nose_line, 0.2);
    const Eigen::Vector2d cue =
        frozen - 2.0 * R * Eigen::Vector2d(std::cos(cut), std::sin(cut)) - Eigen::Vector2d(0.3, 0.0);
    const auto run = bsp::simulateTable(
        {{"cue", at(cue.x(), cue.y(), {1.5, 0, 0})}, {"one", at(frozen.x(), frozen.y())}}, ball, table);
    ASSERT_TRUE(run.ok()) << run.error().describe();
    ASSERT_FALSE(run.value().ball_impacts.empty());
    const double hit_time = run.value().ball_impacts[0].time;
    const bsp::BallTrajectory& one = run.value().balls[1];
    const auto hit = std::find_if(one.events.begin(), one.events.end(),
                                  [](const bsp::MotionEvent& e) { return e.type == Type::BallCollision; });
    ASSERT_NE(hit, one.events.end());
    EXPECT_LE(hit->state.velocity.x(), 1e-9) << cut_deg << "°";
    for (const bsp::MotionEvent& e : one.events)
      EXPECT_FALSE(e.type == Type::CushionHit && e.time == hit_time) << cut_deg << "°";
    double before = tableEnergy(run.value(), ball, 0.0);
    for (double t = 0.0; t <= run.value().duration(); t += 1e-4)
    {
      for (const bsp::BallTrajectory& b : run.value().balls)
        EXPECT_LE(std::abs(b.at(t).position.x()), nose_line + 1e-9) << cut_deg << "° t " << t;
      const double now = tableEnergy(run.value(), ball, t);
      EXPECT_LE(now, before + 1e-9 * (1.0 + before)) << cut_deg << "° t " << t;
      before = now;
    }
  }
}

// Random shots among 2–6 balls: no overlap is ever missed (a brute-force fixed-step check at 0.5 ms), and the
// table's energy never rises (every phase and every impact dissipates).
TEST(TableSimulation, RandomShotsMissNoCollisionAndNeverGainEnergy)
{
  const bsp::Table table;
  const bsp::BallProperties ball;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int shots = std::getenv("TABLE_SHOTS") ? std::atoi(std::getenv("TABLE_SHOTS")) : 1000;
  int impacts = 0;
  double deepest = 0.0;
  for (int k = 0; k < shots; ++k)
  {
    std::vector<bsp::TableBall> balls;
    const int n = 2 + k % 5;
    while (static_cast<int>(balls.size()) < n)
    {
      const bsp::BallState s = at(1.0 * u(rng), 0.45 * u(rng));
      bool clear = true;
      for (const bsp::TableBall& b : balls)
        clear = clear && (b.state.position - s.position).norm() > 2.0 * R + 1e-3;
      if (clear)
        balls.push_back({"b" + std::to_string(balls.size()), s});
    }
    // The cue ball aims at a random object ball with a random offset and spin.
    const Eigen::Vector3d aim = balls[1].state.position - balls[0].state.position;
    const Eigen::Vector3d side = Eigen::Vector3d::UnitZ().cross(aim).normalized();
    const Eigen::Vector3d direction = (aim + side * (1.5 * R * u(rng))).normalized();
    balls[0].state.velocity = (0.5 + 2.5 * std::abs(u(rng))) * direction;
    balls[0].state.angular_velocity = Eigen::Vector3d(20 * u(rng), 20 * u(rng), 20 * u(rng));
    const auto run = bsp::simulateTable(balls, ball, table);
    ASSERT_TRUE(run.ok()) << "shot " << k << ": " << run.error().describe();
    impacts += static_cast<int>(run.value().ball_impacts.size());
    const double overlap = deepestOverlap(run.value(), ball, 5e-4);
    deepest = std::max(deepest, overlap);
    EXPECT_LT(overlap, 1e-9) << "shot " << k;
    double before = tableEnergy(run.value(), ball, 0.0);
    for (double t = 1e-3; t <= run.value().duration(); t += 1e-3)
    {
      const double now = tableEnergy(run.value(), ball, t);
      EXPECT_LE(now, before + 1e-9 * (1.0 + before)) << "shot " << k << " t " << t;
      before = now;
    }
  }
  EXPECT_GT(impacts, shots / 2);  // the shots do hit balls
  std::printf("%d random shots, %d ball impacts, deepest overlap found by the 0.5 ms search %.3g m\n", shots, impacts,
              deepest);
}

// The break: a racked pack of 15 touching balls hit by the cue ball from the head string at 8 m/s is one multiple
// impact of 16 balls; every ball then rests or leaves the table, none overlaps another, energy never rises.
TEST(TableSimulation, TheBreakEndsWithEveryBallAtRestOrGone)
{
  const bsp::Table table;
  const bsp::BallProperties ball;
  std::vector<bsp::TableBall> balls{{"cue", at(-0.25 * table.length, 0.01, {8.0, 0, 0})}};
  for (int row = 0; row < 5; ++row)
    for (int k = 0; k <= row; ++k)
      balls.push_back({std::to_string(balls.size()),
                       at(0.25 * table.length + row * std::sqrt(3.0) * R, (k - 0.5 * row) * 2.0 * R)});
  bsp::MotionParameters parameters;
  parameters.impact.max_seconds = 60.0;  // the pack's impacts take seconds (bench/NOTES.md): the longest budget
  const auto run = bsp::simulateTable(balls, ball, table, parameters);
  ASSERT_TRUE(run.ok()) << run.error().describe();
  for (const bsp::BallTrajectory& b : run.value().balls)
    EXPECT_NE(b.outcome, bsp::MotionOutcome::TimeLimit);
  ASSERT_FALSE(run.value().ball_impacts.empty());
  EXPECT_EQ(run.value().ball_impacts[0].balls.size(), 16u);  // the whole rack and the cue ball: one impact
  EXPECT_LT(deepestOverlap(run.value(), ball, 5e-4), 1e-9);
  double before = tableEnergy(run.value(), ball, 0.0);
  for (double t = 1e-3; t <= run.value().duration(); t += 1e-3)
  {
    const double now = tableEnergy(run.value(), ball, t);
    EXPECT_LE(now, before + 1e-9 * (1.0 + before)) << "t " << t;
    before = now;
  }
}

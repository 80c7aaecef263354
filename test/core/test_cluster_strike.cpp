// The cue strike of a ball that touches others as one multiple impact (scenarios/cluster_strike.hpp): limits
// derived here, the invariants of every impact, and the lone ball's answer unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "billiard_shot_planner/motion/table_strike.hpp"
#include "billiard_shot_planner/scenarios/cluster_strike.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double R = 0.0286;
constexpr double PI = 3.14159265358979323846;

/// A level centre hit on the cue ball at the origin, the cue turned φ from +x (the line of centres to a ball at
/// (2R, 0)), frictionless contacts so that the limits below are exact.
bsp::CueStrike centreHit(double phi)
{
  bsp::CueStrike s;
  s.cue_mass = 0.5;
  s.cue_end_mass = bsp::CUE_HELD_ON_AXIS;
  s.cue_speed = 2.0;
  s.ball_radius = R;
  s.cue_direction = Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0);
  s.hit_normal = -s.cue_direction;
  s.cue_contact = {0.7, 0.0, 1.2};
  s.table_contact = {0.5, 0.0, 10.0};
  return s;
}

/// The cue ball and one ball frozen to it along +x, k_ball_ball / k_cue = 1 / stiffness.
bsp::ClusterStrike frozenPair(double phi, double ball_ball_over_cue)
{
  bsp::ClusterStrike c;
  c.strike = centreHit(phi);
  c.bodies.ball_radius = R;
  c.bodies.balls = {{Eigen::Vector2d::Zero()}, {Eigen::Vector2d(2.0 * R, 0.0)}};
  c.bodies.ball_ball = {1.0, 0.0, 1.2};
  c.bodies.friction_model = bsp::BallBallFriction::Constant;
  // k_bb/k_cue = (k_cloth/k_cue) / (k_cloth/k_bb): each ratio within its range [0.01, 100].
  c.strike.stiffness_ratio = std::sqrt(ball_ball_over_cue);
  c.bodies.stiffness_ratio = 1.0 / std::sqrt(ball_ball_over_cue);
  return c;
}

double directionDeg(const Eigen::Vector3d& v)
{
  return std::atan2(v.y(), v.x()) * 180.0 / PI;
}
}  // namespace

// A very soft, long cue contact against stiff balls: while the cue pushes, the pair moves as one body along the
// line of centres. The push J (along the cue, angle φ) splits into J cos φ along x, carried by both balls (2m), and
// J sin φ across, carried by the cue ball alone: v_x = J cos φ / 2m, v_y = J sin φ / m, so tan θ = 2 tan φ; the
// object ball keeps J cos φ / 2m, the cue ball's x velocity.
TEST(ClusterStrike, SoftCueMovesAFrozenPairAsOneBody)
{
  for (double phi_deg : {0.0, 8.0, 20.0, 34.0})
  {
    const double phi = phi_deg * PI / 180.0;
    auto result = bsp::solve(frozenPair(phi, 1e4));
    ASSERT_TRUE(result.ok()) << result.error().describe();
    const bsp::CueStrikeResult& r = result.value();
    ASSERT_EQ(r.other_balls.size(), 1u);
    const double expected = std::atan(2.0 * std::tan(phi)) * 180.0 / PI;
    EXPECT_NEAR(directionDeg(r.velocity), expected, 1.0) << "phi " << phi_deg;
    EXPECT_NEAR(r.other_balls[0].velocity.x() / r.velocity.x(), 1.0, 0.05) << "phi " << phi_deg;
  }
}

// A very stiff, short cue contact: the cue leaves before the balls meet, so the cue ball then hits the frozen ball
// as a free ball — the sequential answer. Elastic equal balls, no friction: the cue ball keeps only its velocity
// across the line of centres (direction 90°) and the object ball takes v cos φ along it. The cue here is lighter
// than the ball and elastic, so it recoils and does not strike the ball a second time (a heavy cue follows through
// and does: that is no longer the sequential answer).
TEST(ClusterStrike, StiffCueGivesTheSequentialAnswer)
{
  const double phi = 20.0 * PI / 180.0;
  bsp::ClusterStrike pair = frozenPair(phi, 1e-4);
  pair.strike.cue_mass = 0.1;
  pair.strike.cue_contact.restitution = 1.0;
  auto lone = bsp::solve(pair.strike);
  ASSERT_TRUE(lone.ok());
  auto result = bsp::solve(pair);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  const double v = lone.value().velocity.head<2>().norm();
  EXPECT_NEAR(directionDeg(result.value().velocity), 90.0, 1.0);
  EXPECT_NEAR(result.value().other_balls[0].velocity.x(), v * std::cos(phi), 0.02 * v);
}

// Energy never rises, every normal impulse pushes, and the balls' momentum along the cloth changes only by the cue's
// impulse (no cushion here; frictionless cloth).
TEST(ClusterStrike, InvariantsOfTheCombinedImpact)
{
  for (double phi_deg : {0.0, 15.0, 40.0})
    for (double stiffness : {0.1, 1.0, 8.0, 50.0})
    {
      auto result = bsp::solve(frozenPair(phi_deg * PI / 180.0, stiffness));
      ASSERT_TRUE(result.ok()) << result.error().describe();
      const bsp::CueStrikeResult& r = result.value();
      EXPECT_LE(r.impact.final_kinetic_energy, r.impact.initial_kinetic_energy * (1.0 + 1e-12));
      for (const bsp::ContactImpulse& impulse : r.impact.impulses)
        EXPECT_GE(impulse.normal, -1e-15);
      const Eigen::Vector2d momentum = 0.17 * (r.velocity + r.other_balls[0].velocity).head<2>();
      EXPECT_LT((momentum + r.impulse_cue.head<2>()).norm(), 1e-9 * momentum.norm());
      EXPECT_EQ(r.contacts.size(), r.impact.impulses.size());
      EXPECT_EQ(r.contacts.front().name, "tip-ball0");
    }
}

// A ball that touches nothing is struck exactly as the lone strike.
TEST(ClusterStrike, LoneBallOnTheTableIsTheLoneStrike)
{
  const bsp::CueStrike strike = centreHit(0.3);
  std::vector<bsp::TableBall> balls(2);
  balls[0].id = "cue";
  balls[0].state.position = Eigen::Vector3d(0.0, 0.0, R);
  balls[1].id = "one";
  balls[1].state.position = Eigen::Vector3d(0.5, 0.2, R);
  auto on_table = bsp::strikeOnTable(strike, balls, 0, bsp::Table{}, bsp::BallContactSettings{});
  auto lone = bsp::solve(strike);
  ASSERT_TRUE(on_table.ok() && lone.ok());
  EXPECT_EQ(on_table.value().velocity, lone.value().velocity);
  EXPECT_EQ(on_table.value().angular_velocity, lone.value().angular_velocity);
  EXPECT_TRUE(on_table.value().other_balls.empty());
}

// A ball touching the cue ball on the table joins the strike, named by its id.
TEST(ClusterStrike, FrozenBallOnTheTableJoinsTheStrike)
{
  std::vector<bsp::TableBall> balls(2);
  balls[0].id = "cue";
  balls[0].state.position = Eigen::Vector3d(0.0, 0.0, R);
  balls[1].id = "one";
  balls[1].state.position = Eigen::Vector3d(2.0 * R, 0.0, R);
  bsp::BallProperties ball{0.17, R};
  const bsp::StrikeBodies bodies = bsp::strikeBodies(balls, 0, ball, bsp::Table{}, bsp::BallContactSettings{});
  ASSERT_EQ(bodies.members.size(), 2u);
  auto result = bsp::strikeOnTable(centreHit(0.0), balls, 0, bsp::Table{}, bsp::BallContactSettings{});
  ASSERT_TRUE(result.ok()) << result.error().describe();
  ASSERT_EQ(result.value().other_balls.size(), 1u);
  EXPECT_EQ(result.value().other_balls[0].ball, 1u);
  EXPECT_GT(result.value().other_balls[0].velocity.x(), 0.0);
  EXPECT_EQ(result.value().contacts[1].name, "cue-one");
  ASSERT_EQ(result.value().touching_balls.size(), 1u);
  EXPECT_EQ(result.value().touching_balls[0].first, 0u);
  EXPECT_EQ(result.value().touching_balls[0].second, 1u);
}

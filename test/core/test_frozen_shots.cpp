// Frozen shots through predictShot: a cue ball that touches a ball or a cushion is struck together with it as one
// multiple impact, the same strike as strikeOnTable's, and the balls it moved start the motion with the strike's
// velocities. The strike's own limits (soft and stiff cue, invariants) are derived in test_cluster_strike.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "billiard_shot_planner/motion/table_strike.hpp"
#include "billiard_shot_planner/scenarios/cue_stroke.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "table_helpers.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double PI = 3.14159265358979323846;
const bsp::ShotConfiguration CONFIGURATION{};
const double R = CONFIGURATION.ball_radius;

/// A level stroke on the ball at `ball`: φ from +x (degrees), tip offsets a, b in radii.
bsp::CuePlacement stroke(const Eigen::Vector2d& ball, double phi_deg, double speed, double b = 0.0)
{
  return table_helpers::strokeAt(ball, R, {phi_deg * PI / 180.0, 0.0, 0.0, b}, speed);
}

bsp::TableBall ballAt(const std::string& id, const Eigen::Vector2d& position)
{
  bsp::TableBall ball{id, {}};
  ball.state.position = Eigen::Vector3d(position.x(), position.y(), R);
  return ball;
}

/// y of a ball's centre touching the +y cushion's nose: the nose (at cushion_height) is R from the centre.
double touchingPlusY()
{
  const double above = CONFIGURATION.table.cushion_height - R;
  return 0.5 * CONFIGURATION.table.width - std::sqrt(R * R - above * above);
}

const bsp::StrikeContact* contactNamed(const bsp::CueStrikeResult& strike, const std::string& name)
{
  for (const bsp::StrikeContact& contact : strike.contacts)
    if (contact.name == name)
      return &contact;
  return nullptr;
}
}  // namespace

// predictShot's strike of a frozen pair is strikeOnTable's, and the object ball starts with the strike's velocity; the
// meeting is recorded at t = 0 in both balls' events and in the impacts, so the first contact is the frozen ball.
TEST(FrozenShots, PredictShotStrikesAFrozenPairAsOneImpact)
{
  const Eigen::Vector2d cue_ball(-0.4, 0.1);
  for (double phi_deg : {0.0, 8.0, 20.0, 46.0})
  {
    const bsp::CuePlacement cue = stroke(cue_ball, phi_deg, 2.0);
    const std::vector<bsp::TableBall> others{ballAt("one", cue_ball + Eigen::Vector2d(2.0 * R, 0.0))};
    const auto outcome = bsp::predictShot(cue, CONFIGURATION, others);
    ASSERT_TRUE(outcome.ok()) << outcome.error().describe();
    const bsp::ShotOutcome& o = outcome.value();
    ASSERT_EQ(o.strike.other_balls.size(), 1u);
    EXPECT_EQ(o.strike.other_balls[0].ball, 1u);
    ASSERT_EQ(o.strike.touching_balls.size(), 1u);
    EXPECT_EQ(o.strike.contacts[1].name, "cue-one");

    // The same strike as strikeOnTable's on the same balls, bit for bit.
    bsp::CueStrike direct;
    direct.cue_mass = CONFIGURATION.cue_mass;
    direct.cue_end_mass = CONFIGURATION.cue_end_mass;
    direct.cue_direction = cue.direction;
    direct.cue_speed = cue.speed;
    direct.ball_mass = CONFIGURATION.ball_mass;
    direct.ball_radius = R;
    direct.hit_normal =
        bsp::hitNormal(cue.tip, cue.direction, Eigen::Vector3d(cue_ball.x(), cue_ball.y(), R), R).value();
    direct.cue_contact = CONFIGURATION.cue_contact;
    direct.table_contact = CONFIGURATION.table.cloth;
    direct.stiffness_ratio = CONFIGURATION.stiffness_ratio;
    const auto on_table = bsp::strikeOnTable(direct, {ballAt("cue", cue_ball), others[0]}, 0, CONFIGURATION.table,
                                             CONFIGURATION.ball_contact, CONFIGURATION.solver);
    ASSERT_TRUE(on_table.ok());
    EXPECT_EQ(o.strike.velocity, on_table.value().velocity);
    EXPECT_EQ(o.strike.other_balls[0].velocity, on_table.value().other_balls[0].velocity);

    // The motion starts from the strike: both balls' first events carry its velocities.
    // (On the cloth the motion sets the vertical velocity, −1e-17 after the strike, to zero.)
    EXPECT_EQ(o.table.balls[0].events.front().state.velocity.head<2>(), o.strike.velocity.head<2>());
    EXPECT_EQ(o.table.balls[1].events.front().state.velocity.head<2>(), o.strike.other_balls[0].velocity.head<2>());
    EXPECT_EQ(o.table.balls[1].events.front().state.angular_velocity, o.strike.other_balls[0].angular_velocity);
    ASSERT_GE(o.table.balls[0].events.size(), 2u);
    EXPECT_EQ(o.table.balls[0].events[1].type, bsp::MotionEventType::BallCollision);
    EXPECT_EQ(o.table.balls[0].events[1].time, 0.0);
    EXPECT_EQ(o.table.balls[0].events[1].ball, 1);
    EXPECT_EQ(bsp::firstContact(o.table), "one");
    ASSERT_FALSE(o.table.ball_impacts.empty());
    EXPECT_EQ(o.table.ball_impacts.front().time, 0.0);
    // The object ball moves off along the line of centres (+x), turned by the throw: a level strike presses no ball
    // into the cloth, so the ball–ball contact's impulse alone moves it, and Coulomb's cone bounds its turn by
    // atan(μ) with μ ≤ a + b = 0.118 of Alciatore's fit (the default friction model).
    const Eigen::Vector3d& v1 = o.strike.other_balls[0].velocity;
    EXPECT_GT(v1.x(), 0.0);
    EXPECT_LE(std::abs(std::atan2(v1.y(), v1.x())), std::atan(9.951e-3 + 0.108) + 1e-6) << "phi " << phi_deg;
  }
}

// A neighbour farther than the gap leaves the strike the lone one, exactly.
TEST(FrozenShots, NeighbourBeyondTheGapLeavesTheLoneStrike)
{
  const Eigen::Vector2d cue_ball(-0.4, 0.1);
  const bsp::CuePlacement cue = stroke(cue_ball, 20.0, 2.0, 0.3);
  const auto lone = bsp::strikeBall(cue, CONFIGURATION);
  ASSERT_TRUE(lone.ok());
  for (double gap : {2.0 * bsp::TOUCHING_GAP, 1e-6, 0.3})
  {
    const auto near =
        bsp::strikeBall(cue, CONFIGURATION, {ballAt("one", cue_ball + Eigen::Vector2d(2.0 * R + gap, 0.0))});
    ASSERT_TRUE(near.ok());
    EXPECT_EQ(near.value().velocity, lone.value().velocity);
    EXPECT_EQ(near.value().angular_velocity, lone.value().angular_velocity);
    EXPECT_EQ(near.value().states, lone.value().states);
    EXPECT_TRUE(near.value().other_balls.empty());
  }
}

// A cue ball frozen to the +y rail: struck along the rail the cushion takes no impulse; struck 5° into it the rail's
// reaction is part of the strike (it pushes the ball away, −y) and the ball never passes the nose.
TEST(FrozenShots, CueBallFrozenToARail)
{
  const Eigen::Vector2d cue_ball(-0.5, touchingPlusY());
  for (double phi_deg : {0.0, 5.0, 20.0, 90.0})
  {
    const auto outcome = bsp::predictShot(stroke(cue_ball, phi_deg, 2.0), CONFIGURATION);
    ASSERT_TRUE(outcome.ok()) << outcome.error().describe();
    const bsp::StrikeContact* rail = contactNamed(outcome.value().strike, "cue-rail.top");
    ASSERT_NE(rail, nullptr) << "phi " << phi_deg;
    if (phi_deg == 0.0)
      EXPECT_LT(rail->impulse.norm(), 1e-12);
    else
      EXPECT_LT(rail->impulse.y(), 0.0);
    EXPECT_LE(outcome.value().strike.velocity.y(), 1e-12);
    for (const bsp::TrajectorySample& s : outcome.value().trajectory.sample(1e-3))
      EXPECT_LE(s.state.position.y(), cue_ball.y() + bsp::TOUCHING_GAP) << "phi " << phi_deg << " t " << s.time;
  }
}

// The jam: the cue pushes straight into a ball frozen to a ball frozen to the rail, so the cue's push has no free
// direction. The strike is still one bounded impact: every spring gives back what the energetic law lets it, the
// cue recoils, energy falls, no ball passes into the rail.
TEST(FrozenShots, JammedCueBallIsABoundedImpact)
{
  const double y = touchingPlusY();
  const Eigen::Vector2d cue_ball(-0.5, y - 4.0 * R);
  const std::vector<bsp::TableBall> others{ballAt("one", {-0.5, y - 2.0 * R}), ballAt("two", {-0.5, y})};
  const auto struck = bsp::strikeBall(stroke(cue_ball, 90.0, 4.0), CONFIGURATION, others);
  ASSERT_TRUE(struck.ok()) << struck.error().describe();
  const bsp::CueStrikeResult& r = struck.value();
  EXPECT_TRUE(r.velocity.allFinite());
  EXPECT_LT(r.cue_velocity, 0.0);  // the cue recoils
  EXPECT_LT(r.impact.final_kinetic_energy, r.impact.initial_kinetic_energy);
  ASSERT_EQ(r.other_balls.size(), 2u);
  const bsp::StrikeContact* rail = contactNamed(r, "two-rail.top");
  ASSERT_NE(rail, nullptr);
  EXPECT_LT(rail->impulse.y(), 0.0);
  for (const bsp::StruckBall& ball : r.other_balls)
    EXPECT_LE(ball.velocity.y(), 1e-12);
}

// predictShotAfter refuses a strike that moved or paired balls these others do not have, naming it.
TEST(FrozenShots, StrikeOfOtherBallsIsRefused)
{
  const Eigen::Vector2d cue_ball(-0.4, 0.1);
  const bsp::CuePlacement cue = stroke(cue_ball, 10.0, 2.0);
  const auto struck = bsp::strikeBall(cue, CONFIGURATION, {ballAt("one", cue_ball + Eigen::Vector2d(2.0 * R, 0.0))});
  ASSERT_TRUE(struck.ok());
  const auto after = bsp::predictShotAfter(cue, struck.value(), CONFIGURATION);
  ASSERT_FALSE(after.ok());
  EXPECT_EQ(after.error().field, "strike.other_balls");
  bsp::CueStrikeResult touching_only = struck.value();
  touching_only.other_balls.clear();
  const auto paired = bsp::predictShotAfter(cue, touching_only, CONFIGURATION);
  ASSERT_FALSE(paired.ok());
  EXPECT_EQ(paired.error().field, "strike.touching_balls");
}

// Balls overlapping beyond the gap: the ball is named by its place in the call's others.
TEST(FrozenShots, OverlappingNeighbourIsNamed)
{
  const Eigen::Vector2d cue_ball(-0.4, 0.1);
  const auto struck =
      bsp::predictShot(stroke(cue_ball, 10.0, 2.0), CONFIGURATION,
                       {ballAt("far", {0.8, 0.3}), ballAt("one", cue_ball + Eigen::Vector2d(1.9 * R, 0.0))});
  ASSERT_FALSE(struck.ok());
  EXPECT_EQ(struck.error().field.rfind("others[1]", 0), 0u) << struck.error().field;
}

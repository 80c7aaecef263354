// pooltool's and FastFiz's strokes against this package's: the same physical stroke — the cue ball struck from the
// head towards the foot at 2 m/s, a level cue, the tip 0.3 radii right of centre as the player sees it — written in
// each, as their sources define them (pooltool's Cue and cue_strike(), ekiefl/pooltool commit 9a8abfe; FastFiz's
// ShotParams and CueStrikeEvent::doHandle, which negates a before the physics, P6-Pool/fastfiz commit 2c1c920), and
// the strike this package predicts for it against the signs both give.
#include <gtest/gtest.h>

#include <cmath>

#include "billiard_shot_planner/planning/stroke_conventions.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double DEG = M_PI / 180.0;
constexpr double POOLTOOL_RADIUS = 0.028575;  // m, pooltool's and FastFiz's ball

// pooltool: phi 90° is "towards the foot rail"; a = −1 "the rightmost side of ball". FastFiz: the foot spot lies at
// a quarter of the length from y = 0, so the foot is −y (phi 270°); a in mm, + right.
const bsp::PooltoolStroke POOLTOOL{2.0, 90.0, 0.0, -0.3, 0.0};
const bsp::FastFizShot FASTFIZ{0.3 * POOLTOOL_RADIUS * 1e3, 0.0, 0.0, 270.0, 2.0};

void expectStroke(const bsp::Stroke& s, double phi, double theta, double speed, double a, double b)
{
  EXPECT_NEAR(s.phi, phi, 1e-12);
  EXPECT_NEAR(s.theta, theta, 1e-12);
  EXPECT_NEAR(s.speed, speed, 1e-12);
  EXPECT_NEAR(s.a, a, 1e-12);
  EXPECT_NEAR(s.b, b, 1e-12);
}
}  // namespace

TEST(StrokeConventions, TheSameStrokeInEachIsTheSameHere)
{
  expectStroke(bsp::fromPooltool(POOLTOOL), 0.0, 0.0, 2.0, 0.3, 0.0);  // towards the foot (+x), right english
  expectStroke(bsp::fromFastFiz(FASTFIZ, POOLTOOL_RADIUS), 0.0, 0.0, 2.0, 0.3, 0.0);
  // Elevation and follow: degrees to radians, b alike in both (+ up).
  expectStroke(bsp::fromPooltool({3.0, 180.0, 30.0, 0.0, 0.4}), 90.0 * DEG, 30.0 * DEG, 3.0, 0.0, 0.4);
  expectStroke(bsp::fromFastFiz({0.0, 0.4 * POOLTOOL_RADIUS * 1e3, 30.0, 0.0, 3.0}, POOLTOOL_RADIUS), 90.0 * DEG,
               30.0 * DEG, 3.0, 0.0, 0.4);
}

TEST(StrokeConventions, EachConverterRoundTrips)
{
  const bsp::Stroke stroke{2.5, 0.2, 4.0, -0.35, 0.25};
  const bsp::PooltoolStroke pooltool = bsp::toPooltool(stroke);
  EXPECT_NEAR(pooltool.a, 0.35, 1e-15);  // left english there is a > 0
  expectStroke(bsp::fromPooltool(pooltool), 2.5, 0.2, 4.0, -0.35, 0.25);
  const bsp::FastFizShot fastfiz = bsp::toFastFiz(stroke, POOLTOOL_RADIUS);
  EXPECT_NEAR(fastfiz.a, -0.35 * 28.575, 1e-12);
  expectStroke(bsp::fromFastFiz(fastfiz, POOLTOOL_RADIUS), 2.5, 0.2, 4.0, -0.35, 0.25);
}

// The foot spot, a quarter of the length from the foot rail on the long axis, in the three frames; pooltool's
// rack sits at (0.5 w, 0.75 l) of its table, FastFiz's foot spot at (w/2, l/4).
TEST(StrokeConventions, TablePositionsMapTheFootSpotToTheFootSpot)
{
  const bsp::Table table;
  const Eigen::Vector2d foot_spot(0.25 * table.length, 0.0);
  const Eigen::Vector2d pooltool(0.5 * table.width, 0.75 * table.length),
      fastfiz(0.5 * table.width, 0.25 * table.length);
  EXPECT_TRUE(bsp::fromPooltoolPosition(pooltool, table).isApprox(foot_spot, 1e-12));
  EXPECT_TRUE(bsp::fromFastFizPosition(fastfiz, table).isApprox(foot_spot, 1e-12));
  const Eigen::Vector2d anywhere(-0.7, 0.3);
  EXPECT_TRUE(bsp::fromPooltoolPosition(bsp::toPooltoolPosition(anywhere, table), table).isApprox(anywhere, 1e-12));
  EXPECT_TRUE(bsp::fromFastFizPosition(bsp::toFastFizPosition(anywhere, table), table).isApprox(anywhere, 1e-12));
  // A heading keeps pointing at the same place: pooltool's stroke towards its foot rail heads for +x here.
  const Eigen::Vector2d ahead = bsp::fromPooltoolPosition(pooltool + Eigen::Vector2d(0.0, 0.1), table);
  EXPECT_NEAR(std::atan2(ahead.y() - foot_spot.y(), ahead.x() - foot_spot.x()), bsp::fromPooltool(POOLTOOL).phi, 1e-12);
}

// pooltool's closed form for this stroke (cue_strike with a level cue, a = −0.3: ω = (0, 0, −(5/2) a v / R)) spins
// the ball counter-clockwise with ω_z R / v = 5/2 · 0.3 = 0.75, and its squirt (get_squirt_angle, "negative
// deflection is to the right") turns the velocity +0.0215 rad, to the left; FastFiz's gives ω_z R / v = 0.768 (its
// moment of inertia of 160 g against a 163 g ball) and no squirt. This package's engine, with its own cue and tip:
// the same sense of spin and of squirt, and the spin within 5 % of the rigid tip's 0.75 (the tip sticks: the hit
// point's normal leans 17.5° from the cue, inside the friction cone of μ = 0.7).
TEST(StrokeConventions, TheEnginesStrikeHasTheSignsOfPooltoolsAndFastFizs)
{
  const bsp::ShotConfiguration configuration;
  const auto cue = bsp::placeStroke(bsp::fromPooltool(POOLTOOL), {0.0, 0.0}, configuration.ball_radius);
  ASSERT_TRUE(cue.ok()) << cue.error().describe();
  const auto strike = bsp::strikeBall(cue.value(), configuration);
  ASSERT_TRUE(strike.ok()) << strike.error().describe();
  const Eigen::Vector3d v = strike.value().velocity, w = strike.value().angular_velocity;
  EXPECT_GT(w.z(), 0.0);  // counter-clockwise seen from above: right english
  EXPECT_GT(v.y(), 0.0);  // the ball squirts to the left of the cue's line (+x)
  EXPECT_LT(std::atan2(v.y(), v.x()), 0.0215 * 2.0);
  EXPECT_NEAR(w.z() * configuration.ball_radius / v.head<2>().norm(), 0.75, 0.05 * 0.75);
}

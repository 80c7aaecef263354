// Balls touching a rail, and noses too low to hold a ball (issue 23, "Nothing gets through"): a ball placed at a
// cushion and moving into it hits it at once, one moving away leaves it, none ever crosses a nose, a ball leaves the
// table only over a nose, with its bottom above it, and a nose that cannot turn a rolling ball back is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../../src/motion/table_events.hpp"
#include "../fixtures/rail_ids.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace bsp = billiard_shot_planner;
using Type = bsp::MotionEventType;

namespace
{
const double R = 0.0286;

/// Horizontal distance from a nose at which a ball on the cloth touches it.
double reachOf(const bsp::Table& table, double radius = R)
{
  return std::sqrt(radius * radius - std::pow(table.cushion_height - radius, 2));
}

double halfExtent(const bsp::Table& table, int axis)
{
  return 0.5 * (axis == 0 ? table.length : table.width);
}

/// How far (m) the ball overlaps a nose: R minus the distance from the nose line to its centre across the rail.
double noseOverlap(const bsp::BallState& s, const bsp::Table& table, double radius = R)
{
  double deepest = -radius;
  for (int axis = 0; axis < 2; ++axis)
  {
    const double u = halfExtent(table, axis) - std::abs(s.position(axis));
    deepest = std::max(deepest, radius - std::hypot(u, s.position.z() - table.cushion_height));
  }
  return deepest;
}

/// The deepest overlap of a nose along the whole path: every 0.1 ms and at every event.
double deepestOverlap(const bsp::BallTrajectory& t, const bsp::Table& table, double radius = R)
{
  double deepest = -radius;
  for (const auto& s : t.sample(1e-4))
    deepest = std::max(deepest, noseOverlap(s.state, table, radius));
  for (const auto& e : t.events)
    deepest = std::max(deepest, noseOverlap(e.state, table, radius));
  return deepest;
}

/// Whether a ball on the cloth is within the cushions' inner lines (where its centre is when it touches a nose).
bool withinInnerLines(const Eigen::Vector3d& p, const bsp::Table& table, double radius = R)
{
  const double reach = reachOf(table, radius);
  return std::abs(p.x()) <= halfExtent(table, 0) - reach + 1e-9 &&
         std::abs(p.y()) <= halfExtent(table, 1) - reach + 1e-9;
}

/// A ball whose centre touches `rail` (0: −x, 1: +x, 2: −y, 3: +y) on the cloth, `gap` metres inside the table
/// (negative: overlapping the nose), at `along` on the rail's own axis.
bsp::BallState touching(const bsp::Table& table, int rail, double gap, double along, const Eigen::Vector3d& v,
                        const Eigen::Vector3d& w)
{
  const int axis = rail / 2;
  bsp::BallState s;
  s.position(axis) = (rail % 2 == 1 ? 1.0 : -1.0) * (halfExtent(table, axis) - reachOf(table) - gap);
  s.position(1 - axis) = along;
  s.position.z() = R;
  s.velocity = v;
  s.angular_velocity = w;
  return s;
}

bsp::BallTrajectory predicted(const bsp::BallState& start, const bsp::Table& table, const bsp::MotionParameters& p = {})
{
  auto result = bsp::predictTrajectory(start, bsp::BallProperties{0.17, R}, table, p);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().describe());
  return result.ok() ? result.value() : bsp::BallTrajectory{};
}

double speedInto(int rail, const Eigen::Vector3d& v)
{
  return rail % 2 == 1 ? v(rail / 2) : -v(rail / 2);
}
}  // namespace

TEST(RailContact, ABallTouchingARailAndMovingIntoItHitsItAtOnce)
{
  // The two balls, placed exactly where they touch the +y and the −x nose and sent into them. They went
  // through (at rest 2.5 m and 8.8 m off the table): the cushion was looked for only after the start. The same at
  // the edge of the start tolerance (overlapping by 1e-9 m) and 1e-13 m short of touching (the contact then fell
  // below 1e-12 s, the time once taken for the start's own event).
  const bsp::Table table;
  ASSERT_NEAR(halfExtent(table, 1) - reachOf(table), 0.6074560351437924, 1e-15);
  struct Case
  {
    int rail;
    double along;
    Eigen::Vector3d v;
  };
  const Case cases[] = {{3, 0.3, {0.0, 1.0, 0.0}}, {0, 0.2, {-2.0, 0.0, 0.0}}};
  for (const Case& c : cases)
    for (double gap : {0.0, -1e-9, 1e-13})
    {
      const auto t = predicted(touching(table, c.rail, gap, c.along, c.v, Eigen::Vector3d::Zero()), table);
      ASSERT_GE(t.events.size(), 2u);
      const bsp::MotionEvent& hit = t.events[1];
      EXPECT_EQ(hit.type, Type::CushionHit) << c.rail << " " << gap;
      EXPECT_EQ(test_fixtures::railOf(hit.cushion), c.rail);
      EXPECT_LT(hit.time, 1e-12);
      EXPECT_LT(speedInto(c.rail, hit.state.velocity), 0.0) << "it rebounds";
      EXPECT_LE(deepestOverlap(t, table), 1e-9);
      EXPECT_TRUE(t.outcome == bsp::MotionOutcome::Rest || t.outcome == bsp::MotionOutcome::Pocketed);
      if (t.outcome == bsp::MotionOutcome::Rest)
      {
        EXPECT_TRUE(withinInnerLines(t.finalState().position, table));
      }
    }
}

TEST(RailContact, ABallTouchingARailAndMovingAwayOrAlongItLeaves)
{
  const bsp::Table table;
  const Eigen::Vector3d away(0.3, -1.0, 0.0), along(1.0, 0.0, 0.0);
  for (const Eigen::Vector3d& v : {away, along})
  {
    // Rolling: no slip, nothing presses it into the rail.
    const auto t = predicted(touching(table, 3, 0.0, -0.5, v, Eigen::Vector3d::UnitZ().cross(v) / R), table);
    for (const auto& e : t.events)
      if (e.type == Type::CushionHit || e.type == Type::CushionContact)
      {
        EXPECT_GT(e.time, 0.1) << "no contact with the rail it starts at";
      }
    EXPECT_LE(deepestOverlap(t, table), 1e-9);
    EXPECT_NE(t.outcome, bsp::MotionOutcome::AgainstCushion);
  }
}

TEST(RailContact, ABallTouchingARailPressedIntoItByItsSpinEndsAgainstIt)
{
  // At rest against the +y nose with ω_x < 0: the contact slip u_y = v_y + R ω_x < 0, so the cloth's friction drives
  // the ball into the rail. It went through (to y = 0.71 m); sustained contact is not modelled, the path ends there.
  const bsp::Table table;
  const auto start = touching(table, 3, 0.0, 0.3, Eigen::Vector3d::Zero(), {-20.0, 0.0, 0.0});
  const auto t = predicted(start, table);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::AgainstCushion);
  ASSERT_EQ(t.events.back().type, Type::CushionContact);
  EXPECT_EQ(t.events.back().cushion, "rail.top");
  EXPECT_EQ(t.duration(), 0.0);
  EXPECT_LE(deepestOverlap(t, table), 1e-9);
}

TEST(RailContact, AShotOfABallFrozenToTheRailStaysOnTheTable)
{
  // The cue strikes a ball frozen to the +y rail: into the rail level, with topspin, jumping, and along the rail
  // with side spin either way (the tip's end mass squirts it off the cue's line, towards the rail or away).
  bsp::ShotConfiguration configuration;
  const double r = configuration.ball_radius;
  const double reach = std::sqrt(r * r - std::pow(configuration.table.cushion_height - r, 2));
  const Eigen::Vector3d centre(0.3, 0.5 * configuration.table.width - reach, r);
  struct Stroke
  {
    Eigen::Vector3d direction;
    Eigen::Vector3d offset;  ///< where the cue axis passes, from the centre, in radii
  };
  const Stroke strokes[] = {{{0.0, 1.0, 0.0}, {0.0, 0.0, 0.0}},
                            {{0.0, 1.0, 0.0}, {0.0, 0.0, 0.4}},
                            {Eigen::Vector3d(0.0, 1.0, -0.5).normalized(), {0.0, 0.0, 0.4}},
                            {{1.0, 0.0, 0.0}, {0.0, -0.5, 0.0}},
                            {{1.0, 0.0, 0.0}, {0.0, 0.5, 0.0}}};
  int pushed_by_rail = 0;
  for (const Stroke& s : strokes)
  {
    bsp::CuePlacement cue;
    cue.ball = centre.head<2>();
    cue.direction = s.direction;
    cue.speed = 3.0;
    cue.tip = centre + r * s.offset - 3.0 * r * s.direction;  // on the axis through the offset point
    const auto outcome = bsp::predictShot(cue, configuration);
    ASSERT_TRUE(outcome.ok()) << outcome.error().describe();
    const bsp::BallTrajectory& t = outcome.value().trajectory;
    EXPECT_LE(deepestOverlap(t, configuration.table, r), 1e-9);
    EXPECT_NE(t.outcome, bsp::MotionOutcome::TimeLimit);
    EXPECT_NE(t.outcome, bsp::MotionOutcome::OffTable);
    if (t.outcome == bsp::MotionOutcome::Rest)
    {
      EXPECT_TRUE(withinInnerLines(t.finalState().position, configuration.table, r));
    }
    // The rail is part of the strike (one impact with the cue's and the cloth's contacts): its reaction pushes the
    // ball off the rail in the strike, and the motion starts with no second impact at t = 0.
    for (const bsp::StrikeContact& contact : outcome.value().strike.contacts)
      pushed_by_rail += contact.name == "cue-rail.top" && contact.impulse.y() < 0.0;
    EXPECT_FALSE(t.events.size() > 1 && t.events[1].type == Type::CushionHit && t.events[1].time == 0.0);
  }
  EXPECT_GE(pushed_by_rail, 3);  // the three strokes into the rail at least
}

TEST(RailContact, RandomBallsTouchingARailNeverCrossIt)
{
  // 500 balls touching a random rail: exactly, overlapping it within the start tolerance (1e-9 m), or short of it
  // by up to 1e-9 m or by 1e-13 to 1e-10 m; any velocity into, along or away from it, a third of them hopping, any
  // spin; noses from just above the lowest allowed to near the top of the ball, some paths in the plane. Each ends
  // on the cloth within the cushions, against a cushion, in a pocket, or off the table over a nose with its bottom
  // above it; none enters a nose; a ball moving into its rail meets it at once, one moving away does not.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  const double heights[] = {1.27, 1.0, 0.6, 0.3, 1.9};
  int paths = 0, into = 0, away = 0, off_table = 0;
  for (int k = 0; k < 500; ++k)
  {
    bsp::Table table;
    table.cushion_height = heights[k % 5] * R;
    bsp::MotionParameters p;
    p.planar = k % 7 == 0;
    const int rail = static_cast<int>(rng() % 4);
    const int placement = static_cast<int>(rng() % 4);
    const double gap = placement == 0   ? 0.0
                       : placement == 1 ? -1e-9 * unit(rng)
                       : placement == 2 ? 1e-9 * unit(rng)
                                        : std::pow(10.0, -13.0 + 3.0 * unit(rng));
    const double along = 0.85 * halfExtent(table, 1 - rail / 2) * u(rng);
    const double heading = M_PI * u(rng), speed = 0.05 + 4.0 * unit(rng);
    const Eigen::Vector3d v(speed * std::cos(heading), speed * std::sin(heading), k % 3 == 0 ? 1.5 * unit(rng) : 0.0);
    const Eigen::Vector3d w(80.0 * u(rng), 80.0 * u(rng), 50.0 * u(rng));
    const bsp::BallState start = touching(table, rail, gap, along, v, w);
    const auto result = bsp::predictTrajectory(start, bsp::BallProperties{0.17, R}, table, p);
    if (!result.ok())
    {
      EXPECT_EQ(result.error().field, "position") << k;  // a start inside a pocket's capture region
      continue;
    }
    ++paths;
    const bsp::BallTrajectory& t = result.value();
    EXPECT_LE(deepestOverlap(t, table), 1e-9) << k;
    EXPECT_NE(t.outcome, bsp::MotionOutcome::TimeLimit) << k;
    const bsp::MotionEvent& last = t.events.back();
    if (t.outcome == bsp::MotionOutcome::Rest)
    {
      EXPECT_TRUE(withinInnerLines(last.state.position, table)) << k;
    }
    if (t.outcome == bsp::MotionOutcome::AgainstCushion)
    {
      EXPECT_TRUE(std::abs(last.state.position.x()) < halfExtent(table, 0) &&
                  std::abs(last.state.position.y()) < halfExtent(table, 1))
          << k;
    }
    if (t.outcome == bsp::MotionOutcome::OffTable)
    {
      ++off_table;
      const int axis = test_fixtures::railOf(last.cushion) / 2;
      EXPECT_NEAR(std::abs(last.state.position(axis)), halfExtent(table, axis), 1e-9) << k;
      EXPECT_GE(last.state.position.z() - R, table.cushion_height - 1e-9) << k << ": its bottom above the nose";
    }
    // Into or away from the nose along the contact normal: a hop under a nose above the centre moves into it.
    const Eigen::Vector3d v_start = p.planar ? Eigen::Vector3d(v.x(), v.y(), 0.0) : v;
    const double approach = -v_start.dot(
        bsp::detail::cushionNormal(bsp::detail::motionGeometry(table).value().noses[rail], table, start.position));
    const bool met_at_once = t.events.size() > 1 && t.events[1].time == 0.0 &&
                             test_fixtures::railOf(t.events[1].cushion) == rail &&
                             (t.events[1].type == Type::CushionHit || t.events[1].type == Type::CushionContact);
    if (approach > 1e-6)
    {
      ++into;
      EXPECT_TRUE(met_at_once) << k;
    }
    if (approach < -1e-6)
    {
      ++away;
      EXPECT_FALSE(met_at_once) << k;
    }
  }
  EXPECT_GT(paths, 400);
  EXPECT_GT(into, 100);
  EXPECT_GT(away, 100);
  EXPECT_GT(off_table, 0);
}

TEST(RailContact, AHopThatLeavesANoseIsMetWhenItComesBack)
{
  // A ball on a nose below its centre leaves it at 1e-4 m/s along the normal and gravity brings it back after some
  // 2.4e-5 s of a 0.05 s flight. Starting 1e-12 m inside the nose (within round-off of the hit that launched it),
  // its overlap was positive at the first sample: the return was missed and the ball fell into the nose. This is
  // how a ball riding a low nose, hop after hop, went through it.
  bsp::Table table;
  table.cushion_height = 0.5 * R;
  const double elevation = M_PI / 3.0, s = 1e-4, g = 9.81;
  const Eigen::Vector2d n(std::cos(elevation), std::sin(elevation));  // into the table, up
  const double d = R - 1e-12;
  bsp::MotionSegment segment;
  segment.phase = bsp::MotionPhase::Airborne;
  segment.start.position << 0.2, 0.5 * table.width - d * n.x(), table.cushion_height + d * n.y();
  segment.start.velocity << 0.0, -s * n.x(), s * n.y();
  segment.acceleration << 0.0, 0.0, -g;
  const double flight = (s * n.y() + std::sqrt(std::pow(s * n.y(), 2) + 2 * g * (segment.start.position.z() - R))) / g;
  const auto hit = bsp::detail::firstCushionHit(segment, bsp::detail::motionGeometry(table).value(), table, R, flight);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->piece, 3);
  EXPECT_EQ(hit->contact, bsp::detail::NoseContact::Impact);
  EXPECT_NEAR(hit->time, 2.0 * s / (g * n.y()), 0.01 * 2.0 * s / (g * n.y()));
  // Where it meets the nose its centre is one radius from the nose line.
  const Eigen::Vector3d centre = segment.at(hit->time).position;
  EXPECT_NEAR(std::hypot(0.5 * table.width - centre.y(), centre.z() - table.cushion_height), R, 1e-12);
}

TEST(RailContact, ABallRidingALowNoseInTheAirNeverEntersIt)
{
  // A ball sent into the −x rail with side and back spin hops off a nose at 0.3 radii (the lowest allowed is 0.293)
  // and rides it, hop after ever shorter hop. One return was missed and the ball went 7 mm into the nose in the air
  // before falling back onto the cloth. The hops now converge to sustained contact in the air, where the path ends.
  bsp::Table table;
  table.cushion_height = 0.3 * R;
  bsp::BallState start;
  start.position << -1.2495745, 0.27275265890303685, R;
  start.velocity << -2.8106091674145297, -0.59356410072242394, 0.0;
  start.angular_velocity << -15.145023958181881, -10.557883284417279, -40.532021798611119;
  const auto t = predicted(start, table);
  EXPECT_LE(deepestOverlap(t, table), 1e-9);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::AgainstCushion);
  const bsp::MotionEvent& last = t.events.back();
  EXPECT_EQ(last.type, Type::CushionContact);
  EXPECT_EQ(last.cushion, "rail.left");
  EXPECT_GT(last.state.position.z(), R + 1e-3);  // in the air, on the nose
  EXPECT_GT(last.state.position.x(), -0.5 * table.length);
  // Every landing is on the cloth inside the cushions' inner lines.
  for (const auto& e : t.events)
    if (e.type == Type::Landing)
    {
      EXPECT_TRUE(withinInnerLines(e.state.position, table)) << e.time;
    }
}

TEST(CushionHeight, ANoseTooLowToTurnBackABallRollingIntoItIsRefused)
{
  // The physics of the limit: a frictionless, perfectly elastic nose turns a ball rolling straight into it back
  // only if the contact normal rises less than 45° above the cloth, i.e. the nose is above (1 − 1/√2) R.
  for (const double ratio : {bsp::MIN_CUSHION_HEIGHT - 0.01, bsp::MIN_CUSHION_HEIGHT + 0.01})
  {
    const double sin_a = 1.0 - ratio, cos_a = std::sqrt(1.0 - sin_a * sin_a);
    bsp::CushionImpact hit;
    hit.cushion_normal = {0.0, -cos_a, sin_a};  // the +y rail, nose below the centre
    hit.velocity = {0.0, 1.0, 0.0};
    hit.angular_velocity = {-1.0 / R, 0.0, 0.0};
    hit.cushion = {1.0, 0.0, 10.0};
    const auto result = bsp::solve(hit);
    ASSERT_TRUE(result.ok()) << result.error().describe();
    if (ratio < bsp::MIN_CUSHION_HEIGHT)
    {
      EXPECT_GT(result.value().velocity.y(), 0.0) << "still into the rail";
      EXPECT_GT(result.value().velocity.z(), 0.0) << "and up over the nose";
    }
    else
    {
      EXPECT_LT(result.value().velocity.y(), 0.0) << "turned back";
    }
  }
  // The nose of 0.1 mm, just below the limit, and the limit itself.
  bsp::Table table;
  const bsp::BallState start = touching(table, 3, 0.5, 0.3, {0.0, 1.0, 0.0}, Eigen::Vector3d::Zero());
  bsp::MotionParameters planar;
  planar.planar = true;
  for (const double h : {0.0001, bsp::MIN_CUSHION_HEIGHT * R * (1.0 - 1e-12)})
  {
    table.cushion_height = h;
    const auto result = bsp::predictTrajectory(start, bsp::BallProperties{0.17, R}, table, planar);
    ASSERT_FALSE(result.ok()) << h;
    EXPECT_EQ(result.error().field, "table.cushion_height");
  }
  table.cushion_height = bsp::MIN_CUSHION_HEIGHT * R;
  EXPECT_TRUE(bsp::predictTrajectory(start, bsp::BallProperties{0.17, R}, table, planar).ok());
  bsp::ShotConfiguration configuration;
  configuration.table.cushion_height = 0.0001;
  ASSERT_FALSE(bsp::validate(configuration).ok());
  EXPECT_EQ(bsp::validate(configuration).error().field, "table.cushion_height");
}

TEST(RailContact, InThePlaneABallRollingIntoALowNoseStaysOnTheTable)
{
  // A nose at 0.3 radii turns no rolling ball back (0.32 radii would, with this cushion's friction): every
  // hit leaves it moving into the rail, and up. In the plane the rise is dropped, so the ball meets the nose again
  // at once, slower each time. It went through after the first hit and came to rest 0.26 m off the table. Now the
  // hits converge and the path ends against the cushion.
  bsp::Table table;
  table.cushion_height = 0.3 * R;
  bsp::MotionParameters planar;
  planar.planar = true;
  bsp::BallState start;
  start.position << 0.3, 0.0, R;
  start.velocity << 0.0, 1.0, 0.0;
  start.angular_velocity << -1.0 / R, 0.0, 0.0;
  const auto t = predicted(start, table, planar);
  EXPECT_LE(deepestOverlap(t, table), 1e-9);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::AgainstCushion);
  EXPECT_TRUE(withinInnerLines(t.finalState().position, table));
  EXPECT_LT(speedInto(3, t.finalState().velocity), 1e-6);
  int hits = 0;
  for (const auto& e : t.events)
    if (e.type == Type::CushionHit)
    {
      ++hits;
      EXPECT_EQ(e.cushion, "rail.top");
    }
  EXPECT_GE(hits, 2);
}

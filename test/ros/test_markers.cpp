// The marker builder's rules (rviz's conventions for marker arrays): DELETEALL first, one namespace per meaning with
// unique ids, a LINE_STRIP with at least two points and one colour per point, ARROWs with exactly two points, the table
// frame.
#include <gtest/gtest.h>

#include "billiard_shot_planner/motion/table_outline.hpp"

#include <map>
#include <set>

#include "shot_fixtures.hpp"
#include "trajectory_markers.hpp"

namespace bsp = billiard_shot_planner;
using visualization_msgs::Marker;

namespace
{
visualization_msgs::MarkerArray masseMarkers()
{
  const bsp::ShotConfiguration configuration = shot_fixtures::paperShooter();
  const auto outcome = bsp::predictShot(shot_fixtures::masse(), configuration);
  EXPECT_TRUE(outcome.ok());
  return bsp::trajectoryMarkers(outcome.value(), configuration, "table", 0.01);
}
}  // namespace

TEST(TrajectoryMarkers, DeleteAllFirstThenUniqueIdsPerNamespace)
{
  const auto array = masseMarkers();
  ASSERT_GT(array.markers.size(), 10u);
  EXPECT_EQ(array.markers.front().action, Marker::DELETEALL);
  std::map<std::string, std::set<int>> ids;
  for (std::size_t i = 1; i < array.markers.size(); ++i)
  {
    const Marker& m = array.markers[i];
    EXPECT_EQ(m.action, Marker::ADD);
    EXPECT_TRUE(ids[m.ns].insert(m.id).second) << m.ns << " " << m.id;
    EXPECT_EQ(m.header.frame_id, "table");
    EXPECT_GT(m.color.a, 0.0f);
    EXPECT_DOUBLE_EQ(m.lifetime.toSec(), 0.0);
  }
  for (const char* ns : {"trajectory", "ball_start", "ball_end", "velocity", "spin", "hit_point", "cue", "events",
                         "table", "cushions", "jaw_points", "pockets"})
    EXPECT_EQ(ids.count(ns), 1u) << ns;
}

TEST(TrajectoryMarkers, GeometryRules)
{
  for (const Marker& m : masseMarkers().markers)
  {
    if (m.type == Marker::LINE_STRIP)
    {
      EXPECT_GE(m.points.size(), 2u);
      EXPECT_EQ(m.colors.size(), m.points.size());
      EXPECT_GT(m.scale.x, 0.0);
    }
    if (m.type == Marker::ARROW)
    {
      EXPECT_EQ(m.points.size(), 2u) << m.ns;
    }
  }
}

TEST(TrajectoryMarkers, PathColouredByPhase)
{
  const auto array = masseMarkers();
  const Marker* path = nullptr;
  for (const Marker& m : array.markers)
    if (m.ns == "trajectory")
      path = &m;
  ASSERT_TRUE(path);
  std::set<std::tuple<float, float, float>> colours;
  for (const auto& c : path->colors)
    colours.insert({c.r, c.g, c.b});
  // The massé ball hops, slides and rolls.
  for (bsp::MotionPhase phase : {bsp::MotionPhase::Airborne, bsp::MotionPhase::Sliding, bsp::MotionPhase::Rolling})
  {
    const auto c = bsp::phaseColour(phase);
    EXPECT_EQ(colours.count({c.r, c.g, c.b}), 1u) << bsp::toString(phase);
  }
  // The velocity arrow starts at the ball and points along the launch velocity (0.1 m per m/s).
  for (const Marker& m : array.markers)
    if (m.ns == "velocity")
    {
      EXPECT_NEAR(m.points[1].x - m.points[0].x, 0.1 * -2.0733, 1e-3);
    }
}

// A table: every object ball gets its path (two points at least), its start, its id as a label, and the ghost ball
// marks where the cue ball first touched another ball; the rules above hold for them too.
TEST(TrajectoryMarkers, EveryBallOfTheTableIsDrawnWithItsId)
{
  const bsp::ShotConfiguration configuration;
  bsp::CuePlacement cue = shot_fixtures::follow();
  bsp::TableBall one{"one", {}}, two{"two", {}};
  one.state.position << cue.ball.x() + 0.3, cue.ball.y(), 0.0;
  two.state.position << cue.ball.x(), cue.ball.y() + 0.4, 0.0;  // off the line: never touched
  const auto outcome = bsp::predictShot(cue, configuration, {one, two});
  ASSERT_TRUE(outcome.ok()) << outcome.error().describe();
  const auto array = bsp::trajectoryMarkers(outcome.value(), configuration, "table", 0.01);
  std::map<std::string, std::set<int>> ids;
  std::set<std::string> labels;
  for (std::size_t i = 1; i < array.markers.size(); ++i)
  {
    const Marker& m = array.markers[i];
    EXPECT_TRUE(ids[m.ns].insert(m.id).second) << m.ns << " " << m.id;
    if (m.type == Marker::LINE_STRIP)
    {
      EXPECT_GE(m.points.size(), 2u) << m.ns;
    }
    if (m.ns == "object_ids")
      labels.insert(m.text);
  }
  EXPECT_EQ(ids["object_paths"].size(), 2u);
  EXPECT_EQ(ids["object_balls"].size(), 2u);
  EXPECT_EQ(labels, (std::set<std::string>{"one", "two"}));
  EXPECT_EQ(ids["ghost_ball"].size(), 1u);
}

// A frozen shot draws the strike's touching pair (one line from the cue ball to the ball it touches) and the velocity
// the strike gave that ball; a lone strike draws neither.
TEST(TrajectoryMarkers, FrozenShotDrawsTheBallsOfTheStrike)
{
  const bsp::ShotConfiguration configuration;
  const bsp::ShotOutcome frozen = shot_fixtures::frozenFollow(configuration);
  ASSERT_FALSE(frozen.strike.other_balls.empty());
  int pairs = 0, velocities = 0;
  for (const Marker& m : bsp::trajectoryMarkers(frozen, configuration, "table", 0.01).markers)
  {
    if (m.ns == "strike_contacts")
    {
      ASSERT_EQ(m.points.size(), 2u);
      EXPECT_NEAR(std::hypot(m.points[1].x - m.points[0].x, m.points[1].y - m.points[0].y),
                  2.0 * configuration.ball_radius, 1e-9);
      ++pairs;
    }
    velocities += m.ns == "strike_velocity";
  }
  EXPECT_EQ(pairs, 1);
  EXPECT_EQ(velocities, 1);
  const bsp::CuePlacement cue = shot_fixtures::follow();
  bsp::TableBall apart{"one", {}};
  apart.state.position << cue.ball.x() + 0.3, cue.ball.y(), configuration.ball_radius;
  const auto lone = bsp::predictShot(cue, configuration, {apart});
  ASSERT_TRUE(lone.ok());
  for (const Marker& m : bsp::trajectoryMarkers(lone.value(), configuration, "table", 0.01).markers)
    EXPECT_TRUE(m.ns != "strike_contacts" && m.ns != "strike_velocity") << m.ns;
}

// The table alone, as the node draws it before its first answer: the cloth of the table's size, a block behind each
// straight nose of its outline (six rails between the pockets, two jaw facings per pocket), a line along each rounded
// jaw point and a disc per capture region, after a DELETEALL; a carom table's four rails and nothing else.
TEST(TrajectoryMarkers, TheTableAloneIsItsClothCushionsAndPockets)
{
  bsp::Table table;
  table.length = 3.0;
  table.width = 1.5;
  const auto array = bsp::tableMarkers(table, "table");
  ASSERT_FALSE(array.markers.empty());
  EXPECT_EQ(array.markers.front().action, visualization_msgs::Marker::DELETEALL);
  std::map<std::string, int> count;
  for (const auto& m : array.markers)
  {
    ++count[m.ns];
    EXPECT_EQ(m.header.frame_id, "table");
    if (m.ns == "table")
    {
      EXPECT_EQ(m.scale.x, 3.0);
      EXPECT_EQ(m.scale.y, 1.5);
    }
  }
  EXPECT_EQ(count["table"], 1);
  EXPECT_EQ(count["cushions"], 6 + 6 * 2);
  EXPECT_EQ(count["jaw_points"], 6 * 2);
  EXPECT_EQ(count["pockets"], static_cast<int>(table.pockets.size()));
  // Each block lies behind its nose, along it: the bottom rails' blocks below y = -width/2, turned along x.
  for (const auto& m : array.markers)
    if (m.ns == "cushions" && std::abs(m.pose.orientation.z) < 1e-12 && m.pose.position.y < 0.0)
    {
      EXPECT_NEAR(m.pose.position.y, -0.75 - 0.025, 1e-12);
    }

  // Under the jaws' model the pockets drawn are the drop regions behind the shelves.
  bsp::Table jaws = table;
  jaws.pocket_model = bsp::PocketModel::Jaws;
  const auto outline = bsp::tableOutline(jaws).value();
  int drops = 0;
  for (const auto& m : bsp::tableMarkers(jaws, "table").markers)
    if (m.ns == "pockets")
    {
      const auto& opening = outline.pockets[static_cast<std::size_t>(m.id)];
      EXPECT_DOUBLE_EQ(m.pose.position.x, opening.drop_centre.x());
      EXPECT_DOUBLE_EQ(m.pose.position.y, opening.drop_centre.y());
      EXPECT_DOUBLE_EQ(m.scale.x, 2.0 * opening.drop_radius);
      ++drops;
    }
  EXPECT_EQ(drops, 6);

  table.pocket_layout = bsp::PocketLayout::None;
  table.pockets.clear();
  count.clear();
  for (const auto& m : bsp::tableMarkers(table, "table").markers)
    ++count[m.ns];
  EXPECT_EQ(count["cushions"], 4);
  EXPECT_EQ(count["jaw_points"], 0);
  EXPECT_EQ(count["pockets"], 0);
}

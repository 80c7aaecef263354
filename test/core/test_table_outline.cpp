// The table's geometry against the cut it is built from: every figure here is measured back from the segments by
// plane geometry (lines intersected, angles between directions, distances to lines) and compared with the WPA
// specification's numbers the table was given, not with the builder's own arithmetic.
#include <gtest/gtest.h>

#include "billiard_shot_planner/motion/table_outline.hpp"

#include <cmath>
#include <functional>
#include <random>
#include <set>

namespace bsp = billiard_shot_planner;
using Eigen::Vector2d;

namespace
{
constexpr double PI = 3.14159265358979323846;
constexpr double INCH = 0.0254;

double cross(const Vector2d& a, const Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

/// Where the lines through two straight segments cross.
Vector2d intersection(const bsp::NoseSegment& a, const bsp::NoseSegment& b)
{
  const Vector2d da = a.end - a.start, db = b.end - b.start;
  const double along = cross(b.start - a.start, db) / cross(da, db);
  return a.start + along * da;
}

double distanceToLine(const Vector2d& point, const bsp::NoseSegment& segment)
{
  const Vector2d along = (segment.end - segment.start).normalized();
  return std::abs(cross(along, point - segment.start));
}

const bsp::NoseSegment& segment(const bsp::TableOutline& geometry, const std::string& id)
{
  const bsp::NoseSegment* found = geometry.cushion(id);
  if (!found)
    throw std::runtime_error("no segment " + id);
  return *found;
}

bsp::TableOutline built(const bsp::Table& table)
{
  auto geometry = bsp::tableOutline(table);
  if (!geometry)
    throw std::runtime_error(geometry.error().describe());
  return geometry.value();
}

/// A pocket's jaws: the rail each ends, its facing and the pocket's cut.
struct JawCase
{
  std::string pocket, rail, jaw;
  bool corner;
};

const std::vector<JawCase>& jawCases()
{
  static const std::vector<JawCase> cases{{"bottom_left", "rail.left", "left", true},
                                          {"bottom_left", "rail.bottom.left", "bottom", true},
                                          {"bottom_side", "rail.bottom.left", "left", false},
                                          {"bottom_side", "rail.bottom.right", "right", false},
                                          {"bottom_right", "rail.bottom.right", "bottom", true},
                                          {"bottom_right", "rail.right", "right", true},
                                          {"top_right", "rail.right", "right", true},
                                          {"top_right", "rail.top.right", "top", true},
                                          {"top_side", "rail.top.right", "right", false},
                                          {"top_side", "rail.top.left", "left", false},
                                          {"top_left", "rail.top.left", "top", true},
                                          {"top_left", "rail.left", "left", true}};
  return cases;
}
}  // namespace

TEST(TableOutline, ThePocketsMouthsAndCutsAreTheWpaSpecifications)
{
  const bsp::Table table;  // the 9-ft table
  const bsp::TableOutline geometry = built(table);
  ASSERT_EQ(geometry.pockets.size(), 6u);
  for (const bsp::PocketOpening& pocket : geometry.pockets)
  {
    // The jaw points: where each rail's nose line meets its facing's line.
    std::vector<Vector2d> points;
    for (const JawCase& jaw : jawCases())
      if (jaw.pocket == pocket.id)
        points.push_back(intersection(segment(geometry, jaw.rail),
                                      segment(geometry, "pocket." + pocket.id + ".jaw." + jaw.jaw + ".facing")));
    ASSERT_EQ(points.size(), 2u) << pocket.id;
    const double mouth = (points[0] - points[1]).norm();
    const bool corner = pocket.id.find("side") == std::string::npos;
    // WPA: corner mouth 4.5-4.625 in, side 5-5.125 in, between the points where the noses turn into the pocket.
    if (corner)
    {
      EXPECT_GE(mouth, 4.5 * INCH - 1e-12) << pocket.id;
      EXPECT_LE(mouth, 4.625 * INCH + 1e-12) << pocket.id;
    }
    else
    {
      EXPECT_GE(mouth, 5.0 * INCH - 1e-12) << pocket.id;
      EXPECT_LE(mouth, 5.125 * INCH + 1e-12) << pocket.id;
    }
    EXPECT_NEAR(mouth, pocket.mouth(), 1e-12) << pocket.id;
    // WPA's shelf, from the mouth's middle to the slate's cut: corner 1-2.25 in, side 0-0.375 in.
    const Vector2d middle = 0.5 * (points[0] + points[1]);
    const double shelf = (pocket.drop_centre - middle).norm() - pocket.drop_radius;
    EXPECT_GE(shelf, (corner ? 1.0 : 0.0) * INCH - 1e-12) << pocket.id;
    EXPECT_LE(shelf, (corner ? 2.25 : 0.375) * INCH + 1e-12) << pocket.id;
    // The drop region lies on the pocket's axis, square to the mouth.
    EXPECT_NEAR((points[1] - points[0]).dot(pocket.drop_centre - middle), 0.0, 1e-12) << pocket.id;
  }
  for (const JawCase& jaw : jawCases())
  {
    // WPA: the cushion is cut at 142 deg (corner) and 104 deg (side) between its nose and its facing, +-1 deg.
    const std::string facing_id = "pocket." + jaw.pocket + ".jaw." + jaw.jaw + ".facing";
    const bsp::NoseSegment& rail = segment(geometry, jaw.rail);
    const bsp::NoseSegment& facing = segment(geometry, facing_id);
    const Vector2d tip = intersection(rail, facing);
    const Vector2d back_along_rail =
        (((rail.start - tip).norm() > (rail.end - tip).norm() ? rail.start : rail.end) - tip).normalized();
    const Vector2d into_pocket =
        (((facing.start - tip).norm() > (facing.end - tip).norm() ? facing.start : facing.end) - tip).normalized();
    const double angle = std::acos(back_along_rail.dot(into_pocket)) * 180.0 / PI;
    EXPECT_NEAR(angle, jaw.corner ? 142.0 : 104.0, 1.0) << facing_id;
    EXPECT_NEAR(angle, jaw.corner ? table.corner_pockets.facing_angle : table.side_pockets.facing_angle, 1e-9)
        << facing_id;
  }
}

TEST(TableOutline, EachJawsRoundingTouchesItsRailAndFacingAndTheOutlineIsUnbroken)
{
  const bsp::Table table;
  const bsp::TableOutline geometry = built(table);
  // Six rails, and per pocket two jaws of a facing and a rounded point.
  ASSERT_EQ(geometry.cushions.size(), 6u + 6u * 4u);
  std::set<std::string> ids;
  for (const bsp::NoseSegment& segment : geometry.cushions)
    EXPECT_TRUE(ids.insert(segment.id).second) << segment.id;
  for (const JawCase& jaw : jawCases())
  {
    const std::string prefix = "pocket." + jaw.pocket + ".jaw." + jaw.jaw;
    const bsp::NoseSegment& point = segment(geometry, prefix + ".point");
    ASSERT_EQ(point.shape, bsp::NoseSegment::Shape::Arc) << prefix;
    EXPECT_EQ(point.radius, jaw.corner ? table.corner_pockets.jaw_radius : table.side_pockets.jaw_radius);
    EXPECT_NEAR(distanceToLine(point.centre, segment(geometry, jaw.rail)), point.radius, 1e-12) << prefix;
    EXPECT_NEAR(distanceToLine(point.centre, segment(geometry, prefix + ".facing")), point.radius, 1e-12) << prefix;
    EXPECT_NEAR((point.start - point.centre).norm(), point.radius, 1e-12) << prefix;
    EXPECT_NEAR((point.end - point.centre).norm(), point.radius, 1e-12) << prefix;
  }
  // Walking the outline, each segment starts where the one before ends, except across a pocket's opening (from
  // one facing into the pocket to the next one out of it); the cloth lies on the left of each straight piece.
  int openings = 0;
  for (std::size_t i = 0; i < geometry.cushions.size(); ++i)
  {
    const bsp::NoseSegment& here = geometry.cushions[i];
    const bsp::NoseSegment& next = geometry.cushions[(i + 1) % geometry.cushions.size()];
    if ((here.end - next.start).norm() > 1e-12)
    {
      ++openings;
      EXPECT_NE(here.id.find(".facing"), std::string::npos) << here.id;
      EXPECT_NE(next.id.find(".facing"), std::string::npos) << next.id;
    }
    if (here.shape == bsp::NoseSegment::Shape::Line && here.id.rfind("rail.", 0) == 0)
    {
      EXPECT_GT(cross(here.end - here.start, -here.start), 0.0) << here.id;  // the table's centre on the left
    }
  }
  EXPECT_EQ(openings, 6);
}

TEST(TableOutline, RailsAndPocketsFollowTheTablesSize)
{
  bsp::Table table;
  table.length = 92.0 * INCH;  // WPA's 8-ft table
  table.width = 46.0 * INCH;
  const bsp::TableOutline geometry = built(table);
  const double x = 0.5 * table.length, y = 0.5 * table.width;
  for (const char* id : {"rail.bottom.left", "rail.bottom.right"})
  {
    EXPECT_NEAR(segment(geometry, id).start.y(), -y, 1e-15) << id;
    EXPECT_NEAR(segment(geometry, id).end.y(), -y, 1e-15) << id;
  }
  EXPECT_NEAR(segment(geometry, "rail.right").start.x(), x, 1e-15);
  EXPECT_NEAR(segment(geometry, "rail.left").end.x(), -x, 1e-15);
  // The corner pocket's jaw points stand mouth/sqrt(2) from the corner along each rail, the side's mouth/2 from
  // the rail's middle.
  const bsp::PocketOpening* corner = geometry.pocket("top_right");
  ASSERT_NE(corner, nullptr);
  const double along = table.corner_pockets.mouth / std::sqrt(2.0);
  EXPECT_NEAR((corner->jaw_in - Vector2d(x, y - along)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((corner->jaw_out - Vector2d(x - along, y)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(corner->axis.dot(Vector2d(1, 1).normalized()), 1.0, 1e-15);
  const bsp::PocketOpening* side = geometry.pocket("bottom_side");
  ASSERT_NE(side, nullptr);
  EXPECT_NEAR(side->mouthMiddle().x(), 0.0, 1e-15);
  EXPECT_NEAR(side->mouthMiddle().y(), -y, 1e-15);
  EXPECT_NEAR(side->axis.y(), -1.0, 1e-15);
}

TEST(TableOutline, ACaromTableIsFourRailsAndNoPockets)
{
  bsp::Table table;
  table.length = 2.84;  // UMB's match table
  table.width = 1.42;
  table.pocket_layout = bsp::PocketLayout::None;
  table.pockets.clear();
  const bsp::TableOutline geometry = built(table);
  EXPECT_TRUE(geometry.pockets.empty());
  ASSERT_EQ(geometry.cushions.size(), 4u);
  double perimeter = 0.0;
  for (std::size_t i = 0; i < 4; ++i)
  {
    perimeter += geometry.cushions[i].length();
    EXPECT_EQ(geometry.cushions[i].end, geometry.cushions[(i + 1) % 4].start);
  }
  EXPECT_NEAR(perimeter, 2.0 * (2.84 + 1.42), 1e-12);
  // A carom table that lists capture regions contradicts itself.
  table.pockets = bsp::sixPockets(2.84, 1.42);
  const auto refused = bsp::tableOutline(table);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().field, "table.pockets");
}

TEST(TableOutline, ABallFallsOnceItsCentrePassesTheShelf)
{
  const bsp::Table table;
  const bsp::TableOutline geometry = built(table);
  for (const bsp::PocketOpening& pocket : geometry.pockets)
  {
    const bool corner = pocket.id.find("side") == std::string::npos;
    const double shelf = corner ? table.corner_pockets.shelf : table.side_pockets.shelf;
    const Vector2d edge = pocket.mouthMiddle() + shelf * pocket.axis;
    EXPECT_FALSE(pocket.drops(edge - 1e-9 * pocket.axis)) << pocket.id;
    EXPECT_TRUE(pocket.drops(edge + 1e-9 * pocket.axis)) << pocket.id;
    EXPECT_FALSE(pocket.drops(Vector2d::Zero())) << pocket.id;
  }
}

TEST(TableOutline, TheNearestPointOfARoundedJawIsOnItsArcOrAtAnEnd)
{
  bsp::NoseSegment arc;
  arc.shape = bsp::NoseSegment::Shape::Arc;
  arc.centre = {0, 0};
  arc.radius = 0.01;
  arc.start = {0.01, 0};
  arc.end = {0, -0.01};
  arc.sweep = -0.5 * PI;  // clockwise through the fourth quadrant
  const Vector2d middle = arc.closestPoint({1, -1});
  EXPECT_NEAR((middle - Vector2d(0.01, -0.01) / std::sqrt(2.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(arc.closestPoint({1, 1}), arc.start);    // beyond the start
  EXPECT_EQ(arc.closestPoint({-1, -0.5}), arc.end);  // beyond the end
  EXPECT_NEAR(arc.length(), 0.005 * PI, 1e-15);
  bsp::NoseSegment rail;
  rail.start = {0, 0};
  rail.end = {1, 0};
  EXPECT_EQ(rail.closestPoint({0.3, 0.2}), Vector2d(0.3, 0));
  EXPECT_EQ(rail.closestPoint({-2, 0.2}), rail.start);
}

TEST(TableOutline, CutsThatCannotBeBuiltNameTheirField)
{
  const auto refused_for = [](const std::function<void(bsp::Table&)>& change)
  {
    bsp::Table table;
    change(table);
    const auto geometry = bsp::tableOutline(table);
    return geometry.ok() ? std::string("accepted") : geometry.error().field;
  };
  // A side mouth wider than the rail from the corner pocket's jaw.
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.side_pockets.mouth = 2.4; }), "table.side_pockets.mouth");
  // Facings cut at 170 deg in a side pocket close within the shelf.
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.side_pockets.facing_angle = 170.0; }), "table.side_pockets.facing_angle");
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.corner_pockets.facing_angle = 200.0; }),
            "table.corner_pockets.facing_angle");
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.corner_pockets.jaw_radius = 1.0; }), "table.corner_pockets.jaw_radius");
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.corner_pockets.drop_radius = 0.0; }), "table.corner_pockets.drop_radius");
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.side_pockets.mouth = std::nan(""); }), "table.side_pockets.mouth");
  EXPECT_EQ(refused_for([](bsp::Table& t) { t.side_pockets.jaw_radius = 0.0; }), "accepted");
}

// The closed-form fit that validate() checks against the outline it lets through: for random cuts, every accepted one
// lays out rails of positive length and facings that end on their own sides of their pocket's axis; and at the
// boundary where a side pocket's facings meet at the drop region's depth, a cut a hair inside is accepted and lays
// out facings a hair apart, one a hair beyond is refused.
TEST(TableOutline, EveryCutThatValidatesLaysOutAndTheBoundaryIsWhereTheFacingsMeet)
{
  std::mt19937 random(38);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int accepted = 0;
  for (int draw = 0; draw < 2000; ++draw)
  {
    bsp::Table table;
    for (bsp::PocketCut* cut : {&table.corner_pockets, &table.side_pockets})
    {
      cut->mouth = 0.05 + 1.2 * unit(random);
      cut->facing_angle = 90.0 + 90.0 * unit(random);
      cut->shelf = 0.1 * unit(random);
      cut->jaw_radius = 0.05 * unit(random);
      cut->drop_radius = 0.01 + 0.1 * unit(random);
    }
    if (!bsp::validate(table).ok())
      continue;
    ++accepted;
    const bsp::TableOutline outline = built(table);
    for (const bsp::NoseSegment& piece : outline.cushions)
      if (piece.id.rfind("rail.", 0) == 0)
      {
        EXPECT_GT(piece.length(), 0.0) << piece.id;
        EXPECT_GT(cross(piece.end - piece.start, -piece.start), 0.0) << piece.id;  // not turned back
      }
    for (const bsp::PocketOpening& pocket : outline.pockets)
    {
      const Vector2d middle = pocket.mouthMiddle();
      const double side_in = cross(pocket.axis, pocket.jaw_in - middle);
      for (const bsp::NoseSegment& piece : outline.cushions)
        if (piece.id.rfind("pocket." + pocket.id + ".", 0) == 0 && piece.id.find(".facing") != std::string::npos)
        {
          const Vector2d deep =
              (piece.start - middle).dot(pocket.axis) > (piece.end - middle).dot(pocket.axis) ? piece.start : piece.end;
          const Vector2d shallow = deep == piece.start ? piece.end : piece.start;
          EXPECT_GT(cross(pocket.axis, deep - middle) * cross(pocket.axis, shallow - middle), 0.0) << piece.id;
        }
      EXPECT_NE(side_in, 0.0);
    }
  }
  EXPECT_GT(accepted, 100);

  bsp::Table table;
  const bsp::PocketCut& side = table.side_pockets;
  const double depth = side.shelf + side.drop_radius;
  const double meeting = 90.0 + std::atan(0.5 * side.mouth / depth) * 180.0 / PI;
  table.side_pockets.facing_angle = meeting - 1e-6;
  const bsp::TableOutline inside = built(table);
  const bsp::NoseSegment& left = segment(inside, "pocket.bottom_side.jaw.left.facing");
  const bsp::NoseSegment& right = segment(inside, "pocket.bottom_side.jaw.right.facing");
  EXPECT_GT(right.start.x() - left.end.x(), 0.0);
  EXPECT_LT(right.start.x() - left.end.x(), 1e-6);
  table.side_pockets.facing_angle = meeting + 1e-6;
  const auto beyond = bsp::tableOutline(table);
  ASSERT_FALSE(beyond.ok());
  EXPECT_EQ(beyond.error().field, "table.side_pockets.facing_angle");
}

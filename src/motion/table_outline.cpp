#include "billiard_shot_planner/motion/table_outline.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "billiard_shot_planner/core/plane_geometry.hpp"

namespace billiard_shot_planner
{
namespace
{
Eigen::Vector2d rotated(const Eigen::Vector2d& v, double angle)
{
  return Eigen::Rotation2Dd(angle) * v;
}

/// Where the outline meets a pocket: the pocket's middle point on the rectangle (a corner, or the middle of a long
/// rail), the rails' directions as the outline walks in and out, and the names of its jaws (the rails they end).
struct PocketPlace
{
  const char* id;
  Eigen::Vector2d place;
  Eigen::Vector2d in;  ///< the incoming rail's direction
  Eigen::Vector2d out;
  bool corner;
  const char* jaw_in;
  const char* jaw_out;
  const char* rail_after;  ///< the rail from this pocket to the next
};

std::vector<PocketPlace> sixPocketPlaces(double x, double y)
{
  const Eigen::Vector2d east(1, 0), north(0, 1);
  return {{"bottom_left", {-x, -y}, -north, east, true, "left", "bottom", "rail.bottom.left"},
          {"bottom_side", {0, -y}, east, east, false, "left", "right", "rail.bottom.right"},
          {"bottom_right", {x, -y}, east, north, true, "bottom", "right", "rail.right"},
          {"top_right", {x, y}, north, -east, true, "right", "top", "rail.top.right"},
          {"top_side", {0, y}, -east, -east, false, "right", "left", "rail.top.left"},
          {"top_left", {-x, y}, -east, -north, true, "top", "left", "rail.left"}};
}

NoseSegment line(std::string id, const Eigen::Vector2d& start, const Eigen::Vector2d& end)
{
  NoseSegment segment;
  segment.id = std::move(id);
  segment.start = start;
  segment.end = end;
  return segment;
}

/// A jaw: the sharp point where the rail's nose meets the facing, rounded by an arc tangent to both.
struct Jaw
{
  Eigen::Vector2d rail_end;  ///< where the straight rail stops (the arc's tangent point on it)
  NoseSegment point;         ///< the rounding (absent when the radius is 0)
  NoseSegment facing;        ///< walked in the outline's direction
  bool rounded = false;
};

/// The jaw at `tip` whose rail runs along `rail` (unit, pointing from the rail to the pocket) and whose facing runs
/// into the pocket along `facing` (unit). `entering`: the outline walks rail → point → facing (else the reverse).
Jaw jawAt(const std::string& id, const Eigen::Vector2d& tip, const Eigen::Vector2d& rail, const Eigen::Vector2d& facing,
          double facing_length, double cut_angle, double radius, bool entering)
{
  const double tangent = radius / std::tan(0.5 * cut_angle);
  const Eigen::Vector2d on_rail = tip - tangent * rail, on_facing = tip + tangent * facing;
  Jaw jaw;
  jaw.rail_end = on_rail;
  jaw.rounded = radius > 0.0;
  const Eigen::Vector2d facing_end = tip + facing_length * facing;
  jaw.facing = entering ? line(id + ".facing", on_facing, facing_end) : line(id + ".facing", facing_end, on_facing);
  jaw.point.id = id + ".point";
  jaw.point.shape = NoseSegment::Shape::Arc;
  jaw.point.radius = radius;
  jaw.point.centre = tip + (facing - rail).normalized() * (radius / std::sin(0.5 * cut_angle));
  jaw.point.start = entering ? on_rail : on_facing;
  jaw.point.end = entering ? on_facing : on_rail;
  jaw.point.sweep = -(M_PI - cut_angle);  // the outline turns right, around the cushion, by the cut's supplement
  return jaw;
}

struct PocketLayoutParts
{
  PocketOpening opening;
  Jaw in, out;
};

PocketLayoutParts layPocket(const PocketPlace& place, const PocketCut& cut)
{
  const double cut_angle = cut.cutAngle();
  PocketLayoutParts parts;
  PocketOpening& opening = parts.opening;
  opening.id = place.id;
  if (place.corner)
  {
    const double along = cut.mouth / std::sqrt(2.0);
    opening.jaw_in = place.place - along * place.in;
    opening.jaw_out = place.place + along * place.out;
    opening.axis = (place.in - place.out).normalized();
  }
  else
  {
    opening.jaw_in = place.place - 0.5 * cut.mouth * place.in;
    opening.jaw_out = place.place + 0.5 * cut.mouth * place.in;
    opening.axis = -rotated(place.in, 0.5 * M_PI);
  }
  // Each facing leaves its rail turned into the cushion by the cut's supplement.
  const Eigen::Vector2d facing_in = rotated(place.in, -(M_PI - cut_angle));
  const Eigen::Vector2d facing_out = rotated(-place.out, M_PI - cut_angle);
  const double depth = cut.shelf + cut.drop_radius;  // the facings reach the drop region's middle
  const double facing_length = depth / facing_in.dot(opening.axis);
  opening.drop_centre = opening.mouthMiddle() + depth * opening.axis;
  opening.drop_radius = cut.drop_radius;
  const std::string jaws = "pocket." + opening.id + ".jaw.";
  parts.in =
      jawAt(jaws + place.jaw_in, opening.jaw_in, place.in, facing_in, facing_length, cut_angle, cut.jaw_radius, true);
  parts.out = jawAt(jaws + place.jaw_out, opening.jaw_out, -place.out, facing_out, facing_length, cut_angle,
                    cut.jaw_radius, false);
  return parts;
}

void appendJaw(std::vector<NoseSegment>& cushions, const Jaw& jaw, bool entering)
{
  if (!entering)
    cushions.push_back(jaw.facing);
  if (jaw.rounded)
    cushions.push_back(jaw.point);
  if (entering)
    cushions.push_back(jaw.facing);
}

TableOutline caromGeometry(double x, double y)
{
  TableOutline outline;
  outline.cushions = {line("rail.bottom", {-x, -y}, {x, -y}), line("rail.right", {x, -y}, {x, y}),
                      line("rail.top", {x, y}, {-x, y}), line("rail.left", {-x, y}, {-x, -y})};
  return outline;
}
}  // namespace

double NoseSegment::length() const
{
  return shape == Shape::Line ? (end - start).norm() : std::abs(sweep) * radius;
}

Eigen::Vector2d NoseSegment::closestPoint(const Eigen::Vector2d& point) const
{
  if (shape == Shape::Line)
  {
    const Eigen::Vector2d along = end - start;
    const double squared = along.squaredNorm();
    const double fraction = squared > 0.0 ? std::clamp((point - start).dot(along) / squared, 0.0, 1.0) : 0.0;
    return start + fraction * along;
  }
  // The arc's angle from its start to the point, measured in the arc's own sense; beyond the arc, the nearer end.
  const Eigen::Vector2d from_start = start - centre, to_point = point - centre;
  double angle = std::atan2(cross(from_start, to_point), from_start.dot(to_point));
  if (sweep < 0.0)
    angle = -angle;
  const double span = std::abs(sweep);
  if (angle >= 0.0 && angle <= span && to_point.norm() > 0.0)
    return centre + radius * to_point.normalized();
  return (point - start).norm() <= (point - end).norm() ? start : end;
}

const NoseSegment* TableOutline::cushion(const std::string& id) const
{
  const auto found = std::find_if(cushions.begin(), cushions.end(), [&](const auto& c) { return c.id == id; });
  return found == cushions.end() ? nullptr : &*found;
}

const PocketOpening* TableOutline::pocket(const std::string& id) const
{
  const auto found = std::find_if(pockets.begin(), pockets.end(), [&](const auto& p) { return p.id == id; });
  return found == pockets.end() ? nullptr : &*found;
}

std::vector<NoseSegment> TableOutline::jawsOf(const std::string& pocket) const
{
  // Jaw segments are named "pocket.<pocket>.jaw.<side>.facing|point" (docs/tables.md, Ids).
  const std::string prefix = "pocket." + pocket + ".jaw.";
  std::vector<NoseSegment> jaws;
  std::copy_if(cushions.begin(), cushions.end(), std::back_inserter(jaws),
               [&](const NoseSegment& segment) { return segment.id.rfind(prefix, 0) == 0; });
  return jaws;
}

Expected<TableOutline> tableOutline(const Table& table, const std::string& field)
{
  // The table's checks include the cuts' fit (validatePocketFit): what passes them lays out.
  if (Status status = validate(table, field); !status)
    return status.error();
  const double x = 0.5 * table.length, y = 0.5 * table.width;
  if (table.pocket_layout == PocketLayout::None)
    return caromGeometry(x, y);

  const std::vector<PocketPlace> places = sixPocketPlaces(x, y);
  std::vector<PocketLayoutParts> parts;
  parts.reserve(places.size());
  for (const PocketPlace& place : places)
    parts.push_back(layPocket(place, place.corner ? table.corner_pockets : table.side_pockets));
  TableOutline outline;
  for (std::size_t k = 0; k < places.size(); ++k)
  {
    const PocketLayoutParts& here = parts[k];
    const PocketLayoutParts& next = parts[(k + 1) % parts.size()];
    outline.pockets.push_back(here.opening);
    appendJaw(outline.cushions, here.out, false);
    outline.cushions.push_back(line(places[k].rail_after, here.out.rail_end, next.in.rail_end));
    appendJaw(outline.cushions, next.in, true);
  }
  // The walk began at the bottom-left pocket's jaw out; its jaw in, laid last, closes the outline there.
  return outline;
}

}  // namespace billiard_shot_planner

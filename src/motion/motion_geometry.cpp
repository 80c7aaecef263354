#include "motion_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "billiard_shot_planner/core/plane_geometry.hpp"
#include "billiard_shot_planner/motion/table_outline.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// How far (m) pieces that join overlap in what they cover, so that round-off cannot leave a ball's nearest nose point
/// between them.
constexpr double JOIN_OVERLAP = 1e-9;

/// Distance (m) within which two segments' ends are one point of the outline.
constexpr double SAME_POINT = 1e-9;

NosePiece linePiece(const NoseSegment& segment, int cushion)
{
  NosePiece piece;
  piece.cushion = cushion;
  piece.tangent = (segment.end - segment.start).normalized();
  // The cloth lies on the left of the outline's direction: out of the table is to its right.
  piece.line.outward = Eigen::Vector2d(piece.tangent.y(), -piece.tangent.x());
  piece.line.edge = piece.line.outward.dot(segment.start);
  piece.from = piece.tangent.dot(segment.start);
  piece.to = piece.tangent.dot(segment.end);
  return piece;
}

NosePiece arcPiece(const NoseSegment& segment, int cushion)
{
  NosePiece piece;
  piece.shape = NosePiece::Shape::Arc;
  piece.cushion = cushion;
  piece.centre = segment.centre;
  piece.radius = segment.radius;
  piece.arc_start = (segment.start - segment.centre).normalized();
  piece.sweep = segment.sweep;
  return piece;
}

NosePiece pointPiece(const Eigen::Vector2d& place, int cushion)
{
  NosePiece piece;
  piece.shape = NosePiece::Shape::Point;
  piece.cushion = cushion;
  piece.centre = place;
  return piece;
}

Eigen::Vector2d directionOf(const NoseSegment& segment)
{
  return (segment.end - segment.start).normalized();
}

/// The points a straight segment needs besides its line: its free ends (a facing's end in the pocket) and a sharp
/// corner where it turns right into the next straight segment (an unrounded jaw, jutting into the table). Corners that
/// turn left (the table's own corners) lie behind both lines, and rounded ones are arcs.
void addCornerPoints(const std::vector<NoseSegment>& segments, std::size_t i, std::vector<NosePiece>& pieces)
{
  const NoseSegment& here = segments[i];
  const NoseSegment* next = nullptr;
  bool preceded = false;
  for (const NoseSegment& other : segments)
  {
    if ((other.start - here.end).norm() <= SAME_POINT)
      next = &other;
    if ((other.end - here.start).norm() <= SAME_POINT)
      preceded = true;
  }
  const int cushion = static_cast<int>(i);
  if (!preceded)
    pieces.push_back(pointPiece(here.start, cushion));
  const bool sharp_turn_right =
      next && next->shape == NoseSegment::Shape::Line && cross(directionOf(here), directionOf(*next)) < 0.0;
  if (!next || sharp_turn_right)
    pieces.push_back(pointPiece(here.end, cushion));
}

MotionGeometry circlesGeometry(const Table& table)
{
  MotionGeometry geometry;
  const std::array<Nose, 4> rails = railNoses(table);
  geometry.cushion_ids.assign(RAIL_IDS.begin(), RAIL_IDS.end());
  for (int rail = 0; rail < 4; ++rail)
  {
    NosePiece piece;
    piece.cushion = rail;
    piece.line = rails[static_cast<std::size_t>(rail)];
    piece.tangent = Eigen::Vector2d(-piece.line.outward.y(), piece.line.outward.x());
    geometry.noses.push_back(piece);
  }
  for (std::size_t i = 0; i < table.pockets.size(); ++i)
    geometry.drops.push_back(
        {table.pockets[i].centre, table.pockets[i].radius, pocketId(table.pockets, i), "capture region"});
  return geometry;
}

/// The far end of a facing: the end farther from its pocket's mouth.
Eigen::Vector2d farEnd(const NoseSegment& facing, const PocketOpening& pocket)
{
  const Eigen::Vector2d middle = pocket.mouthMiddle();
  return (facing.start - middle).norm() > (facing.end - middle).norm() ? facing.start : facing.end;
}

/// The throat between the pocket's jaw points and its facings' far ends, counterclockwise.
Throat throatOf(const TableOutline& outline, const PocketOpening& pocket)
{
  std::vector<Eigen::Vector2d> far_ends;
  for (const NoseSegment& segment : outline.jawsOf(pocket.id))
    if (segment.shape == NoseSegment::Shape::Line)
      far_ends.push_back(farEnd(segment, pocket));
  if (far_ends.size() != 2)
    return Throat{{pocket.jaw_out, pocket.drop_centre, pocket.drop_centre, pocket.jaw_in}};
  // Each facing's far end lies on its own jaw's side of the axis.
  if ((far_ends[0] - pocket.jaw_out).norm() > (far_ends[1] - pocket.jaw_out).norm())
    std::swap(far_ends[0], far_ends[1]);
  Throat throat{{pocket.jaw_out, far_ends[0], far_ends[1], pocket.jaw_in}};
  if (cross(throat.corners[1] - throat.corners[0], throat.corners[2] - throat.corners[1]) < 0.0)
    std::reverse(throat.corners.begin(), throat.corners.end());
  return throat;
}

MotionGeometry jawsGeometry(const TableOutline& outline)
{
  MotionGeometry geometry;
  for (std::size_t i = 0; i < outline.cushions.size(); ++i)
  {
    const NoseSegment& segment = outline.cushions[i];
    const int cushion = static_cast<int>(i);
    geometry.cushion_ids.push_back(segment.id);
    if (segment.shape == NoseSegment::Shape::Arc)
    {
      geometry.noses.push_back(arcPiece(segment, cushion));
      continue;
    }
    geometry.noses.push_back(linePiece(segment, cushion));
    addCornerPoints(outline.cushions, i, geometry.noses);
  }
  for (const PocketOpening& pocket : outline.pockets)
  {
    geometry.drops.push_back({pocket.drop_centre, pocket.drop_radius, pocket.id, "drop region"});
    geometry.throats.push_back(throatOf(outline, pocket));
  }
  return geometry;
}
}  // namespace

std::array<Nose, 4> railNoses(const Table& table)
{
  const double x = 0.5 * table.length, y = 0.5 * table.width;
  return {{{{-1.0, 0.0}, x}, {{1.0, 0.0}, x}, {{0.0, -1.0}, y}, {{0.0, 1.0}, y}}};
}

bool NosePiece::covers(const Eigen::Vector2d& point) const
{
  switch (shape)
  {
    case Shape::Line:
    {
      const double along = tangent.dot(point);
      return along >= from - JOIN_OVERLAP && along <= to + JOIN_OVERLAP;
    }
    case Shape::Arc:
    {
      const Eigen::Vector2d to_point = point - centre;
      double angle = std::atan2(cross(arc_start, to_point), arc_start.dot(to_point));
      if (sweep < 0.0)
        angle = -angle;
      const double slack = JOIN_OVERLAP / radius;
      return angle >= -slack && angle <= std::abs(sweep) + slack;
    }
    case Shape::Point:
      return true;
  }
  return false;
}

double NosePiece::across(const Eigen::Vector2d& point) const
{
  if (shape == Shape::Line)
    return line.edge - (line.outward.x() * point.x() + line.outward.y() * point.y());
  return (point - centre).norm() - radius;
}

bool NosePiece::overlaps(const Eigen::Vector2d& point, double reach, double tolerance) const
{
  if (shape == Shape::Line)
    return line.outward.x() * point.x() + line.outward.y() * point.y() > line.edge - reach + tolerance;
  return (point - centre).norm() - radius < reach - tolerance;
}

Eigen::Vector2d NosePiece::outwardAt(const Eigen::Vector2d& point) const
{
  if (shape == Shape::Line)
    return line.outward;
  return (centre - point).normalized();
}

bool Throat::contains(const Eigen::Vector2d& point) const
{
  for (std::size_t k = 0; k < corners.size(); ++k)
    if (cross(corners[(k + 1) % corners.size()] - corners[k], point - corners[k]) < 0.0)
      return false;
  return true;
}

bool MotionGeometry::offTable(const Eigen::Vector3d& point) const
{
  if (std::abs(point.x()) <= half_length && std::abs(point.y()) <= half_width)
    return false;
  return std::none_of(throats.begin(), throats.end(),
                      [&](const Throat& throat) { return throat.contains(point.head<2>()); });
}

Expected<MotionGeometry> motionGeometry(const Table& table)
{
  MotionGeometry geometry;
  if (table.pocket_model == PocketModel::Circles)
  {
    geometry = circlesGeometry(table);
  }
  else
  {
    auto outline = tableOutline(table);
    if (!outline)
      return outline.error();
    geometry = jawsGeometry(outline.value());
  }
  geometry.half_length = 0.5 * table.length;
  geometry.half_width = 0.5 * table.width;
  return geometry;
}

}  // namespace detail
}  // namespace billiard_shot_planner

#include "table_message.hpp"

#include "geometry_conversions.hpp"

namespace billiard_shot_planner
{
namespace
{
geometry_msgs::Point pointAt(const Eigen::Vector2d& p, double z)
{
  return toPoint(Eigen::Vector3d(p.x(), p.y(), z));
}

CushionSegment segmentMessage(const NoseSegment& segment, double height)
{
  CushionSegment message;
  message.id = segment.id;
  message.shape = segment.shape == NoseSegment::Shape::Arc ? CushionSegment::ARC : CushionSegment::LINE;
  message.start = pointAt(segment.start, height);
  message.end = pointAt(segment.end, height);
  message.centre = pointAt(segment.centre, height);
  message.radius = segment.radius;
  message.sweep = segment.sweep;
  return message;
}

TablePocket pocketMessage(const PocketOpening& pocket)
{
  TablePocket message;
  message.id = pocket.id;
  message.jaw_in = pointAt(pocket.jaw_in, 0.0);
  message.jaw_out = pointAt(pocket.jaw_out, 0.0);
  message.axis = toVector3(Eigen::Vector3d(pocket.axis.x(), pocket.axis.y(), 0.0));
  message.drop_centre = pointAt(pocket.drop_centre, 0.0);
  message.drop_radius = pocket.drop_radius;
  return message;
}
}  // namespace

TableGeometry tableMessage(const TableOutline& outline, const Table& table, const std::string& frame,
                           const ros::Time& stamp)
{
  TableGeometry message;
  message.header.frame_id = frame;
  message.header.stamp = stamp;
  message.length = table.length;
  message.width = table.width;
  message.cushion_height = table.cushion_height;
  for (const NoseSegment& segment : outline.cushions)
    message.cushions.push_back(segmentMessage(segment, table.cushion_height));
  for (const PocketOpening& pocket : outline.pockets)
    message.pockets.push_back(pocketMessage(pocket));
  return message;
}

}  // namespace billiard_shot_planner

#pragma once

#include <billiard_shot_planner/TableGeometry.h>
#include <ros/time.h>

#include <string>

#include "billiard_shot_planner/motion/table_outline.hpp"

namespace billiard_shot_planner
{
/// The table's outline as a message in `frame` (the table frame), stamped `stamp`: the cushions' segments at the
/// noses' height, the pockets on the cloth. Pure conversion, no ROS master needed.
TableGeometry tableMessage(const TableOutline& outline, const Table& table, const std::string& frame,
                           const ros::Time& stamp);

}  // namespace billiard_shot_planner

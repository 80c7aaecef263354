#pragma once

// Eigen → geometry_msgs for the ROS glue. (tf2_eigen's toMsg is ambiguous for Eigen::Vector3d arguments: its
// 6-vector overload also matches through Eigen's templated constructors.)
#include <geometry_msgs/Point.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Core>

namespace billiard_shot_planner
{
inline geometry_msgs::Point toPoint(const Eigen::Vector3d& p)
{
  geometry_msgs::Point m;
  m.x = p.x();
  m.y = p.y();
  m.z = p.z();
  return m;
}

inline geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v)
{
  geometry_msgs::Vector3 m;
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
  return m;
}

}  // namespace billiard_shot_planner

#pragma once

#include <Eigen/Core>

namespace billiard_shot_planner
{
/// The z component of a × b for two vectors in the table plane: positive when b turns counterclockwise from a.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}
}  // namespace billiard_shot_planner

#pragma once

// The rails as a bank or a kick meets them: one mirror serves both, the target's route to a pocket off a rail and the
// cue ball's route to a ghost ball off a rail.
#include <Eigen/Core>
#include <array>
#include <string>

#include "billiard_shot_planner/motion/table.hpp"

namespace billiard_shot_planner
{
namespace planning
{
/// A rail and the line a ball's centre runs along when it touches the rail's nose on the cloth: the nose's line moved
/// onto the table by the cushion's reach. The rails run along the table's axes: `axis` is the coordinate across the
/// rail (0 for the rails at ±x, 1 at ±y) and `side` its sign at the rail.
struct RailLine
{
  std::string id;  ///< RAIL_IDS
  int axis = 0;
  double side = 1.0;
  double half = 0.0;  ///< m, from the table's centre to the nose, across the rail
  double line = 0.0;  ///< the coordinate of the centre's line across the rail: side · (half − reach)

  /// The mirror image of `point` in the centre's line: a straight path to it is a path off the rail.
  Eigen::Vector2d mirror(const Eigen::Vector2d& point) const
  {
    Eigen::Vector2d image = point;
    image(axis) = 2.0 * line - point(axis);
    return image;
  }
  /// Where along the straight path from `from` to `image` (0 at `from`, 1 at `image`) it crosses the centre's line.
  double crossing(const Eigen::Vector2d& from, const Eigen::Vector2d& image) const
  {
    return (line - from(axis)) / (image(axis) - from(axis));
  }
  /// Whether `point` lies on the rail's nose line or beyond it (a pocket on this rail).
  bool holds(const Eigen::Vector2d& point) const { return side * point(axis) >= half - 1e-9; }
};

/// The four rails of `table` in RAIL_IDS' order, for a ball of `radius`.
std::array<RailLine, 4> railLines(const Table& table, double radius);

}  // namespace planning
}  // namespace billiard_shot_planner

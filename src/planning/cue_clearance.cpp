// The cue as a cylinder behind its tip: it must touch no other ball and pass above the rails.
#include <algorithm>

#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace
{
using planning::ClearanceMargin;

bool clearsTheBalls(const Eigen::Vector3d& tip, const Eigen::Vector3d& back, const std::vector<TableBall>& others,
                    const RobotLimits& limits, double ball_radius, const ClearanceMargin& margin)
{
  for (const TableBall& ball : others)
  {
    const Eigen::Vector3d centre = ball.state.position;
    const double along = std::clamp((centre - tip).dot(back), 0.0, limits.cue_length);
    if ((tip + along * back - centre).norm() < ball_radius + limits.cue_radius + margin.at(along))
      return false;
  }
  return true;
}

/// Where the cue's axis crosses a rail line (the edge of the playing surface) within its length, its underside is
/// above the rails' top.
bool passesAboveTheRails(const Eigen::Vector3d& tip, const Eigen::Vector3d& back, const Table& table,
                         const RobotLimits& limits, const ClearanceMargin& margin)
{
  for (int axis = 0; axis < 2; ++axis)
  {
    if (back(axis) == 0.0)
      continue;
    const double half = 0.5 * (axis == 0 ? table.length : table.width);
    for (double side : {-1.0, 1.0})
    {
      const double along = (side * half - tip(axis)) / back(axis);
      if (along > 0.0 && along <= limits.cue_length &&
          tip.z() + along * back.z() - limits.cue_radius - margin.at(along) < limits.rail_height)
        return false;
    }
  }
  return true;
}
}  // namespace

bool cueClears(const CuePlacement& cue, const std::vector<TableBall>& others, const Table& table,
               const RobotLimits& limits, double ball_radius, double margin, double margin_per_metre)
{
  const Eigen::Vector3d back = -cue.direction.normalized();  // from the tip towards the butt
  const ClearanceMargin room{margin, margin_per_metre};
  return clearsTheBalls(cue.tip, back, others, limits, ball_radius, room) &&
         passesAboveTheRails(cue.tip, back, table, limits, room);
}

namespace planning
{
bool cueClears(const CuePlacement& cue, const PlanContext& context, const ClearanceMargin& margin)
{
  return billiard_shot_planner::cueClears(cue, context.others, context.configuration.table, context.request.limits,
                                          context.radius(), margin.offset, margin.per_metre);
}

}  // namespace planning
}  // namespace billiard_shot_planner

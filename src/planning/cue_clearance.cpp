// The cue as a cylinder behind its tip: it must touch no other ball and pass above the rails.
#include <algorithm>

#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace planning
{
namespace
{
bool clearsTheBalls(const Eigen::Vector3d& tip, const Eigen::Vector3d& back, const PlanContext& context)
{
  const RobotLimits& limits = context.request.limits;
  for (const TableBall& ball : context.others)
  {
    const Eigen::Vector3d centre = ball.state.position;
    const double along = std::clamp((centre - tip).dot(back), 0.0, limits.cue_length);
    if ((tip + along * back - centre).norm() < context.radius() + limits.cue_radius)
      return false;
  }
  return true;
}

/// Where the cue's axis crosses a rail line (the edge of the playing surface) within its length, its underside is
/// above the rails' top.
bool passesAboveTheRails(const Eigen::Vector3d& tip, const Eigen::Vector3d& back, const PlanContext& context)
{
  const RobotLimits& limits = context.request.limits;
  const Table& table = context.configuration.table;
  for (int axis = 0; axis < 2; ++axis)
  {
    if (back(axis) == 0.0)
      continue;
    const double half = 0.5 * (axis == 0 ? table.length : table.width);
    for (double side : {-1.0, 1.0})
    {
      const double along = (side * half - tip(axis)) / back(axis);
      if (along > 0.0 && along <= limits.cue_length &&
          tip.z() + along * back.z() - limits.cue_radius < limits.rail_height)
        return false;
    }
  }
  return true;
}
}  // namespace

bool cueClears(const CuePlacement& cue, const PlanContext& context)
{
  const Eigen::Vector3d back = -cue.direction.normalized();  // from the tip towards the butt
  return clearsTheBalls(cue.tip, back, context) && passesAboveTheRails(cue.tip, back, context);
}

}  // namespace planning
}  // namespace billiard_shot_planner

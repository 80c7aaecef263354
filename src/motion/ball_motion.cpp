#include "billiard_shot_planner/motion/ball_motion.hpp"

#include <utility>

#include "ball_mover.hpp"
#include "billiard_shot_planner/core/validation.hpp"
#include "table_event_loop.hpp"

namespace billiard_shot_planner
{
Status validate(const MotionParameters& p)
{
  if (Status status = firstError(
          {requirePositive(p.gravity, "gravity"), requirePositive(p.sliding_friction, "sliding_friction"),
           requirePositive(p.rolling_friction, "rolling_friction"),
           requirePositive(p.spinning_friction, "spinning_friction"),
           requireNonNegative(p.min_bounce_speed, "min_bounce_speed"),
           requireWithin(p.max_time, 1e-3, MAX_TRAJECTORY_TIME, "max_time", "seconds; a ball stops within a minute")});
      !status)
    return status;
  if (p.max_events < 2)
    return invalidArgument("max_events", "must be at least 2");
  return {};
}

Expected<BallTrajectory> predictTrajectory(const BallState& start, const BallProperties& ball, const Table& table,
                                           const MotionParameters& parameters)
{
  if (Status status = detail::checkMotionSetting(ball, table, parameters); !status)
    return status.error();
  auto geometry = detail::motionGeometry(table);
  if (!geometry)
    return geometry.error();
  if (Status status = detail::checkStart(start, ball, table, geometry.value()); !status)
    return status.error();
  // The lone ball is the one-ball case of the table's simulation.
  auto simulated = detail::runTableSimulation({TableBall{"ball", start}}, ball, table, parameters, {});
  if (!simulated)
    return simulated.error();
  return std::move(simulated.value().balls.front());
}

}  // namespace billiard_shot_planner

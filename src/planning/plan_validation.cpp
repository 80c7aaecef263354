// Checks of a plan request: every field, named as the CLI and the ROS interface name it.
#include <algorithm>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "plan_context.hpp"

namespace billiard_shot_planner
{
namespace
{
constexpr double MAX_BUDGET = 60.0;  ///< s, as the engine's own wall-clock bound
constexpr int MAX_ROLLOUTS = 100000;
constexpr int MAX_THREADS = 256;

Status checkRange(double low, double high, const std::string& field)
{
  if (Status status = firstError({requireFinite(low, field), requireFinite(high, field)}); !status)
    return status;
  if (low > high)
    return invalidArgument(field, "is an empty range: " + formatNumber(low) + " > " + formatNumber(high));
  return {};
}

Status checkLimitsOf(const RobotLimits& l)
{
  return firstError(
      {checkRange(l.min_theta, l.max_theta, "limits.theta"),
       requireWithin(l.min_theta, 0.0, M_PI / 2, "limits.theta", "an elevation from level to vertical"),
       requireWithin(l.max_theta, 0.0, M_PI / 2, "limits.theta", "an elevation from level to vertical"),
       checkRange(l.min_speed, l.max_speed, "limits.speed"), requirePositive(l.min_speed, "limits.speed"),
       requirePlausibleSpeed(l.max_speed, "limits.speed"),
       requireWithin(l.max_offset, 0.0, 0.95, "limits.max_offset", "ball radii: the hit point stays on the ball"),
       requireNonNegative(l.cue_length, "limits.cue_length"), requireNonNegative(l.cue_radius, "limits.cue_radius"),
       requireNonNegative(l.rail_height, "limits.rail_height")});
}

Status checkNoiseOf(const ExecutionNoise& n)
{
  return firstError({requireNonNegative(n.phi, "noise.phi"), requireNonNegative(n.theta, "noise.theta"),
                     requireNonNegative(n.speed, "noise.speed"), requireNonNegative(n.a, "noise.a"),
                     requireNonNegative(n.b, "noise.b")});
}

Status checkBalls(const PlanRequest& r, const ShotConfiguration& c)
{
  // The table's own checks (ids, overlaps, off the cloth, in a pocket, into a cushion), with every ball at rest.
  std::vector<TableBall> at_rest = r.balls;
  for (TableBall& ball : at_rest)
  {
    if (Status status = firstError(
            {requireFinite(ball.state.velocity, "balls"), requireFinite(ball.state.angular_velocity, "balls")});
        !status)
      return status;
    if (ball.state.velocity.norm() > 0.0 || ball.state.angular_velocity.norm() > 0.0)
      return Error{ErrorKind::BallsMoving, "balls",
                   "the balls of a plan are at rest (ball \"" + ball.id + "\" moves): wait until they stop"};
  }
  if (auto run = simulateTable(at_rest, {c.ball_mass, c.ball_radius}, c.table, c.motion, c.ball_contact); !run)
    return run.error();
  const auto has = [&](const std::string& id)
  { return std::any_of(r.balls.begin(), r.balls.end(), [&](const TableBall& b) { return b.id == id; }); };
  if (!has(r.cue_ball))
    return invalidArgument("cue_ball", "no ball has the id \"" + r.cue_ball + "\"");
  if (r.cue_ball != CUE_BALL_ID && has(CUE_BALL_ID))
    return invalidArgument("balls", std::string("only the cue ball may be called \"") + CUE_BALL_ID + "\"");
  if (r.balls.size() < 2)
    return invalidArgument("balls", "there is no object ball to pot");
  if (!r.target.empty() && (!has(r.target) || r.target == r.cue_ball))
    return invalidArgument("target", "no object ball has the id \"" + r.target + "\"");
  return {};
}

/// "bottom_left, bottom_right, …": the ids a request may name.
std::string pocketIds(const std::vector<planning::PocketTarget>& pockets)
{
  std::string ids;
  for (const planning::PocketTarget& pocket : pockets)
    ids += (ids.empty() ? "" : ", ") + pocket.id;
  return ids;
}

Status checkSearch(const PlanRequest& r, const ShotConfiguration& c)
{
  auto pockets = planning::pocketTargets(c.table, c.ball_radius);
  if (!pockets)
    return pockets.error();
  if (!r.pocket.empty() && planning::indexOf(pockets.value(), r.pocket) < 0)
    return invalidArgument("pocket", "names no pocket of the table (" + pocketIds(pockets.value()) + "), got \"" +
                                         r.pocket + "\"; empty for any");
  if (r.cue_region)
    if (Status status = firstError({requireFinite(r.cue_region->centre, "cue_region.centre"),
                                    requirePositive(r.cue_region->radius, "cue_region.radius")});
        !status)
      return status;
  return firstError({requireWithin(r.budget, 1e-3, MAX_BUDGET, "budget", "seconds: at least a millisecond"),
                     requireWithin(r.rollouts, 1, MAX_ROLLOUTS, "rollouts", "rollouts per shot"),
                     requireWithin(r.threads, 0, MAX_THREADS, "threads", "0 for one per hardware thread")});
}
}  // namespace

Status validate(const RobotLimits& limits)
{
  return checkLimitsOf(limits);
}

Status validate(const ExecutionNoise& noise)
{
  return checkNoiseOf(noise);
}

Status validate(const PlanRequest& request, const ShotConfiguration& configuration)
{
  return firstError({validate(configuration), validate(request.limits), validate(request.noise),
                     checkSearch(request, configuration), checkBalls(request, configuration)});
}

}  // namespace billiard_shot_planner

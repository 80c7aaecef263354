#include "planning_settings.hpp"

#include <algorithm>
#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
namespace
{
constexpr int MAX_ROLLOUTS = 100000;
constexpr int MAX_THREADS = 256;

/// The planner's field names ("limits.speed", "noise.phi") as the node's parameters.
Status asParameter(Status status)
{
  if (status)
    return status;
  Error error = status.error();
  std::string field = "planning/" + error.field;
  for (char& c : field)
    c = c == '.' ? '/' : c;
  if (field == "planning/limits/speed" || field == "planning/limits/theta")
    field = field == "planning/limits/speed" ? "planning/limits/min_speed" : "planning/limits/min_theta";
  error.field = field;
  return error;
}

Status check(const PlanningSettings& s)
{
  return firstError({asParameter(validate(s.limits)), asParameter(validate(s.noise)),
                     requireWithin(s.budget, 1e-3, 60.0, "planning/budget", "seconds"),
                     requireWithin(s.rest_speed, 0.0, 1.0, "planning/rest_speed", "m/s"),
                     requireWithin(s.rollouts, 1, MAX_ROLLOUTS, "planning/rollouts", "rollouts per shot"),
                     requireWithin(s.threads, 0, MAX_THREADS, "planning/threads", "0: one per hardware thread")});
}

/// An integer parameter set through an override's double: whole numbers only.
Status setInteger(int& target, double value, const std::string& name)
{
  if (!(std::isfinite(value) && value == std::floor(value) && std::abs(value) < 1e9))
    return invalidArgument(name, "must be a whole number, got " + formatNumber(value));
  target = static_cast<int>(value);
  return {};
}
}  // namespace

std::vector<PlanningParameter> planningParameters(PlanningSettings& s)
{
  return {{"planning/limits/min_theta", &s.limits.min_theta},
          {"planning/limits/max_theta", &s.limits.max_theta},
          {"planning/limits/min_speed", &s.limits.min_speed},
          {"planning/limits/max_speed", &s.limits.max_speed},
          {"planning/limits/max_offset", &s.limits.max_offset},
          {"planning/limits/cue_length", &s.limits.cue_length},
          {"planning/limits/cue_radius", &s.limits.cue_radius},
          {"planning/limits/rail_height", &s.limits.rail_height},
          {"planning/noise/phi", &s.noise.phi},
          {"planning/noise/theta", &s.noise.theta},
          {"planning/noise/speed", &s.noise.speed},
          {"planning/noise/a", &s.noise.a},
          {"planning/noise/b", &s.noise.b},
          {"planning/budget", &s.budget},
          {"planning/rest_speed", &s.rest_speed}};
}

Expected<PlanningSettings> readPlanningSettings(ParameterTree& parameters)
{
  PlanningSettings s;
  for (const PlanningParameter& parameter : planningParameters(s))
    if (Status status = parameters.read(parameter.name, *parameter.value); !status)
      return status.error();
  if (Status status = firstError(
          {parameters.read("planning/rollouts", s.rollouts), parameters.read("planning/threads", s.threads), check(s)});
      !status)
    return status.error();
  return s;
}

Status settleAtRest(TableBall& ball, double rest_speed, double ball_radius)
{
  const double speed = std::max(ball.state.velocity.norm(), ball.state.angular_velocity.norm() * ball_radius);
  if (speed > rest_speed)
    return Error{ErrorKind::BallsMoving, "table.balls",
                 "ball \"" + ball.id + "\" moves at " + formatNumber(speed) +
                     " m/s, faster than ~planning/rest_speed (" + formatNumber(rest_speed) +
                     " m/s): it must be at rest; wait until it stops"};
  ball.state.velocity.setZero();
  ball.state.angular_velocity.setZero();
  return {};
}

Expected<bool> applyPlanningOverride(PlanningSettings& settings, const std::string& name, double value)
{
  PlanningSettings changed = settings;
  bool known = false;
  for (const PlanningParameter& parameter : planningParameters(changed))
    if (name == parameter.name)
    {
      *parameter.value = value;
      known = true;
    }
  if (name == "planning/rollouts" || name == "planning/threads")
  {
    if (Status status = setInteger(name == "planning/rollouts" ? changed.rollouts : changed.threads, value, name);
        !status)
      return status.error();
    known = true;
  }
  if (!known)
    return false;
  if (Status status = check(changed); !status)
    return status.error();
  settings = changed;
  return true;
}

}  // namespace billiard_shot_planner

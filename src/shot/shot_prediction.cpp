#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "billiard_shot_planner/core/validation.hpp"

#include <algorithm>

namespace billiard_shot_planner
{
namespace
{
/// A part's error named as the configuration names the part ("max_time" of the motion is "motion.max_time").
Status inPart(Status status, const std::string& part)
{
  if (status)
    return status;
  Error error = status.error();
  error.field = part + "." + error.field;
  return error;
}
}  // namespace

Status validate(const ShotConfiguration& c)
{
  Status status =
      firstError({requirePositive(c.cue_mass, "cue_mass"), requirePositiveOrInfinite(c.cue_end_mass, "cue_end_mass"),
                  requirePositive(c.ball_mass, "ball_mass"), requirePositive(c.ball_radius, "ball_radius"),
                  validate(c.cue_contact, "cue_contact"), requireStiffnessRatio(c.stiffness_ratio, "stiffness_ratio"),
                  validate(c.table, "table"), inPart(validate(c.motion), "motion"), validate(c.solver, "solver")});
  if (!status)
    return status;
  return validateCushionHeight(c.table.cushion_height, c.ball_radius, "table.cushion_height");
}

std::vector<NamedParameter> numericParameters(ShotConfiguration& c)
{
  return {{"cue_mass", &c.cue_mass},
          {"cue_end_mass", &c.cue_end_mass},
          {"ball_mass", &c.ball_mass},
          {"ball_radius", &c.ball_radius},
          {"cue_contact.restitution", &c.cue_contact.restitution},
          {"cue_contact.friction", &c.cue_contact.friction},
          {"cue_contact.eta2", &c.cue_contact.eta2},
          {"stiffness_ratio", &c.stiffness_ratio},
          {"table.length", &c.table.length},
          {"table.width", &c.table.width},
          {"table.cushion_height", &c.table.cushion_height},
          {"table.cushion_stiffness_ratio", &c.table.cushion_stiffness_ratio},
          {"table.cloth.restitution", &c.table.cloth.restitution},
          {"table.cloth.friction", &c.table.cloth.friction},
          {"table.cloth.eta2", &c.table.cloth.eta2},
          {"table.cushion.restitution", &c.table.cushion.restitution},
          {"table.cushion.friction", &c.table.cushion.friction},
          {"table.cushion.eta2", &c.table.cushion.eta2},
          {"motion.gravity", &c.motion.gravity},
          {"motion.sliding_friction", &c.motion.sliding_friction},
          {"motion.rolling_friction", &c.motion.rolling_friction},
          {"motion.spinning_friction", &c.motion.spinning_friction},
          {"motion.min_bounce_speed", &c.motion.min_bounce_speed},
          {"motion.max_time", &c.motion.max_time},
          {"solver.relative_tolerance", &c.solver.relative_tolerance},
          {"solver.absolute_tolerance", &c.solver.absolute_tolerance},
          {"solver.max_seconds", &c.solver.max_seconds}};
}

Status applyOverride(ShotConfiguration& configuration, const std::string& name, double value)
{
  // Tried on a copy: a rejected value leaves the configuration as it was.
  ShotConfiguration changed = configuration;
  for (const NamedParameter& parameter : numericParameters(changed))
    if (name == parameter.name)
    {
      *parameter.value = value;
      if (Status status = validate(changed); !status)
        return status;
      configuration = changed;
      return {};
    }
  return invalidArgument(name, "is not a physical parameter that can be overridden");
}

Expected<ShotOutcome> predictShot(const CuePlacement& cue, const ShotConfiguration& c)
{
  if (Status status = firstError(
          {requireFinite(cue.tip, "cue_pose.position"), requireDirection(cue.direction, "cue_pose.orientation"),
           requirePositive(cue.speed, "cue_speed"), requireFinite(cue.ball, "ball_position"), validate(c)});
      !status)
    return status.error();
  const Eigen::Vector3d centre(cue.ball.x(), cue.ball.y(), c.ball_radius);
  auto normal = hitNormal(cue.tip, cue.direction, centre, c.ball_radius);
  if (!normal)
    return normal.error();
  CueStrike strike;
  strike.cue_mass = c.cue_mass;
  strike.cue_end_mass = c.cue_end_mass;
  strike.cue_direction = cue.direction;
  strike.cue_speed = cue.speed;
  strike.ball_mass = c.ball_mass;
  strike.ball_radius = c.ball_radius;
  strike.hit_normal = normal.value();
  strike.cue_contact = c.cue_contact;
  strike.table_contact = c.table.cloth;
  strike.stiffness_ratio = c.stiffness_ratio;
  auto struck = solve(strike, c.solver);
  if (!struck)
    return struck.error();
  BallState start;
  start.position = centre;
  start.velocity = struck.value().velocity;
  start.angular_velocity = struck.value().angular_velocity;
  MotionParameters motion = c.motion;
  motion.impact = c.solver;
  auto trajectory = predictTrajectory(start, Ball{c.ball_mass, c.ball_radius}, c.table, motion);
  if (!trajectory)
  {
    Error error = trajectory.error();
    if (error.field == "position")
      error.field = "ball_position";  // the start of the trajectory is where the request put the ball
    return error;
  }
  return ShotOutcome{std::move(struck).value(), std::move(trajectory).value(), centre + c.ball_radius * normal.value()};
}

}  // namespace billiard_shot_planner

#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "billiard_shot_planner/core/error_fields.hpp"
#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/motion/table_strike.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

#include <algorithm>
#include <string>
#include <utility>

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
                  validate(c.table, "table"), inPart(validate(c.motion), "motion"), validate(c.solver, "solver"),
                  validate(c.ball_contact.ball_ball, "ball_ball"),
                  requireStiffnessRatio(c.ball_contact.stiffness_ratio, "ball_ball.cloth_stiffness_ratio")});
  if (!status)
    return status;
  return validateForBall(c.table, c.ball_radius);
}

CueStrike strikePhysics(const ShotConfiguration& c)
{
  CueStrike strike;
  strike.cue_mass = c.cue_mass;
  strike.cue_end_mass = c.cue_end_mass;
  strike.ball_mass = c.ball_mass;
  strike.ball_radius = c.ball_radius;
  strike.cue_contact = c.cue_contact;
  strike.table_contact = c.table.cloth;
  strike.stiffness_ratio = c.stiffness_ratio;
  return strike;
}

namespace
{
/// Every number of a configuration with its place in it.
class NumberCollector final : public ConfigurationVisitor
{
public:
  void number(const std::string& path, double& value) override { numbers.push_back({path, &value}); }
  void flag(const std::string& /*path*/, bool& /*value*/) override {}
  void choice(const std::string& /*path*/, std::string& /*value*/, const std::vector<std::string>& /*options*/) override
  {
  }
  void pockets(const std::string& /*path*/, std::vector<Pocket>& /*pockets*/, const Table& /*table*/) override {}

  std::vector<NamedParameter> numbers;
};
}  // namespace

std::vector<NamedParameter> numericParameters(ShotConfiguration& c)
{
  NumberCollector collector;
  (void)visitConfiguration(c, collector);  // it changes no choice: the walk cannot fail
  return collector.numbers;
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

namespace
{
/// A table error in the caller's terms: the cue ball (the table's balls[0]) is "cue.ball", its only input being its
/// place; the others are "others[k]", as the caller listed them.
Error inCallTerms(Error error)
{
  const auto ball = elementOf(error.field, "balls");
  if (ball && ball->index == 0)
    error.field = ball->rest == ".position" ? "cue.ball" : "cue.ball" + ball->rest;
  else if (ball)
    error.field = "others[" + std::to_string(ball->index - 1) + "]" + ball->rest;
  return error;
}

/// The cue ball (at `cue_ball`, at rest before the strike) and the others, as the table's balls: the cue ball first.
std::vector<TableBall> tableBalls(const Eigen::Vector2d& cue_ball, double radius, const std::vector<TableBall>& others)
{
  std::vector<TableBall> balls{{CUE_BALL_ID, {}}};
  balls.front().state.position = Eigen::Vector3d(cue_ball.x(), cue_ball.y(), radius);
  balls.insert(balls.end(), others.begin(), others.end());
  return balls;
}

Expected<TableTrajectory> moveBalls(const std::vector<TableBall>& balls, const ShotConfiguration& c,
                                    const MotionParameters& motion)
{
  const BallProperties ball{c.ball_mass, c.ball_radius};
  if (balls.size() == 1)
  {
    // The lone ball: its own checks name its fields as a lone ball's.
    auto trajectory = predictTrajectory(balls.front().state, ball, c.table, motion);
    if (!trajectory)
      return trajectory.error();
    TableTrajectory table;
    table.ids = {CUE_BALL_ID};
    table.balls.push_back(std::move(trajectory).value());
    return table;
  }
  auto table = simulateTable(balls, ball, c.table, motion, c.ball_contact);
  if (!table)
    return inCallTerms(table.error());
  return table;
}
}  // namespace

Expected<CueStrikeResult> strikeBall(const CuePlacement& cue, const ShotConfiguration& c,
                                     const std::vector<TableBall>& others)
{
  if (Status status =
          firstError({requireFinite(cue.tip, "cue.tip"), requireDirection(cue.direction, "cue.direction"),
                      requirePositive(cue.speed, "cue.speed"), requireFinite(cue.ball, "cue.ball"), validate(c)});
      !status)
    return status.error();
  const Eigen::Vector3d centre(cue.ball.x(), cue.ball.y(), c.ball_radius);
  auto normal = hitNormal(cue.tip, cue.direction, centre, c.ball_radius);
  if (!normal)
    return normal.error();
  CueStrike strike = strikePhysics(c);
  strike.cue_direction = cue.direction;
  strike.cue_speed = cue.speed;
  strike.hit_normal = normal.value();
  auto struck =
      strikeOnTable(strike, tableBalls(cue.ball, c.ball_radius, others), 0, c.table, c.ball_contact, c.solver);
  if (!struck)
    return inCallTerms(struck.error());
  return struck;
}

Expected<ShotOutcome> predictShot(const CuePlacement& cue, const ShotConfiguration& c,
                                  const std::vector<TableBall>& others)
{
  auto struck = strikeBall(cue, c, others);
  if (!struck)
    return struck.error();
  return predictShotAfter(cue, std::move(struck).value(), c, others);
}

Expected<ShotOutcome> predictShotAfter(const CuePlacement& cue, CueStrikeResult struck, const ShotConfiguration& c,
                                       const std::vector<TableBall>& others)
{
  for (const StruckBall& other : struck.other_balls)
    if (other.ball == 0 || other.ball > others.size())
      return invalidArgument("strike.other_balls",
                             "names a ball the table does not have: not the strike of these balls");
  for (const TouchingBalls& pair : struck.touching_balls)
    if (pair.first > others.size() || pair.second > others.size() || pair.first == pair.second)
      return invalidArgument("strike.touching_balls",
                             "names a ball the table does not have: not the strike of these balls");
  const Eigen::Vector3d centre(cue.ball.x(), cue.ball.y(), c.ball_radius);
  MotionParameters motion = c.motion;
  motion.impact = c.solver;
  auto table = moveBalls(ballsAfterStrike(tableBalls(cue.ball, c.ball_radius, others), 0, struck), c, motion);
  if (!table)
  {
    Error error = table.error();
    if (error.field == "position")
      error.field = "cue.ball";  // the start of the trajectory is where the caller put the ball
    return error;
  }
  recordStrike(table.value(), 0, struck);
  BallTrajectory cue_ball = table.value().balls.front();
  const Eigen::Vector3d hit_point = centre + c.ball_radius * struck.hit_normal;
  return ShotOutcome{std::move(struck), std::move(cue_ball), hit_point, std::move(table).value()};
}

}  // namespace billiard_shot_planner

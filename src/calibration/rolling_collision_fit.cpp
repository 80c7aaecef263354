#include "billiard_shot_planner/calibration/rolling_collision_fit.hpp"

#include <cmath>

#include "named_values.hpp"

#include "billiard_shot_planner/impact/laws/normal_law.hpp"

namespace billiard_shot_planner
{
namespace
{
/// A cloth without cushions or pockets within reach: the balls roll out freely.
constexpr double OPEN_CLOTH = 100.0;
/// How far the cue ball starts before the meeting, m: its deceleration over it changes its speed by < 1e-4.
constexpr double RUN_UP = 0.001;

template <class Visitor>
void visitCollisionValues(RollingCollisionTable& table, Visitor&& visit)
{
  visit("ball_ball.restitution", table.contact.ball_ball.restitution);
  visit("ball_ball.friction", table.contact.ball_ball.friction);
  visit("ball_ball.eta2", table.contact.ball_ball.eta2);
  visit("ball_ball.cloth_stiffness_ratio", table.contact.stiffness_ratio);
  visitLawParameters(table.contact.ball_ball.normal_law,
                     [&](const char* name, double& value) { visit(std::string("ball_ball.law.") + name, value); });
}

/// The ball's speed at its first change from sliding to rolling after its first meeting with the other ball.
double rollingSpeedAfterMeeting(const BallTrajectory& path)
{
  bool met = false;
  for (const MotionEvent& event : path.events)
  {
    met = met || event.type == MotionEventType::BallCollision;
    if (met && event.type == MotionEventType::SlideToRoll)
      return event.state.velocity.head<2>().norm();
  }
  return NAN;
}
}  // namespace

std::vector<std::string> rollingCollisionParameters(const RollingCollisionTable& table)
{
  return namedValues(table, [](RollingCollisionTable& model, auto&& visit) { visitCollisionValues(model, visit); });
}

Status applyRollingCollisionValues(const std::vector<std::string>& names, const std::vector<double>& values,
                                   RollingCollisionTable& table)
{
  return applyNamedValues(
      names, values, table, [](RollingCollisionTable& model, auto&& visit) { visitCollisionValues(model, visit); },
      "is not a parameter of a ball-ball collision (the ball_ball contact's "
      "constants, its law's and ball_ball.cloth_stiffness_ratio)");
}

Expected<std::pair<double, double>> predictRollingCollision(const RollingCollisionTable& table, double speed_in,
                                                            double cut)
{
  if (!(speed_in > 0.0) || !std::isfinite(speed_in))
    return invalidArgument("speed_in", "must be finite and > 0");
  if (!(std::abs(cut) < 0.5 * M_PI))
    return invalidArgument("cut", "must be within (-90, 90) degrees");
  const double r = table.ball.radius;
  Table cloth;
  cloth.length = OPEN_CLOTH;
  cloth.width = OPEN_CLOTH;
  cloth.pockets.clear();
  cloth.cloth = table.cloth;
  std::vector<TableBall> balls(2);
  balls[0].id = "cue";
  balls[0].state.position = Eigen::Vector3d(-RUN_UP, 0.0, r);
  balls[0].state.velocity = Eigen::Vector3d(speed_in, 0.0, 0.0);
  balls[0].state.angular_velocity = Eigen::Vector3d(0.0, speed_in / r, 0.0);  // rolling: v + ω × (−R ẑ) = 0
  balls[1].id = "object";
  balls[1].state.position = Eigen::Vector3d(2.0 * r * std::cos(cut), 2.0 * r * std::sin(cut), r);
  auto paths = simulateTable(balls, table.ball, cloth, table.motion, table.contact);
  if (!paths)
    return paths.error();
  const double cue = rollingSpeedAfterMeeting(paths.value().balls[0]);
  const double object = rollingSpeedAfterMeeting(paths.value().balls[1]);
  if (!std::isfinite(cue) || !std::isfinite(object))
    return Error{ErrorKind::NumericalFailure, "", "a ball did not roll again after the meeting"};
  return std::pair{cue, object};
}

Expected<FitResult> fitRollingCollisions(const RollingCollisionTable& table,
                                         const std::vector<FitParameter>& parameters,
                                         const std::vector<RollingCollision>& collisions, double speed_sigma,
                                         const FitOptions& options)
{
  if (!(speed_sigma > 0.0) || !std::isfinite(speed_sigma))
    return invalidArgument("speed_sigma", "must be finite and > 0");
  for (std::size_t i = 0; i < collisions.size(); ++i)
  {
    const RollingCollision& c = collisions[i];
    if (!(c.speed_in > 0.0) || !std::isfinite(c.speed_in))
      return invalidArgument(indexedField("collisions", i) + ".speed_in", "must be finite and > 0");
    if (!(std::abs(c.cut) < 0.5 * M_PI))
      return invalidArgument(indexedField("collisions", i) + ".cut", "must be within (-90, 90) degrees");
    if (!(c.cue_speed_out >= 0.0 && c.object_speed_out >= 0.0) || !std::isfinite(c.cue_speed_out + c.object_speed_out))
      return invalidArgument(indexedField("collisions", i) + ".speed_out", "must be finite and >= 0");
  }
  const std::vector<std::string> names = parameterNames(parameters);
  const std::vector<double> starts = parameterStarts(parameters);
  RollingCollisionTable start = table;
  if (Status applied = applyRollingCollisionValues(names, starts, start); !applied)
    return applied.error();
  if (auto checked = predictRollingCollision(start, 1.0, 0.3);
      !checked && checked.error().code == ErrorKind::InvalidArgument)
    return checked.error();
  std::vector<ResidualBlock> blocks;
  blocks.reserve(collisions.size());
  for (const RollingCollision& collision : collisions)
  {
    blocks.push_back({2, [=](const std::vector<double>& values, Eigen::VectorXd& residuals)
                      {
                        RollingCollisionTable trial = table;
                        if (!applyRollingCollisionValues(names, values, trial))
                          return false;
                        const auto out = predictRollingCollision(trial, collision.speed_in, collision.cut);
                        if (!out)
                          return false;
                        residuals.resize(2);
                        residuals(0) = (out.value().first - collision.cue_speed_out) / speed_sigma;
                        residuals(1) = (out.value().second - collision.object_speed_out) / speed_sigma;
                        return true;
                      }});
  }
  return fitLeastSquares(parameters, blocks, options);
}

}  // namespace billiard_shot_planner

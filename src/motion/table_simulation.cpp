#include "billiard_shot_planner/motion/table_simulation.hpp"

#include <algorithm>
#include <set>

#include "ball_contact_time.hpp"
#include "ball_mover.hpp"
#include "billiard_shot_planner/core/validation.hpp"
#include "table_event_loop.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
std::string ballField(std::size_t i)
{
  return "balls[" + std::to_string(i) + "]";
}

Status checkBalls(const std::vector<TableBall>& balls, const BallProperties& ball, const Table& table)
{
  if (balls.empty())
    return invalidArgument("balls", "at least one ball is needed");
  if (balls.size() > MAX_TABLE_BALLS)
    return invalidArgument(
        "balls", "at most " + std::to_string(MAX_TABLE_BALLS) + " balls, got " + std::to_string(balls.size()));
  const auto geometry = motionGeometry(table);
  if (!geometry)
    return geometry.error();
  std::set<std::string> ids;
  for (std::size_t i = 0; i < balls.size(); ++i)
  {
    if (balls[i].id.empty())
      return invalidArgument(ballField(i) + ".id", "must not be empty");
    if (!ids.insert(balls[i].id).second)
      return invalidArgument(ballField(i) + ".id", "\"" + balls[i].id + "\" is used by another ball");
    if (Status status = checkStart(balls[i].state, ball, table, geometry.value(), ballField(i) + "."); !status)
      return status;
  }
  for (std::size_t i = 0; i < balls.size(); ++i)
    for (std::size_t j = i + 1; j < balls.size(); ++j)
    {
      const double gap =
          (balls[i].state.position.head<2>() - balls[j].state.position.head<2>()).norm() - 2.0 * ball.radius;
      if (gap < -BALL_TOUCHING_TOLERANCE)
        return invalidArgument(ballField(j) + ".position", "overlaps ball \"" + balls[i].id + "\" by " +
                                                               formatNumber(-gap) + " m (touching balls are " +
                                                               "allowed within " +
                                                               formatNumber(BALL_TOUCHING_TOLERANCE) + " m)");
    }
  return {};
}

}  // namespace
}  // namespace detail

double TableTrajectory::duration() const
{
  double last = 0.0;
  for (const BallTrajectory& b : balls)
    last = std::max(last, b.events.empty() ? 0.0 : b.events.back().time);
  return last;
}

std::string firstContact(const TableTrajectory& trajectory, std::size_t ball)
{
  if (ball >= trajectory.balls.size())
    return "";
  for (const MotionEvent& e : trajectory.balls[ball].events)
    if (e.type == MotionEventType::BallCollision && e.ball >= 0 &&
        static_cast<std::size_t>(e.ball) < trajectory.ids.size())
      return trajectory.ids[static_cast<std::size_t>(e.ball)];
  return "";
}

Status validateTableBalls(const std::vector<TableBall>& balls, const BallProperties& ball, const Table& table)
{
  return detail::checkBalls(balls, ball, table);
}

Expected<TableTrajectory> simulateTable(const std::vector<TableBall>& balls, const BallProperties& ball,
                                        const Table& table, const MotionParameters& parameters,
                                        const BallContactSettings& contact)
{
  if (Status status = detail::checkMotionSetting(ball, table, parameters); !status)
    return status.error();
  if (Status status = detail::checkBalls(balls, ball, table); !status)
    return status.error();
  return detail::runTableSimulation(balls, ball, table, parameters, contact);
}

}  // namespace billiard_shot_planner

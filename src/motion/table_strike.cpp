#include "billiard_shot_planner/motion/table_strike.hpp"

#include <algorithm>

#include "table_collisions.hpp"

namespace billiard_shot_planner
{
namespace
{
double gapBetween(const TableBall& a, const TableBall& b, double radius)
{
  return (a.state.position.head<2>() - b.state.position.head<2>()).norm() - 2.0 * radius;
}

void addBall(StrikeBodies& s, const TableBall& ball, std::size_t index, const BallProperties& properties,
             const Table& table, const detail::MotionGeometry& geometry)
{
  s.members.push_back(index);
  const std::size_t k = s.bodies.balls.size();
  s.bodies.balls.push_back(
      {ball.state.position.head<2>(), ball.state.velocity, ball.state.angular_velocity, 0.0, ball.id});
  const Eigen::Vector3d centre(ball.state.position.x(), ball.state.position.y(), properties.radius);
  for (CushionTouch& touch : detail::cushionTouches(k, centre, geometry, table, properties.radius))
    s.bodies.cushions.push_back(std::move(touch));
}
}  // namespace

StrikeBodies strikeBodies(const std::vector<TableBall>& balls, std::size_t struck, const BallProperties& ball,
                          const Table& table, const BallContactSettings& contact)
{
  StrikeBodies s{detail::collisionSettings(ball, table, contact), {}};
  s.bodies.touching_tolerance = TOUCHING_GAP;
  // Valid balls lie on a valid table, whose geometry lays out.
  const auto laid_out = detail::motionGeometry(table);
  const detail::MotionGeometry geometry = laid_out ? laid_out.value() : detail::MotionGeometry{};
  addBall(s, balls[struck], struck, ball, table, geometry);
  // Breadth first: every ball within the gap of a member joins.
  for (std::size_t k = 0; k < s.members.size(); ++k)
    for (std::size_t m = 0; m < balls.size(); ++m)
      if (std::find(s.members.begin(), s.members.end(), m) == s.members.end() &&
          gapBetween(balls[s.members[k]], balls[m], ball.radius) <= TOUCHING_GAP)
        addBall(s, balls[m], m, ball, table, geometry);
  return s;
}

Expected<CueStrikeResult> strikeOnTable(const CueStrike& strike, const std::vector<TableBall>& balls,
                                        std::size_t struck, const Table& table, const BallContactSettings& contact,
                                        const SolverOptions& options)
{
  const BallProperties ball{strike.ball_mass, strike.ball_radius};
  if (Status status = validateTableBalls(balls, ball, table); !status)
    return status.error();
  if (struck >= balls.size())
    return invalidArgument("cue_ball", "names no ball: there are " + std::to_string(balls.size()));
  const StrikeBodies bodies = strikeBodies(balls, struck, ball, table, contact);
  if (bodies.lone())
    return solve(strike, options);
  ClusterStrike cluster{strike, bodies.bodies, 0};
  auto solved = solve(cluster, options);
  if (!solved)
    return solved.error();
  for (StruckBall& other : solved.value().other_balls)
    other.ball = bodies.members[other.ball];
  for (TouchingBalls& pair : solved.value().touching_balls)
    pair = {std::min(bodies.members[pair.first], bodies.members[pair.second]),
            std::max(bodies.members[pair.first], bodies.members[pair.second])};
  return solved;
}

std::vector<TableBall> ballsAfterStrike(std::vector<TableBall> balls, std::size_t struck, const CueStrikeResult& strike)
{
  balls[struck].state.velocity = strike.velocity;
  balls[struck].state.angular_velocity = strike.angular_velocity;
  for (const StruckBall& other : strike.other_balls)
  {
    balls[other.ball].state.velocity = other.velocity;
    balls[other.ball].state.angular_velocity = other.angular_velocity;
  }
  return balls;
}

void recordStrike(TableTrajectory& trajectory, std::size_t struck, const CueStrikeResult& strike)
{
  if (strike.touching_balls.empty())
    return;
  BallImpactRecord record{0.0, {static_cast<int>(struck)}};
  for (const StruckBall& other : strike.other_balls)
    record.balls.push_back(static_cast<int>(other.ball));
  for (int ball : record.balls)
  {
    // The first pair that holds the ball names the ball it met; every ball of the strike is in one.
    const auto pair = std::find_if(strike.touching_balls.begin(), strike.touching_balls.end(),
                                   [&](const TouchingBalls& p)
                                   { return static_cast<int>(p.first) == ball || static_cast<int>(p.second) == ball; });
    if (pair == strike.touching_balls.end())
      continue;
    std::vector<MotionEvent>& events = trajectory.balls[static_cast<std::size_t>(ball)].events;
    MotionEvent met = events.front();
    met.type = MotionEventType::BallCollision;
    met.ball = static_cast<int>(static_cast<int>(pair->first) == ball ? pair->second : pair->first);
    events.insert(events.begin() + 1, met);
  }
  trajectory.ball_impacts.insert(trajectory.ball_impacts.begin(), record);
}

}  // namespace billiard_shot_planner

#include "table_collisions.hpp"

#include <string>

#include "phase_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Height (m) above the cloth within which a ball's centre counts as on it: the round-off of a landing's position.
constexpr double ON_CLOTH_TOLERANCE = 1e-9;

BallCollision collisionOf(const std::vector<BallState>& touching, const Ball& ball, const Table& table,
                          const BallContactSettings& contact)
{
  BallCollision collision;
  collision.ball_mass = ball.mass;
  collision.ball_radius = ball.radius;
  collision.ball_ball = contact.ball_ball;
  collision.friction_model = contact.friction_model;
  collision.cloth = table.cloth;
  collision.stiffness_ratio = contact.stiffness_ratio;
  for (const BallState& state : touching)
    collision.balls.push_back({state.position.head<2>(), state.velocity, state.angular_velocity});
  return collision;
}
}  // namespace

Expected<std::vector<BallState>> resolveBallImpact(const std::vector<BallState>& touching, const Ball& ball,
                                                   const Table& table, const BallContactSettings& contact,
                                                   const SolverOptions& options)
{
  for (std::size_t i = 0; i < touching.size(); ++i)
    if (touching[i].position.z() > ball.radius + ON_CLOTH_TOLERANCE)
      return Error{ErrorCode::InvalidShot, "balls",
                   "a ball in the air meets another ball: impacts of balls off the cloth are not modelled"};
  auto solved = solve(collisionOf(touching, ball, table, contact), options);
  if (!solved && solved.error().code == ErrorCode::NoApproachingContact)
    return touching;  // a graze within the touching tolerance: nothing presses, nothing changes
  if (!solved)
    return solved.error();
  std::vector<BallState> after = touching;
  for (std::size_t i = 0; i < after.size(); ++i)
  {
    after[i].velocity = solved.value().balls[i].velocity;
    after[i].angular_velocity = solved.value().balls[i].angular_velocity;
  }
  return after;
}
}  // namespace detail
}  // namespace billiard_shot_planner

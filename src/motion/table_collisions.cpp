#include "table_collisions.hpp"

#include <algorithm>

#include "table_events.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
BallCollision collisionOf(const std::vector<BallState>& touching, const BallProperties& ball, const Table& table,
                          const MotionGeometry& geometry, const BallContactSettings& contact)
{
  BallCollision collision = collisionSettings(ball, table, contact);
  for (std::size_t i = 0; i < touching.size(); ++i)
  {
    const BallState& state = touching[i];
    collision.balls.push_back({state.position.head<2>(), state.velocity, state.angular_velocity,
                               std::max(state.position.z() - ball.radius, 0.0)});
    for (CushionTouch& touch : cushionTouches(i, state.position, geometry, table, ball.radius))
      collision.cushions.push_back(std::move(touch));
  }
  return collision;
}
}  // namespace

std::vector<CushionTouch> cushionTouches(std::size_t ball, const Eigen::Vector3d& centre,
                                         const MotionGeometry& geometry, const Table& table, double radius)
{
  std::vector<CushionTouch> touches;
  for (int index : touchedNoses(centre, geometry, table, radius))
  {
    const NosePiece& piece = geometry.noses[static_cast<std::size_t>(index)];
    touches.push_back({ball, cushionNormal(piece, table, centre), geometry.cushionId(piece)});
  }
  return touches;
}

BallCollision collisionSettings(const BallProperties& ball, const Table& table, const BallContactSettings& contact)
{
  BallCollision collision;
  collision.ball_mass = ball.mass;
  collision.ball_radius = ball.radius;
  collision.ball_ball = contact.ball_ball;
  collision.friction_model = contact.friction_model;
  collision.cloth = table.cloth;
  collision.stiffness_ratio = contact.stiffness_ratio;
  collision.cushion = table.cushion;
  collision.cushion_stiffness_ratio = table.cushion_stiffness_ratio;
  return collision;
}

Expected<std::vector<BallState>> resolveBallImpact(const std::vector<BallState>& touching, const BallProperties& ball,
                                                   const Table& table, const MotionGeometry& geometry,
                                                   const BallContactSettings& contact, const SolverOptions& options)
{
  auto solved = solve(collisionOf(touching, ball, table, geometry, contact), options);
  if (!solved && solved.error().code == ErrorKind::NoApproachingContact)
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

#pragma once

#include <vector>

#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "motion_geometry.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// A collision with no balls yet: the balls' mass and radius, the ball–ball contact, the table's cloth and cushion.
BallCollision collisionSettings(const BallProperties& ball, const Table& table, const BallContactSettings& contact);

/// The states right after the multiple impact of balls that touch (each with its cloth contact and the cushions it
/// touches), by the ball-collision scenario: one engine problem for the whole cluster.
Expected<std::vector<BallState>> resolveBallImpact(const std::vector<BallState>& touching, const BallProperties& ball,
                                                   const Table& table, const MotionGeometry& geometry,
                                                   const BallContactSettings& contact, const SolverOptions& options);

/// The cushions a ball with its centre at `centre` touches, as contacts of the ball with index `ball` in an impact.
std::vector<CushionTouch> cushionTouches(std::size_t ball, const Eigen::Vector3d& centre,
                                         const MotionGeometry& geometry, const Table& table, double radius);
}  // namespace detail
}  // namespace billiard_shot_planner

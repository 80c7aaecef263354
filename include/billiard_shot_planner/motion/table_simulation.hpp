#pragma once

#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/ball_trajectory.hpp"
#include "billiard_shot_planner/motion/table.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"

namespace billiard_shot_planner
{
/// The most balls one simulation takes: a full pool rack and the cue ball are 16, snooker's 22.
constexpr std::size_t MAX_TABLE_BALLS = 32;

/// A ball on the table: its id and its state when the simulation starts (at rest, or moving: the cue ball right
/// after the strike). The position's z is ignored on the cloth.
struct TableBall
{
  std::string id;
  BallState state;
};

/// The balls that took part in one impact between balls, by index.
struct BallImpactRecord
{
  double time = 0.0;
  std::vector<int> balls;
};

/// Every ball's path until all rest or leave the table, and the impacts between balls.
struct TableTrajectory
{
  std::vector<std::string> ids;       ///< in the order of the input
  std::vector<BallTrajectory> balls;  ///< one per id
  std::vector<BallImpactRecord> ball_impacts;
  /// The time the last ball came to rest or left the table.
  double duration() const;
};

/// The id of the first ball that ball `ball` (by index) touches, or "" when it touches none.
std::string firstContact(const TableTrajectory& trajectory, std::size_t ball = 0);

/// How balls meet (scenarios/ball_collision.hpp): the ball–ball contact, and the cloth's stiffness relative to it.
/// The cloth's own law is the table's.
struct BallContactSettings
{
  SurfaceContact ball_ball = BallCollision{}.ball_ball;  ///< e, μ (of the constant model), η²
  BallBallFriction friction_model = BallCollision{}.friction_model;
  double stiffness_ratio = BallCollision{}.stiffness_ratio;  ///< k_cloth / k_ball_ball
};

/// Checks the balls as simulateTable does: their count, ids, starts and overlaps (errors named as its).
Status validateTableBalls(const std::vector<TableBall>& balls, const BallProperties& ball, const Table& table);

/// Simulates every ball on the table from its start until every ball rests or has left the table (or a ball meets
/// the time or event limit). One event queue for all balls: each ball moves in its closed-form phases; the next
/// event is the earliest of any ball's own event (phase change, landing, cushion, pocket) and of any pair's contact
/// (the exact earliest root of |p_i(t) − p_j(t)| = 2R, detail::earliestBallContact). Balls that meet, with every
/// ball touching them, are one multiple impact of the engine (scenarios/ball_collision.hpp). Only the balls of an
/// event change their phase. One ball is predictTrajectory's case.
/// Errors name the ball ("balls[2].position"): no ball, more than MAX_TABLE_BALLS, an empty or repeated id,
/// overlapping balls, a ball off the cloth, in a pocket or overlapping a cushion, non-finite values.
Expected<TableTrajectory> simulateTable(const std::vector<TableBall>& balls, const BallProperties& ball,
                                        const Table& table, const MotionParameters& parameters = {},
                                        const BallContactSettings& contact = {});

}  // namespace billiard_shot_planner

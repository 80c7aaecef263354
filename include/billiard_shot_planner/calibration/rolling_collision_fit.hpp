#pragma once

#include <string>
#include <utility>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"

namespace billiard_shot_planner
{
/// A rolling cue ball meeting an object ball at rest: its speed at the meeting, the cut angle (between its direction
/// and the line of centres at contact, rad), and both balls' speeds once they roll again, as tracked (m/s).
struct RollingCollision
{
  double speed_in = 0.0;
  double cut = 0.0;
  double cue_speed_out = 0.0;
  double object_speed_out = 0.0;
};

/// The table the collisions were measured on: the balls, the cloth, the motion on it and the ball–ball contact
/// (what fitRollingCollisions fits).
struct RollingCollisionTable
{
  BallProperties ball;
  SurfaceContact cloth{0.51625, 0.152479, 10.0};
  MotionParameters motion;
  BallContactSettings contact;
};

/// The parameters a collision fit may fit: "ball_ball.restitution", "ball_ball.friction" (of the constant friction
/// model), "ball_ball.eta2", "ball_ball.cloth_stiffness_ratio" and the ball–ball law's own
/// ("ball_ball.law.yield_speed").
std::vector<std::string> rollingCollisionParameters(const RollingCollisionTable& table);

/// The table with the named values applied. Errors: a name rollingCollisionParameters does not list.
Status applyRollingCollisionValues(const std::vector<std::string>& names, const std::vector<double>& values,
                                   RollingCollisionTable& table);

/// The cue ball's and the object ball's speeds once each rolls again after the meeting (simulateTable on an
/// unbounded cloth: the meeting is one multiple impact of the two balls and their cloth contacts, the rest their
/// motion). Errors: speed_in ≤ 0, |cut| ≥ 90°, the table's constants out of range, and the simulation's.
Expected<std::pair<double, double>> predictRollingCollision(const RollingCollisionTable& table, double speed_in,
                                                            double cut);

/// Fits the named parameters to measured collisions by fitLeastSquares on (v − v_obs)/σ of both balls, σ =
/// `speed_sigma` (m/s, > 0). Errors: InvalidArgument naming a parameter (unknown, or a start the table rejects),
/// `speed_sigma`, or a collision ("collisions[1].cut"), and fitLeastSquares' own.
Expected<FitResult> fitRollingCollisions(const RollingCollisionTable& table,
                                         const std::vector<FitParameter>& parameters,
                                         const std::vector<RollingCollision>& collisions, double speed_sigma,
                                         const FitOptions& options = {});

}  // namespace billiard_shot_planner

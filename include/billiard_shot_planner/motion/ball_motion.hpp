#pragma once

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/motion/ball_trajectory.hpp"
#include "billiard_shot_planner/motion/table.hpp"

namespace billiard_shot_planner
{
/// How the deceleration of a rolling ball is written (docs/impact_model.md, Motion on the table).
enum class RollingModel
{
  Paper,     ///< Jia et al.: a = (5/7) μ_r g (the paper's μ_r = 0.0209727)
  Pooltool,  ///< Leckie–Greenspan / pooltool: a = μ_r g; μ_r(paper) = (7/5) μ_r(pooltool)
};

/// The longest trajectory the package predicts, s: a ball stops within a minute on any cloth; the bound keeps the
/// work and the output of a call bounded whatever the friction coefficients.
constexpr double MAX_TRAJECTORY_TIME = 600.0;

/// Friction and stopping rules of the ball's motion on the table (docs/impact_model.md, Motion on the table).
/// Defaults: the paper's measured values.
struct MotionParameters
{
  double gravity = 9.81;                ///< m/s²
  double sliding_friction = 0.152479;   ///< μ_s, ball on cloth while slipping (paper §9.2)
  double rolling_friction = 0.0209727;  ///< μ_r, in the convention of rolling_model (paper §9.2)
  RollingModel rolling_model = RollingModel::Paper;
  /// μ_sp: spin about z decays at 5 μ_sp g / (2R). Default (4/9)·0.0286 = 0.0127, pooltool's 10·(2/5)R/9.
  double spinning_friction = 0.0127;
  bool planar = false;             ///< drop v_z after the shot (the paper's choice) instead of hopping
  double min_bounce_speed = 0.02;  ///< m/s: a landing that rebounds slower than this ends the hopping
  double max_time = 60.0;          ///< s, [0.001, MAX_TRAJECTORY_TIME]: the trajectory is cut here (time_limit)
  int max_events = 1000;
  SolverOptions impact;  ///< for the landings and cushion impacts
};

/// A ball's mass and radius (the message Ball of the ROS interface is a ball on the table: id and position).
struct BallProperties
{
  double mass = 0.17;      ///< kg
  double radius = 0.0286;  ///< m
};

/// Predicts the ball's path on the table from its state right after the shot, event by event with closed-form
/// phases and exact event times; landings and cushion hits are solved by the multiple-impact engine. The start
/// position's z is ignored when the ball is on the cloth (it is set to the radius).
/// Errors: InvalidArgument naming the field (ball off the table or overlapping a cushion, bad friction, …).
Expected<BallTrajectory> predictTrajectory(const BallState& start, const BallProperties& ball, const Table& table,
                                           const MotionParameters& parameters = {});

Status validate(const MotionParameters& parameters);

}  // namespace billiard_shot_planner

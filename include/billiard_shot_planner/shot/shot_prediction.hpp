#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace billiard_shot_planner
{
/// Everything physical about a shot except where the cue is and how fast it moves: the cue, the ball, the table
/// and the motion model. Defaults (config/default.yaml): the paper's set-up (§9.2) with the corrected ball
/// (0.17 kg, 0.0286 m) and a hand-held cue: its tip free to move across the axis with a typical end mass, and
/// Mindlin's tangential stiffness (η² = 1.2) instead of the paper's fitted 7 (see docs/cue_strike.md).
struct ShotConfiguration
{
  double cue_mass = 0.5018;                        ///< kg, cue (and whatever moves with it) along its axis
  double cue_end_mass = TYPICAL_CUE_END_MASS;      ///< kg, the tip across the axis; CUE_HELD_ON_AXIS: the paper's
  double ball_mass = 0.17;                         ///< kg
  double ball_radius = 0.0286;                     ///< m
  SurfaceContact cue_contact{0.656532, 0.7, 1.2};  ///< cue tip on ball: e, μ, η² (Mindlin's η² for a soft tip)
  double stiffness_ratio = 0.8;                    ///< k_cloth / k_cue
  Table table;                                     ///< includes the cloth contact (e, μ, η²) of the strike
  BallContactSettings ball_contact;                ///< how balls meet (e, μ or Alciatore's μ(v), η², k_cloth/k)
  MotionParameters motion;
  SolverOptions solver;
};

/// Checks every field; the error names it by its path in the configuration ("cue_contact.friction").
Status validate(const ShotConfiguration& configuration);

/// A numeric parameter of ShotConfiguration by its path ("table.cloth.friction"); the ROS node's parameter and
/// override names are these paths with '/' for '.'.
struct NamedParameter
{
  std::string name;
  double* value;
};

/// The configuration's cue, ball, tip and cloth as a strike's physics (cue direction, speed and hit point left to
/// the caller).
CueStrike strikePhysics(const ShotConfiguration& configuration);

/// Every numeric parameter of the configuration, by name: cue_mass, cue_end_mass, ball_mass, ball_radius,
/// cue_contact.{restitution,friction,eta2}, stiffness_ratio, table.{length,width,cushion_height,
/// cushion_stiffness_ratio}, table.cloth.…, table.cushion.…, motion.{gravity,sliding_friction,rolling_friction,
/// spinning_friction,min_bounce_speed,max_time}, solver.{relative_tolerance,absolute_tolerance,max_seconds},
/// ball_ball.…, and each contact's law's own parameters under `<contact>.law.` ("table.cushion.law.yield_speed")
/// for the law each contact has.
std::vector<NamedParameter> numericParameters(ShotConfiguration& configuration);

/// Sets one numeric parameter by name. Errors: unknown name, or a value the configuration rejects (then the
/// configuration is left unchanged).
Status applyOverride(ShotConfiguration& configuration, const std::string& name, double value);

/// Where the cue is at the moment of contact and how fast it moves, and where the ball rests (table frame).
struct CuePlacement
{
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();         ///< centre of the cue tip, on the cue axis
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< the cue's direction of motion (normalised)
  double speed = 1.0;                                    ///< m/s
  Eigen::Vector2d ball = Eigen::Vector2d::Zero();        ///< the ball's centre in the table plane
};

/// The id of the cue ball among the balls of a shot's table.
inline const char* const CUE_BALL_ID = "cue";

struct ShotOutcome
{
  CueStrikeResult strike;
  BallTrajectory trajectory;  ///< the cue ball's
  Eigen::Vector3d hit_point;  ///< table frame
  /// Every ball's path: the cue ball first (id CUE_BALL_ID), then the other balls in the order given. On an empty
  /// table, the cue ball alone.
  TableTrajectory table;
};

/// The strike alone, predictShot's first part: the hit point where the cue axis meets the ball and the ball's
/// velocity and spin right after the cue leaves it. A cue ball that touches other balls of `others` or a cushion
/// (within TOUCHING_GAP) is struck as one multiple impact with all it touches (strikeOnTable): `other_balls` then
/// numbers `others` from 1 (0 is the cue ball). Errors as predictShot's.
Expected<CueStrikeResult> strikeBall(const CuePlacement& cue, const ShotConfiguration& configuration,
                                     const std::vector<TableBall>& others = {});

/// The whole prediction: the hit point where the cue axis meets the ball, the strike by the multiple-impact
/// engine, and the path of every ball on the table (`others`: the balls besides the cue ball, at rest or moving;
/// none may be called CUE_BALL_ID). Pure function, thread-safe. Errors name the input by its place in the call: the
/// cue's fields under "cue" ("cue.tip", "cue.direction", "cue.speed", "cue.ball" for the cue ball; "cue" for a cue
/// that misses or points away from its ball), the other balls by their index in `others` ("others[2].position"), the
/// configuration's fields by their paths ("table.cloth.friction"). Each front end maps them to its own names.
Expected<ShotOutcome> predictShot(const CuePlacement& cue, const ShotConfiguration& configuration,
                                  const std::vector<TableBall>& others = {});

/// predictShot's second part: the balls' paths after a strike already solved by strikeBall(cue, configuration,
/// others) (a fit of the motion's constants, which the strike does not depend on, solves each strike once). The balls
/// the strike moved start with its velocities, and its meetings are recorded at t = 0 (recordStrike).
Expected<ShotOutcome> predictShotAfter(const CuePlacement& cue, CueStrikeResult struck,
                                       const ShotConfiguration& configuration,
                                       const std::vector<TableBall>& others = {});

}  // namespace billiard_shot_planner

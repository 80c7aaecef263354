#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// A cue tip's effective mass across the cue's axis that holds it on the axis: the paper's shooter, whose cue ran
/// in ball bearings (§9.2, eq. 48).
constexpr double CUE_HELD_ON_AXIS = std::numeric_limits<double>::infinity();

/// A hand-held (or robot-held) cue's end mass: the part of the shaft behind the tip that moves sideways with it
/// during the strike. Pooltool's default, the ball's mass over 30 (0.17 / 30 kg); Shepard and Alciatore measure
/// 4–10 g for common shafts, less for "low-squirt" ones.
constexpr double TYPICAL_CUE_END_MASS = 0.0057;

/// The integrated billiard shot (paper §8): the cue strikes the ball at rest on the table. Table frame, z up, SI
/// units.
///
/// The cue tip moves along the cue's axis ĉ with the cue's mass and across it with its end mass, as degrees of
/// freedom of the same impact problem (an infinite end mass holds it on its axis, eq. 48). Contact p (cue–ball) has
/// the ball's outward normal n̂ at the hit point; contact q (ball–table) has normal ẑ and touches at rest: it takes
/// part only if the strike presses the ball into the cloth (a draw shot lifts it, a level hit through the centre
/// only slides it).
struct CueStrike
{
  double cue_mass = 0.5;                       ///< kg, > 0: what moves with the tip along the cue's axis
  double cue_end_mass = TYPICAL_CUE_END_MASS;  ///< kg, > 0 or CUE_HELD_ON_AXIS: the tip's mass across the axis
  Eigen::Vector3d cue_direction = -Eigen::Vector3d::UnitZ();  ///< ĉ, the cue's direction of motion (normalised)
  double cue_speed = 1.0;                                     ///< m/s, > 0
  double ball_mass = 0.17;
  double ball_radius = 0.0286;
  Eigen::Vector3d hit_normal = Eigen::Vector3d::UnitZ();  ///< n̂ at the hit point (normalised); see hitNormal()
  SurfaceContact cue_contact;                             ///< e, μ, η² of the cue tip on the ball
  SurfaceContact table_contact;                           ///< e, μ, η² of the ball on the cloth
  double stiffness_ratio = 1.0;                           ///< k_table / k_cue
};

/// The hit normal where the cue axis (through `axis_point`, along `direction`) first meets the ball: ray–sphere
/// intersection. Errors (InvalidShot) when the axis misses the ball, the tip is inside the ball, or the ball is behind
/// the tip.
Expected<Eigen::Vector3d> hitNormal(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& direction,
                                    const Eigen::Vector3d& ball_centre, double ball_radius);

/// One contact of a strike's impact, for reports: its name and its total impulse on its body A, in the table frame.
/// A lone strike's are "cue-ball" (A the tip: the impulse on the cue) and "ball-table" (A the ball); a strike of a ball
/// that touches others names the bodies ("tip-cue", "cue-one", "one-cloth", "cue-cushion1"; A the tip, then the
/// second ball named, then the ball).
struct StrikeContact
{
  std::string name;
  Eigen::Vector3d impulse;  ///< N·s
};

/// A ball the strike moved besides the struck one: a ball it touches, directly or through others.
struct StruckBall
{
  std::size_t ball = 0;  ///< index, as the caller numbers the balls
  Eigen::Vector3d velocity;
  Eigen::Vector3d angular_velocity;
};

/// Two balls that touched during the strike (indices as the caller numbers the balls, `first` < `second`).
struct TouchingBalls
{
  std::size_t first = 0;
  std::size_t second = 0;
};

struct CueStrikeResult
{
  Eigen::Vector3d velocity;          ///< ball, m/s
  Eigen::Vector3d angular_velocity;  ///< ball, rad/s
  double cue_velocity = 0.0;         ///< cue after the shot, along ĉ
  Eigen::Vector3d tip_velocity;      ///< the cue tip after the shot (along ĉ and across it), m/s
  Eigen::Vector3d impulse_cue;       ///< impulse on the cue at the hit point (N·s)
  Eigen::Vector3d impulse_table;     ///< impulse on the ball at the table contact (N·s)
  Eigen::Vector3d hit_normal;        ///< n̂ used (normalised)
  Eigen::Vector3d cue_direction;     ///< ĉ used (normalised)
  /// A lone strike's: S1 (both), S2 (ball–table only), S3 (cue–ball only), S4 (end). A strike of a ball that
  /// touches others: each state's active contacts by name, joined by '+' ("tip-cue+cue-one+cue-cloth"), "end" last.
  std::vector<std::string> states;
  /// The tip slipped on the ball from the first instant (|v_t| > μη²|v_n|): a miscue warning.
  bool miscue = false;
  /// The ball leaves the cloth upwards (a jump, a massé or a scoop): its motion starts airborne.
  bool leaves_cloth = false;
  /// Every contact of the impact, in the engine's order: contact 0 is the cue's; in a lone strike contact 1 is the
  /// ball–table contact.
  std::vector<StrikeContact> contacts;
  std::vector<StruckBall> other_balls;  ///< empty for a lone strike
  /// Every pair of balls in contact in the strike (the struck ball's index as the caller gives it); empty for a
  /// lone strike.
  std::vector<TouchingBalls> touching_balls;
  ImpactResult impact;  ///< the engine's full result, contacts as `contacts`
};

/// The engine's configuration for this strike: generalised velocity (v_c, [v_⊥1, v_⊥2,] v, ω) — the tip along ĉ,
/// across it when the end mass is finite, the ball's linear and angular velocity — contact 0 cue–ball, contact 1
/// ball–table. Errors as solve().
Expected<ImpactProblem> makeImpactProblem(const CueStrike& strike);

/// Solves the strike with the multiple-impact engine: any hit the tip can make, above, on or below the ball's
/// equator, level or steep. Errors: InvalidArgument (a field, named: cue_end_mass must be > 0 or infinite),
/// InvalidShot (n̂·ĉ ≥ 0: the cue does not approach the ball at the hit point).
Expected<CueStrikeResult> solve(const CueStrike& strike, const SolverOptions& options = {});

}  // namespace billiard_shot_planner
